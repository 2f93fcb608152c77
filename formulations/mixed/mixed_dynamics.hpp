// The mixed GEBT formulation for dynamics (seed 002 Eqs. 16–56): the residual F(t, X, Ẋ) of Eq. 56
// with the momenta P, H of every element and its two Jacobians ∂F/∂X, ∂F/∂Ẋ, one class for every
// parameterization. Theory notes: docs/mixed-dynamics.md; the quaternion's design and index
// argument docs/mixed-formulation.md ("Dynamics") and docs/mixed-dynamics.md ("The quaternion").
//
// Unknowns and equations (MixedNumbering, mixed_layout.hpp, with `dynamic`): per node the statics'
// unknowns (û, ĉ, or the reactions of a supported node, and ρ) and six equilibrium rows with the
// momentum terms of Eqs. 45–46 added (mixed_dynamic_element.hpp); per element u, c, F, M, P, H
// (15 + K) and the kinematic rows of Eqs. 47–48 unchanged plus f_P, f_H (Eqs. 49–50): 12 + 2K.
// Three parameters: 18N + 6M unknowns, seed 002 after Eq. 56. The quaternion: Eq. 50 reads
// f_H = Ω − C^ba H_m(q) q̇, so q̇ enters only through H_m(q) q̇ (and the overbar terms of Eqs.
// 45–46, −R (·)~ H_m q̇), and its radial part (H_m q = 0) enters nowhere. The norm is kept as in
// statics by the Cayley relations of the kinematic rows from the support at every instant; a free
// tree (no support, e.g. the manufactured motion's flying rod) gets the parameterization's
// constraint row ½(|q̂_0|² − 1) = 0 at node 0 (param::ParameterConstraint), algebraic.
//
// Differential unknowns (rates appear in F): u, c, P, H of every element, and the components of F,
// M whose damping coefficient μᵢ is not zero (mixed_damping.hpp: the damping force holds their
// rates); algebraic: the other F, M and all node unknowns. The initial conditions solve the damped
// F, M as algebraic unknowns (fixed by the kinematic rows given u, c) with their rates held at
// zero, consistent for every start the runner makes: at rest, in rigid translation or in rigid
// rotation with a turning frame the strains do not change. With a redundant parameter (the
// quaternion) the radial direction of c is algebraic too, and IDA's `id` is per component, not per
// direction, so two vectors are given:
//  - differential(): all K components of every element c are 1. IDA uses it (with
//    IDASetSuppressAlg) only to leave the algebraic unknowns out of its error test; the radial
//    direction then stays in the test, which is valid for an index-1 algebraic direction (it is a
//    smooth function of the differential state, |q_i| = cos(δ_i/4)) and costs nothing;
//  - initial_condition_differential(x): the consistent-initialization chart. The parameterization's
//    algebraic_component of each element c is algebraic (solved in X, its rate held), the others
//    differential (their rates solved); afterwards complete_initial_rates() removes the radial
//    part of ċ (which F does not see). Without a redundant parameter both are differential().
//
// Turning root (case key `rotating_frame`, docs/rotating-frame.md): frame a of seed 002 turns at
// constant Ω about the axis through c, Q(t) = exp(t Ω̃); u, c are the motion relative to it (the
// supports at rest in it), P, H the absolute momenta, and the element gains the ω_a and v_i terms
// of Eqs. 45, 46, 49, 50 (mixed_frame_terms.hpp). Gravity turns in the frame's axes (Q(t)ᵀ g);
// dead loads, which would turn too, are refused, as in the displacement formulation.
//
// Loads and prescribed motion follow their time functions; tables and ramps (which may jump) are
// evaluated at max(t, t⁺) with t⁺ = start + 1e-6 Δt, their right limit at the start (a load
// released at t = 0, docs/benchmarks.md §8, is off from the initial conditions on).
#pragma once

#include <vector>

#include "core/dae_system.hpp"
#include "core/model.hpp"
#include "formulations/mixed/mixed_damping.hpp"
#include "formulations/mixed/mixed_dynamic_common.hpp"
#include "formulations/mixed/mixed_dynamic_element.hpp"
#include "formulations/mixed/mixed_element.hpp"
#include "formulations/mixed/mixed_frame_terms.hpp"
#include "formulations/mixed/mixed_layout.hpp"
#include "formulations/mixed/mixed_node_frames.hpp"
#include "formulations/mixed/mixed_statics.hpp"
#include "parameterizations/concept.hpp"
#include "parameterizations/parameter_constraint.hpp"

namespace rotbeam::form {

template <param::RotationParameterization P>
class MixedDynamics : public DaeSystem {
  public:
    static constexpr int K = P::kSize;
    static constexpr int kConstraintRows = param::ParameterConstraint<P>::kRows;
    using Params = param::Params<K>;

    // `time_scale` sets the velocity scale length / time_scale of the f_P, f_H rows and of P, H
    // (the end time of a dynamic run, 1 otherwise). Throws InputError when a section has no mass
    // matrix or a singular one (Eq. 18 is inverted), carries damping with a singular compliance,
    // or (with a redundant parameter) the structure is not a tree held by its supports or a
    // single free tree.
    MixedDynamics(const Model& model, double time_scale, double load_time_floor = 0.0);

    int size() const override { return numbering_.size(); }
    void evaluate(double t, const VecX& x, const VecX& xdot, VecX& residual, SparseMatrix* J_x,
                  SparseMatrix* J_xdot) override;
    const SparseMatrix& pattern() const override { return pattern_; }
    const VecX& differential() const override { return differential_; }
    const VecX& configuration() const override { return configuration_; }
    VecX initial_condition_differential(const VecX& x) const override;
    void complete_initial_rates(const VecX& x, VecX& xdot) const override;
    const VecX& residual_scale() const override { return residual_scale_; }
    const VecX& state_scale() const override { return state_scale_; }
    const VecX& increment_scale() const override { return increment_scale_; }
    AssemblyCounters counters() const override { return counters_; }
    std::string describe_state(const VecX& x) const override;

    const MixedLayout& layout() const { return layout_; }
    const MixedNumbering& numbering() const { return numbering_; }
    int node_count() const { return numbering_.node_count(); }
    int element_count() const { return numbering_.element_count; }
    bool supported(int node) const { return numbering_.supported(node); }
    int node_column(int node) const { return numbering_.node_column(node); }
    int element_column(int e) const { return numbering_.element_column(e); }
    int element_row(int e) const { return numbering_.element_row(e); }
    void set_load_time_floor(double t) { load_time_floor_ = t; }

    // The dynamic state at rest with the statics' unknowns (MixedStatics<P>::state_vector()); at
    // rest relative to a turning frame with one (the momenta of its rigid rotation).
    VecX from_static_state(const VecX& static_state) const;
    // Sets every element's momenta to those of a rigid translation with velocity v relative to
    // the frame (inertial without one): [P; H] = I [Aᵀ (v + Ω × r); Aᵀ Ω], Ω = 0 without a frame
    // (an initial velocity, DynamicSettings::initial_velocity).
    void set_translational_momenta(VecX& x, const Vec3& v) const;
    // The turning frame (zero angular velocity without one).
    bool rotating() const { return spinning_; }
    const Vec3& frame_angular_velocity() const { return omega_frame_; }
    const Vec3& frame_center() const { return center_; }
    Mat3 frame_rotation(double t) const;
    // Kinetic energy ½ Σ ΔL [V; Ω]ᵀ [P; H], strain energy ½ Σ ΔL [F; M]ᵀ S [F; M] and the angular
    // momentum Σ ΔL (r × A P + A H) about the frame's centre (the origin without one), in the
    // unknowns' axes, of state x (element mid-point values: the element's constant momenta).
    MixedEnergy energy(const VecX& x) const;
    // Named point displacement and rotation (relative to the reference) in state x at time t.
    PointState point_state(const VecX& x, double t, int point_index) const;
    // As MixedStatics<P>::rotation_stations, in state x at time t.
    std::vector<StaticProblem::RotationStation> rotation_stations(const VecX& x, double t) const;
    // As MixedStatics<P>::node_frames and section_resultants (mixed_node_frames.hpp), in state x
    // at time t; with a turning frame in its axes (the motion relative to it).
    std::vector<StaticState::NodeFrame> node_frames(const VecX& x, double t) const;
    std::vector<SectionResultants> section_resultants(const VecX& x) const;
    // The node frames' nodes (mixed_frame_nodes), e.g. for a mode's amplitudes in their order.
    std::vector<MixedFrameNode> frame_nodes() const {
        return mixed_frame_nodes(layout_, element_count());
    }
    double max_rotation_angle(const VecX& x) const;
    // max | |q| − 1 | at the nodes (conserved by the Cayley relations) and in the elements
    // (cos(δ/4) by construction), in state x at time t.
    // The constraint spelled out (not kConstraintRows): clang 14 does not find a class member
    // in the requires-clause of the out-of-line definition.
    QuaternionNormDrift norm_drift(const VecX& x, double t) const
        requires(param::ParameterConstraint<P>::kRows > 0);

  private:
    Params given_rotation(int node, double t) const;
    void node_motion(const VecX& x, double t, int node, Vec3& u_hat, Params& c_hat) const;
    void assemble_element(int e, double t, const VecX& x, const VecX& xdot, VecX& residual,
                          SparseMatrix* J_x, SparseMatrix* J_xdot);
    void add_node_terms(int e, double t, const VecX& x, VecX& residual, SparseMatrix* J_x) const;
    void add_damping(int e, const VecX& x, const VecX& xdot, VecX& residual, SparseMatrix* J_x,
                     SparseMatrix* J_xdot);
    void add_point_loads(double t, const VecX& x, VecX& residual, SparseMatrix* J_x) const;
    void build_scales(double time_scale, double mass_scale, double inertia_scale);
    Vec3 element_position(int e, const VecX& x) const;  // x^r_i + u_i − c

    Model model_;
    MixedLayout layout_;  // built without distributed loads: f_dead holds gravity only
    MixedNumbering numbering_;
    std::vector<Mat6> mass_inverse_;
    SparseMatrix pattern_;
    VecX differential_;
    VecX configuration_;  // u, c of every element
    VecX residual_scale_;
    VecX state_scale_;
    VecX increment_scale_;
    double load_time_floor_ = 0.0;
    AssemblyCounters counters_;
    MixedElementResult<K> static_result_;
    MixedInertiaResult<K> inertia_result_;
    MixedFrameResult<K> frame_result_;
    std::vector<MixedDampingSection> damping_;  // per element; inactive without damping
    MixedDampingResult<K> damping_result_;
    VecX ic_differential_;  // differential_ with the damped F, M algebraic (initial conditions)
    bool spinning_ = false;
    Vec3 omega_frame_ = Vec3::Zero();
    Vec3 center_ = Vec3::Zero();
};

}  // namespace rotbeam::form
