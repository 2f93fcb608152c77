// The mixed GEBT statics with four rotation unknowns (the quaternion). Same
// model, frames, loads and equations as MixedStatics<P> (mixed_statics.hpp), with Eq. 48 in four
// components (mixed_quaternion_element.hpp) and the numbering of mixed_quaternion_layout.hpp:
// 13 unknowns and 14 rows per element, 7 unknowns and 6 rows per free node, 6 (+ ρ) per support.
// No norm equation: the discrete kinematics conserve |q̂| from node to node (a Cayley transform),
// R = C(q)/|q|² makes the norm irrelevant to every other equation, and norm_drift() reports how
// far the solution's quaternions are from unit length. Theory note: docs/mixed-formulation.md.
//
// The update is additive (retract(dx) = x + dx), so KINSOL can drive it as well.
#pragma once

#include <array>
#include <vector>

#include "core/model.hpp"
#include "core/nonlinear_system.hpp"
#include "formulations/mixed/mixed_quaternion_element.hpp"
#include "formulations/mixed/mixed_quaternion_layout.hpp"
#include "parameterizations/concept.hpp"

namespace rotbeam::form {

// max | |q| − 1 | over the free and supported nodes' q̂ (conserved by Eq. 48: round-off) and over
// the elements' q_i (the average of its end nodes': |q_i| = cos(δ/4), O(ΔL²), by construction).
struct QuaternionNormDrift {
    double nodes = 0.0;
    double elements = 0.0;
};

template <param::RotationParameterization P>
requires(P::kSize == 4) class MixedQuaternionStatics : public StaticProblem {
  public:
    static constexpr int K = P::kSize;
    using Params = param::Params<K>;

    explicit MixedQuaternionStatics(const Model& model);

    int size() const override { return layout_.size(); }
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
    double max_rotation_angle() const override;
    std::vector<SectionResultants> section_resultants() const override;
    std::vector<RotationStation> rotation_stations() const override;

    const MixedQuaternionLayout& layout() const { return layout_; }
    MixedHomogeneousState<P::kSize> element_state(int e) const;
    QuaternionNormDrift norm_drift() const;

  private:
    // Given û, q̂ of a supported node at the current load factor (times ρ where it has one).
    void supported_motion(int node, Vec3& u_hat, Params& q_hat) const;
    Params given_rotation(int node) const;
    void node_motion(int node, Vec3& u_hat, Params& q_hat) const;
    void add_point_loads(VecX& residual, SparseMatrix* jacobian) const;
    void assemble_element(int e, VecX& residual, SparseMatrix* jacobian);
    void add_node_terms(int e, VecX& residual, SparseMatrix* jacobian) const;
    // J(r0:, c0:) += b for a block inside the fixed pattern (binary search, no allocation).
    template <class Derived>
    static void add_block(SparseMatrix& J, int r0, int c0, const Eigen::MatrixBase<Derived>& b) {
        for (Eigen::Index j = 0; j < b.cols(); ++j) {
            for (Eigen::Index i = 0; i < b.rows(); ++i) {
                J.coeffRef(r0 + static_cast<int>(i), c0 + static_cast<int>(j)) += b(i, j);
            }
        }
    }

    Model model_;  // a copy: the caller's model may go out of scope
    MixedQuaternionLayout layout_;
    VecX x_;
    std::array<VecX, kCheckpointSlots> saved_;
    VecX residual_scale_;
    VecX increment_scale_;
    SparseMatrix pattern_;
    double lambda_ = 0.0;
    AssemblyCounters counters_;
    MixedHomogeneousResult<K> element_result_;
};

}  // namespace rotbeam::form
