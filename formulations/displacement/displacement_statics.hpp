// Static analysis with the displacement-based GEBT formulation (seed 000; Kynema, BeamDyn):
// Legendre spectral finite elements (mesh.hpp), nodal rotations stored in the parameterization P
// and updated by composing the spatial increment, p ← exp(δψ) ⊗ p (the retraction), `relative`
// (default, objective) or `direct` rotation interpolation (interpolate_rotation.hpp), and the
// exact consistent Jacobian of the residual through that retraction. With `relative` and
// discretization.rescale the nodal parameters are kept in their short chart (angle ≤ π) after
// every retraction: they enter only through R_j, so no element chart is split.
//
// Unknowns: per unconstrained node [δu; δψ] (6). Residual rows per node: [force; moment],
//   r_a = Σ_q w_q (N_a′ F^E1 + N_a F^E2 − N_a f_ext) − (point loads at the node),
// (seed 000 Eq. 9 in weak form, statics: no F^I, no damping). Loads: dead or follower point and
// distributed loads, gravity (with the centre-of-mass offset moment); all multiplied by the load
// factor λ. Follower loads f = R f0 turn with the (interpolated) relative rotation and add the
// load stiffness (f0 × ...) — assembled only when such loads exist (AssemblyCounters).
//
// Evaluation allocates nothing after the first call: every buffer is sized in the constructor and
// the Jacobian's sparsity pattern is fixed (the value positions of every element block are
// precomputed).
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "core/model.hpp"
#include "core/potential_hessian.hpp"
#include "core/static_stability_kinetic.hpp"
#include "core/static_state.hpp"
#include "formulations/displacement/calculate_rotating_frame_forces.hpp"
#include "formulations/displacement/interpolate_rotation.hpp"
#include "formulations/displacement/mesh.hpp"
#include "formulations/displacement/mip_stresses.hpp"
#include "parameterizations/concept.hpp"
#include "parameterizations/registry.hpp"

namespace rotbeam::form {

template <param::RotationParameterization P>
class DisplacementStatics : public StaticProblem, public PotentialSystem, public KineticSystem {
  public:
    using Params = param::Params<P::kSize>;

    explicit DisplacementStatics(const Model& model);

    int size() const override { return mesh_.unknowns; }
    void evaluate(VecX& residual, SparseMatrix* jacobian) override;
    void retract(const Eigen::Ref<const VecX>& dx) override;
    void save_state(int slot) override;
    void restore_state(int slot) override;
    const VecX& residual_scale() const override { return residual_scale_; }
    const VecX& increment_scale() const override { return increment_scale_; }
    std::string describe_state() const override;
    // The warm start (displacement_statics_warm_start.hpp).
    std::optional<NodalField> nodal_field() const override;
    bool start_from(const NodalField& field) override;

    void set_load_factor(double lambda) override;
    // The potential energy, its gradient (the Galerkin one, not the residual) and Hessian
    // (displacement_statics_energy.hpp).
    std::optional<double> potential_energy() override;
    PotentialHessian potential_hessian() override;
    bool potential_gradient(VecX& gradient) override;
    void move_along_potential_chart(const Eigen::Ref<const VecX>& dx) override;
    // The linearized free motion's lowest eigenvalues (displacement_statics_kinetic.hpp).
    KineticSpectrum kinetic_spectrum(int count) override;
    // Dynamics: every load multiplied by its own time function at t (gravity by 1), λ = 1; the
    // residual scale stays the one of λ = 1. Prescribed motion is not time-dependent here (the
    // dynamic problem rejects non-zero prescribed motion).
    void set_time(double t);
    // Dynamics: the state of a free node set directly (the time integrator owns the update).
    void set_node_state(int node, const Vec3& u, const Params& p) {
        u_[node] = u;
        p_[node] = p;
        mip_.drop();
    }
    bool relative_interpolation() const { return relative_; }
    // solver.assemble_all_terms (displacement_statics_absent_terms.hpp): `motion` assembles the
    // inertial and damping kernels at rest in a static analysis, `load_stiffness` the load
    // stiffness of dead loads, all with zero coefficients. The constructor sets both from the
    // model; the dynamics switch `motion` off (they assemble the real inertia and damping).
    void assemble_absent_terms(bool motion, bool load_stiffness) {
        absent_motion_ = motion;
        absent_load_stiffness_ = load_stiffness;
    }
    bool rescales_nodes() const { return rescale_nodes_; }
    // Dynamics in a rotating frame (displacement_dynamics.hpp): the dynamics assemble the whole
    // inertial force of the moving frame themselves, so they switch the steady one off here
    // (on from the model otherwise), and turn gravity with the frame (the gravity vector in
    // rotating components at the current time).
    void set_rotating_frame_forces(bool on) { spin_forces_ = on; }
    void set_gravity(const Vec3& g) { model_.gravity = g; }
    // Adds a 6×6 node block (rows of element node a, columns of node b) into J's fixed pattern.
    void add_block(SparseMatrix& J, int element, int a, int b, const Mat6& block) const;
    PointState point_state(int point_index) const override;
    AssemblyCounters counters() const override { return counters_; }
    // Largest rotation angle [rad] held in the state's parameters (messages and tests).
    double max_rotation_angle() const;
    bool additive() const override { return additive_; }
    // With the additive update the unknowns are [u; p] per free node (what KINSOL iterates on).
    VecX state_vector() const override {
        VecX x = VecX::Zero(additive_ ? mesh_.unknowns : 0);
        if constexpr (P::kSize == 3) {
            for (size_t i = 0; additive_ && i < mesh_.nodes.size(); ++i) {
                const int d = mesh_.nodes[i].dof;
                if (d < 0) continue;
                x.segment<3>(d) = u_[i];
                x.segment<3>(d + 3) = p_[i];
            }
        }
        return x;
    }
    void set_state_vector(const Eigen::Ref<const VecX>& x) override {
        if constexpr (P::kSize == 3) {
            for (size_t i = 0; additive_ && i < mesh_.nodes.size(); ++i) {
                const int d = mesh_.nodes[i].dof;
                if (d < 0) continue;
                u_[i] = x.segment<3>(d);
                p_[i] = x.segment<3>(d + 3);
            }
        } else {
            (void)x;
        }
    }
    std::vector<CenterlinePoint> centerline() const override {
        std::vector<CenterlinePoint> out;
        for (const MeshElement& e : mesh_.elements) {
            for (size_t j = out.empty() || out.back().member != e.member ? 0 : 1;
                 j < e.nodes.size(); ++j) {
                out.push_back({e.member, mesh_.nodes[e.nodes[j]].x0 + u_[e.nodes[j]]});
            }
        }
        return out;
    }

    // Every node of every element in arc-length order (the shared end node once).
    std::vector<RotationStation> rotation_stations() const override {
        std::vector<RotationStation> out;
        for (const MeshElement& e : mesh_.elements) {
            for (size_t j = out.empty() || out.back().member != e.member ? 0 : 1;
                 j < e.nodes.size(); ++j) {
                out.push_back({e.member, true, P::matrix(p_[e.nodes[j]])});
            }
        }
        return out;
    }

    // Every node of every element in arc-length order (the shared end node once).
    std::vector<NodeFrame> node_frames() const override {
        std::vector<NodeFrame> out;
        for (const MeshElement& e : mesh_.elements) {
            for (size_t j = out.empty() || out.back().member != e.member ? 0 : 1;
                 j < e.nodes.size(); ++j) {
                const int n = e.nodes[j];
                out.push_back({e.member, e.node_s[j], mesh_.nodes[n].x0, u_[n], P::matrix(p_[n])});
            }
        }
        return out;
    }

    const Mesh& mesh() const { return mesh_; }
    // Nodal state (relative to the reference configuration), for tests and output.
    const Vec3& node_displacement(int node) const { return u_[node]; }
    const Params& node_rotation(int node) const { return p_[node]; }
    double force_scale() const { return force_scale_; }
    double length_scale() const { return length_scale_; }

    // Why the loads have no potential, a rotating frame's centrifugal load aside (empty: they
    // have one: gravity, dead forces).
    std::string non_conservative_load_reason() const;

  private:
    struct NodeLoad {
        int node = -1;
        Vec3 force = Vec3::Zero();
        Vec3 moment = Vec3::Zero();
        bool follower = false;
        double factor = 1.0;  // time function value (dynamics), 1 in statics
        int source = -1;      // index into Model::point_loads
    };

    void build_pattern();
    void compute_scales(const Model& model);
    void update_residual_scale();
    void gather_element(const MeshElement& e, bool jacobian);
    void assemble_element(int element, VecX& r, SparseMatrix* J);
    void record_mip_maps(int g, const Mat3& Q, const Vec6& FE1, const Vec6& F_geometric, int nn);
    // External distributed loads and gravity at one quadrature point: the force/moment density
    // and its derivative with respect to the point's δψ.
    void distributed_load(const MeshElement& e, const QuadraturePoint& qp, const Mat3& R,
                          bool jacobian, Vec6& f, Eigen::Matrix<double, 6, 3>& df_dpsi);
    void assemble_point_loads(VecX& r, SparseMatrix* J);
    std::string no_potential_reason() const;
    bool element_energy(int element, double& energy, VecX& gradient);
    // The steady rotating frame's inertial force at one quadrature point (zero without one).
    RotatingFrameForces rotating_frame_forces(const MeshElement& e, const QuadraturePoint& qp,
                                              const double* N, const Mat3& R);
    // solver.assemble_all_terms: the inertial and damping terms at rest at quadrature point q of
    // element k (J: after assemble_element computed the nodal maps A_, K_ of that point).
    void assemble_rest_terms(int k, int q, const InterpolatedRotation<P>& rot, const Vec3& xp,
                             VecX& r, SparseMatrix* J);
    // The load stiffness (λ R f0)~ of a point load at `node`, scattered with `factor` (1: a
    // follower load; 0: a dead load under solver.assemble_all_terms).
    void add_load_stiffness(int node, const Vec3& f, const Vec3& m, double factor, SparseMatrix& J);

    Model model_;
    bool spin_forces_ = true;  // set_rotating_frame_forces
    Mesh mesh_;
    std::vector<NodeLoad> point_loads_;
    std::vector<double> distributed_factor_;  // per distributed load: time function value
    double lambda_ = 0.0;
    double time_ = 0.0;  // the loads' time (set_time; load fields in time)
    double force_scale_ = 1.0;
    double unit_force_scale_ = 1.0;  // at λ = 1
    double axial_stiffness_ = 0.0;   // largest EA-like diagonal entry
    bool fixed_force_scale_ = false;
    double length_scale_ = 1.0;
    VecX residual_scale_;
    VecX increment_scale_;

    std::vector<Vec3> u_;
    std::vector<Params> p_;
    std::array<std::vector<Vec3>, kCheckpointSlots> saved_u_;
    std::array<std::vector<Params>, kCheckpointSlots> saved_p_;
    std::vector<Params> p_trial_;

    SparseMatrix pattern_;
    std::vector<std::vector<int>> block_index_;  // per element: (a·nn + b)·6 + c → value index
    std::vector<int> diagonal_index_;            // per node: 6 value indices of its diagonal block

    // Per-element workspace (sized for p+1 nodes).
    std::vector<Params> pe_;
    std::vector<Vec3> ue_;
    std::vector<param::TangentInverse<P::kSize>> Me_;
    std::vector<Mat3> A_;
    std::vector<Mat3> K_;
    Mat3 R0_ = Mat3::Identity();  // relative: the element's reference-node rotation
    bool relative_ = true;
    bool rescale_nodes_ = false;
    // The case asked for rescaling but `direct` interpolation cannot do it (describe_state says
    // so).
    bool rescale_refused_ = false;
    // update: additive — the Newton unknowns of a node's rotation are δp (p ← p + δp) and the
    // Jacobian's rotation columns are multiplied by H_s(p) (δψ = H_s(p) δp); three-parameter
    // types only. Lets KINSOL (an additive solver) drive the displacement formulation.
    bool additive_ = false;
    void apply_parameter_tangent(SparseMatrix& J) const;
    std::vector<Mat6> D_;
    std::vector<Eigen::Matrix<double, 3, 6>> E_;
    MipStresses mip_;  // solver.mip (mip_stresses.hpp); inactive by default

    AssemblyCounters counters_;
    bool absent_motion_ = false;
    bool absent_load_stiffness_ = false;
};

// Instantiated in displacement_statics.cpp for every parameterization of the registry.
#define ROTBEAM_DISPLACEMENT_EXTERN(P) extern template class DisplacementStatics<param::P>;
ROTBEAM_FOR_EACH_PARAMETERIZATION(ROTBEAM_DISPLACEMENT_EXTERN)
#undef ROTBEAM_DISPLACEMENT_EXTERN

}  // namespace rotbeam::form
