// The mixed GEBT formulation for statics (seed 002 §III, Eqs. 16–56; Yu & Blair, Wang & Yu,
// GXBeam), one class for every parameterization: three parameters (seed 002's Eq. 48 with H_m⁻¹)
// and the quaternion (Eq. 48 in four components with the right inverse H_m⁺, no norm equation:
// the discrete kinematics conserve |q̂| from node to node, R = C(q)/|q|² makes the norm irrelevant
// to every other equation, and norm_drift() reports how far the solution's quaternions are from
// unit length). Unknowns, equations and numbering: mixed_layout.hpp (MixedNumbering); element
// equations: mixed_element.hpp; the parameterization's redundancy:
// parameterizations/parameter_constraint.hpp; theory note: docs/mixed-formulation.md.
//
// The update is additive (retract(dx) = x + dx): the rotation unknowns are the parameters of the
// rotation relative to the reference configuration, used in one chart throughout, so KINSOL can
// drive it as well. The Jacobian's sparsity pattern is fixed at construction; evaluate()
// allocates nothing after its first call.
#pragma once

#include <array>
#include <vector>

#include "core/model.hpp"
#include "core/static_stability_kinetic.hpp"
#include "core/static_state.hpp"
#include "formulations/mixed/mixed_element.hpp"
#include "formulations/mixed/mixed_layout.hpp"
#include "formulations/mixed/mixed_load_fields.hpp"
#include "parameterizations/concept.hpp"
#include "parameterizations/parameter_constraint.hpp"

namespace rotbeam::form {

// Section resultants of one element in inertial components (A F, A M) at its mid-length.
struct MixedElementResultants {
    int member = -1;
    double s_mid = 0.0;
    Vec3 force = Vec3::Zero();
    Vec3 moment = Vec3::Zero();
};

// max | |q| − 1 | over the free and supported nodes' q̂ (conserved by Eq. 48: round-off) and over
// the elements' q_i (the average of its end nodes': |q_i| = cos(δ/4), O(ΔL²), by construction).
struct QuaternionNormDrift {
    double nodes = 0.0;
    double elements = 0.0;
};

// J(r0:, c0:) += b for a block inside a fixed pattern (binary search, no allocation).
template <class Derived>
void add_mixed_block(SparseMatrix& J, int r0, int c0, const Eigen::MatrixBase<Derived>& b) {
    for (Eigen::Index j = 0; j < b.cols(); ++j) {
        for (Eigen::Index i = 0; i < b.rows(); ++i) {
            J.coeffRef(r0 + static_cast<int>(i), c0 + static_cast<int>(j)) += b(i, j);
        }
    }
}

template <param::RotationParameterization P>
class MixedStatics : public StaticProblem, public KineticSystem {
  public:
    static constexpr int K = P::kSize;
    static constexpr int kConstraintRows = param::ParameterConstraint<P>::kRows;
    using Params = param::Params<K>;

    explicit MixedStatics(const Model& model);

    int size() const override { return numbering_.size(); }
    void evaluate(VecX& residual, SparseMatrix* jacobian) override;
    void retract(const Eigen::Ref<const VecX>& dx) override { x_ += dx; }
    void save_state(int slot) override { saved_[static_cast<std::size_t>(slot)] = x_; }
    void restore_state(int slot) override { x_ = saved_[static_cast<std::size_t>(slot)]; }
    const VecX& residual_scale() const override { return residual_scale_; }
    const VecX& increment_scale() const override { return increment_scale_; }
    bool additive() const override { return true; }
    VecX state_vector() const override { return x_; }
    void set_state_vector(const Eigen::Ref<const VecX>& x) override { x_ = x; }
    std::string describe_state() const override;

    void set_load_factor(double lambda) override { lambda_ = lambda; }
    PointState point_state(int point_index) const override;
    AssemblyCounters counters() const override { return counters_; }
    // Largest rotation angle [rad] held in the state's parameters (messages and tests).
    double max_rotation_angle() const;
    std::vector<SectionResultants> section_resultants() const override;
    std::vector<RotationStation> rotation_stations() const override;
    std::vector<NodeFrame> node_frames() const override;
    // The linearized free motion about the current state (mixed_statics_kinetic.hpp).
    KineticSpectrum kinetic_spectrum(int count) override;

    const MixedLayout& layout() const { return layout_; }
    const MixedNumbering& numbering() const { return numbering_; }
    MixedElementState<K> element_state(int e) const;
    std::vector<MixedElementResultants> resultants() const;
    // The constraint spelled out (not kConstraintRows): clang 14 does not find a class member
    // in the requires-clause of the out-of-line definition.
    QuaternionNormDrift norm_drift() const requires(param::ParameterConstraint<P>::kRows > 0);

  private:
    // Given û, ĉ of a supported node at the current load factor (times ρ where it has one).
    Params given_rotation(int node) const;
    void supported_motion(int node, Vec3& u_hat, Params& c_hat) const;
    void node_motion(int node, Vec3& u_hat, Params& c_hat) const;
    void add_point_loads(VecX& residual, SparseMatrix* jacobian) const;
    void assemble_element(int e, VecX& residual, SparseMatrix* jacobian);
    void add_node_terms(int e, VecX& residual, SparseMatrix* jacobian) const;
    // solver.assemble_all_terms (mixed_statics_rest_terms.hpp): element e's inertial terms
    // (seed 002 Eqs. 45–46, 49–50) at rest, P = H = 0, into its end nodes' rows.
    void prepare_rest_terms();
    void assemble_rest_terms(int e, int a, int b, VecX& residual, SparseMatrix* jacobian);

    Model model_;  // a copy: the caller's model may go out of scope
    MixedLayout layout_;
    MixedNumbering numbering_;
    VecX x_;
    std::array<VecX, kCheckpointSlots> saved_;
    VecX residual_scale_;
    VecX increment_scale_;
    SparseMatrix pattern_;
    double lambda_ = 0.0;
    AssemblyCounters counters_;
    MixedElementResult<K> element_result_;
    std::vector<Mat6> rest_mass_inverse_;  // per element; empty: no rest terms
    // The steady rotating frame (core/model.hpp): each element's section mass (material axes, by
    // the mass rule, as the mixed dynamics take it); empty without a rotating frame.
    std::vector<Mat6> spin_mass_;
    void add_rotating_frame(int e, int a, int b, VecX& residual, SparseMatrix* jacobian);
};

}  // namespace rotbeam::form
