// The mixed GEBT dynamics with four rotation unknowns (the quaternion): the residual F(t, X, Ẋ) of
// seed 002 Eq. 56 and its Jacobians ∂F/∂X, ∂F/∂Ẋ, built on the quaternion statics
// (mixed_quaternion_element.hpp, the numbering of mixed_quaternion_layout.hpp) and the momentum
// terms of mixed_dynamic_element.hpp (generic in the parameter count). Design and index argument:
// docs/mixed-formulation.md ("Dynamics") and docs/mixed-dynamics.md ("The quaternion").
//
// Unknowns (columns)                                 Equations (rows)
//   element: u (3), q (4), F, M, P, H = 19             f_F^−, f_M^− (4), f_F^+, f_M^+ (4),
//                                                      f_P, f_H = 20
//   free node: û, q̂ (4) = 7                            equilibrium with the momentum terms = 6
//   first support: reactions = 6; further ones + ρ     equilibrium = 6
// Square on any tree held by its supports, as the statics (the two extra element rows balance the
// P, H columns with f_P, f_H, Eqs. 49–50). Eq. 50 reads f_H = Ω − C^ba H_m(q) q̇: q̇ enters only
// through H_m(q) q̇ (and the overbar terms of Eqs. 45–46, −R (·)~ H_m q̇), so its radial part
// (H_m q = 0) enters nowhere. The norm is kept as in statics, by the algebraic Cayley relations of
// the kinematic rows from the support at every instant; no norm equation, no multiplier. A free
// tree (no support, e.g. the manufactured motion's flying rod) has nothing to carry the norm from:
// it gets one last row ½(|q̂_0|² − 1) = 0 at node 0 (MixedQuaternionLayout::free_norm), algebraic.
//
// Differential and algebraic unknowns. Per element, u, P, H and the three tangential directions
// of q are differential; F, M, the radial direction of q and every node unknown algebraic (given
// u and the element rotations, the 14 kinematic rows fix F, M, |q| and the 7 node unknowns of the
// element's far node: index 1 on a tree with one support, as the three-parameter DAE). IDA's `id`
// is per component, not per direction, so two vectors are given:
//  - differential(): all four components of every element q are 1. IDA uses it (with
//    IDASetSuppressAlg) only to leave the algebraic unknowns out of its error test; the radial
//    direction then stays in the test, which is valid for an index-1 algebraic direction (it is a
//    smooth function of the differential state, |q_i| = cos(δ_i/4)) and costs nothing;
//  - initial_condition_differential(x): the consistent-initialization chart. The component of
//    largest magnitude of each element q is algebraic (solved in X, its rate held), the other three
//    differential (their rates solved): with q_k ≠ 0 the three columns of H_m(q) other than k span
//    R³ (its null space is q), so the rate equations are regular, and moving q_k moves q off the
//    constraint manifold's radial direction, so the kinematic rows fix it. Afterwards
//    complete_initial_rates() removes the radial part of q̇ (which F does not see).
#pragma once

#include <vector>

#include "core/dae_system.hpp"
#include "core/model.hpp"
#include "formulations/mixed/mixed_dynamic_element.hpp"
#include "formulations/mixed/mixed_quaternion_element.hpp"
#include "formulations/mixed/mixed_quaternion_layout.hpp"
#include "formulations/mixed/mixed_quaternion_statics.hpp"
#include "parameterizations/concept.hpp"

namespace rotbeam::form {

// Offsets inside a quaternion element's dynamic block (columns) and rows.
struct MixedQuaternionDynamicBlock {
    static constexpr int kUnknowns = 19;  // u, q, F, M, P, H
    static constexpr int kRows = 20;      // kinematic (14), f_P, f_H
    static constexpr int u = 0, q = 3, F = 7, M = 10, P = 13, H = 16;
    static constexpr int kinematic_rows = 14, fP = 14, fH = 17;
};

template <param::RotationParameterization P>
requires(P::kSize == 4) class MixedQuaternionDynamics : public DaeSystem {
  public:
    static constexpr int K = P::kSize;
    using Params = param::Params<K>;
    using Block = MixedQuaternionDynamicBlock;

    // As MixedDynamics<P>: `time_scale` sets the velocity scale of the momentum rows and unknowns;
    // InputError for a section without (or with a singular) mass, damping, or a structure that is
    // not a tree held by its supports (mixed_quaternion_layout.hpp).
    MixedQuaternionDynamics(const Model& model, double time_scale, double load_time_floor = 0.0);

    int size() const override { return size_; }
    void evaluate(double t, const VecX& x, const VecX& xdot, VecX& residual, SparseMatrix* J_x,
                  SparseMatrix* J_xdot) override;
    const SparseMatrix& pattern() const override { return pattern_; }
    const VecX& differential() const override { return differential_; }
    VecX initial_condition_differential(const VecX& x) const override;
    void complete_initial_rates(const VecX& x, VecX& xdot) const override;
    const VecX& residual_scale() const override { return residual_scale_; }
    const VecX& state_scale() const override { return state_scale_; }
    const VecX& increment_scale() const override { return increment_scale_; }
    AssemblyCounters counters() const override { return counters_; }
    std::string describe_state(const VecX& x) const override;

    const MixedQuaternionLayout& layout() const { return layout_; }
    int node_count() const { return static_cast<int>(layout_.base.nodes.size()); }
    bool supported(int node) const { return layout_.supported(node); }
    int node_column(int node) const { return layout_.node_column(node); }
    int element_column(int e) const { return layout_.node_unknowns + Block::kUnknowns * e; }
    int element_row(int e) const { return 6 * node_count() + Block::kRows * e; }
    int element_count() const { return layout_.base.element_count(); }

    // The dynamic state at rest with the statics' unknowns (MixedQuaternionStatics<P>).
    VecX from_static_state(const VecX& static_state) const;
    // Every element's momenta of a rigid translation with inertial velocity v: [P; H] = I [Aᵀv; 0].
    void set_translational_momenta(VecX& x, const Vec3& v) const;
    PointState point_state(const VecX& x, double t, int point_index) const;
    // As MixedQuaternionStatics<P>::rotation_stations, in state x at time t.
    std::vector<StaticProblem::RotationStation> rotation_stations(const VecX& x, double t) const;
    double max_rotation_angle(const VecX& x) const;
    // max | |q| − 1 | at the nodes (conserved by the Cayley relations) and in the elements
    // (cos(δ/4) by construction), in state x at time t.
    QuaternionNormDrift norm_drift(const VecX& x, double t) const;

  private:
    Params given_rotation(int node, double t) const;
    void node_motion(const VecX& x, double t, int node, Vec3& u_hat, Params& q_hat) const;
    void assemble_element(int e, double t, const VecX& x, const VecX& xdot, VecX& residual,
                          SparseMatrix* J_x, SparseMatrix* J_xdot);
    void add_node_terms(int e, double t, const VecX& x, VecX& residual, SparseMatrix* J_x) const;
    void add_point_loads(double t, const VecX& x, VecX& residual, SparseMatrix* J_x) const;
    void build_scales(double time_scale, double mass_scale, double inertia_scale);

    Model model_;
    MixedQuaternionLayout layout_;  // built without distributed loads: f_dead holds gravity only
    int size_ = 0;
    std::vector<Mat6> mass_inverse_;
    SparseMatrix pattern_;
    VecX differential_;
    VecX residual_scale_;
    VecX state_scale_;
    VecX increment_scale_;
    double load_time_floor_ = 0.0;
    AssemblyCounters counters_;
    MixedHomogeneousResult<K> static_result_;
    MixedInertiaResult<K> inertia_result_;
};

// The fixed sparsity pattern of ∂F/∂X and ∂F/∂Ẋ for the quaternion's dynamic numbering.
SparseMatrix mixed_quaternion_dynamic_pattern(const MixedQuaternionLayout& layout);

}  // namespace rotbeam::form
