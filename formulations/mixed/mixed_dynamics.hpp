// The mixed GEBT formulation for dynamics (seed 002 Eqs. 16–56): the residual F(t, X, Ẋ) of Eq. 56
// with the momenta P, H of every element and its two Jacobians ∂F/∂X, ∂F/∂Ẋ, generic over a
// three-parameter rotation parameterization. Theory note: docs/mixed-dynamics.md.
//
// Unknowns (18N + 6M, seed 002 after Eq. 56): per node the statics' six (û, ĉ, or the reactions of
// a supported node); per element u, c, F, M, P, H. The element block is 3 + k + 12 long for k
// rotation parameters (k = 3 here; the quaternion's k = 4 changes only the block length and the
// kinematic rows, MixedDynamicNumbering is written for it). Equations: the statics' node
// equilibrium rows with the momentum terms of Eqs. 45–46 added (mixed_dynamic_element.hpp), the
// kinematic rows of Eqs. 47–48 unchanged, and f_P, f_H (Eqs. 49–50) per element.
//
// Differential unknowns (rates appear in F): u, c, P, H of every element; algebraic: F, M and all
// node unknowns. Loads and prescribed motion follow their time functions; tables and ramps (which
// may jump) are evaluated at max(t, t⁺) with t⁺ = start + 1e-6 Δt, their right limit at the start
// (a load released at t = 0, docs/benchmarks.md §8, is off from the initial conditions on).
#pragma once

#include <vector>

#include "core/dae_system.hpp"
#include "core/model.hpp"
#include "formulations/mixed/mixed_dynamic_element.hpp"
#include "formulations/mixed/mixed_element.hpp"
#include "formulations/mixed/mixed_layout.hpp"
#include "parameterizations/concept.hpp"

namespace rotbeam::form {

// Offsets of the dynamic unknowns: nodes first (6 each, as in statics), then elements.
struct MixedDynamicNumbering {
    int nodes = 0;
    int elements = 0;
    int rotation_size = 3;
    int element_block() const { return 3 + rotation_size + 12; }  // u, c, F, M, P, H
    int size() const { return 6 * nodes + element_block() * elements; }
    int node_offset(int n) const { return 6 * n; }
    int element_offset(int e) const { return 6 * nodes + element_block() * e; }
    // Within an element block.
    int u() const { return 0; }
    int c() const { return 3; }
    int F() const { return 3 + rotation_size; }
    int M() const { return 6 + rotation_size; }
    int P() const { return 9 + rotation_size; }
    int H() const { return 12 + rotation_size; }
};

template <param::RotationParameterization P>
class MixedDynamics : public DaeSystem {
  public:
    // `time_scale` sets the velocity scale length / time_scale of the f_P, f_H rows and of P, H
    // (the end time of a dynamic run, 1 otherwise). Throws InputError when a section has no mass
    // matrix or a singular one (Eq. 18 is inverted).
    MixedDynamics(const Model& model, double time_scale, double load_time_floor = 0.0);

    int size() const override { return numbering_.size(); }
    void evaluate(double t, const VecX& x, const VecX& xdot, VecX& residual, SparseMatrix* J_x,
                  SparseMatrix* J_xdot) override;
    const SparseMatrix& pattern() const override { return pattern_; }
    const VecX& differential() const override { return differential_; }
    const VecX& residual_scale() const override { return residual_scale_; }
    const VecX& state_scale() const override { return state_scale_; }
    const VecX& increment_scale() const override { return increment_scale_; }
    AssemblyCounters counters() const override { return counters_; }
    std::string describe_state(const VecX& x) const override;

    const MixedLayout& layout() const { return layout_; }
    const MixedDynamicNumbering& numbering() const { return numbering_; }
    // The accessors MixedQuaternionDynamics has too (the runner is generic over both).
    int node_count() const { return numbering_.nodes; }
    bool supported(int node) const { return layout_.supported(node); }
    int node_column(int node) const { return numbering_.node_offset(node); }
    void set_load_time_floor(double t) { load_time_floor_ = t; }

    // The dynamic state at rest with the statics' unknowns (MixedStatics<P>::state_vector()).
    VecX from_static_state(const VecX& static_state) const;
    // Sets every element's momenta to those of a rigid translation with inertial velocity v:
    // [P; H] = I [Aᵀ v; 0] (an initial velocity, DynamicSettings::initial_velocity).
    void set_translational_momenta(VecX& x, const Vec3& v) const;
    // Named point displacement and rotation (relative to the reference) in state x at time t.
    PointState point_state(const VecX& x, double t, int point_index) const;
    // As MixedStatics<P>::rotation_stations, in state x at time t.
    std::vector<StaticProblem::RotationStation> rotation_stations(const VecX& x, double t) const;
    double max_rotation_angle(const VecX& x) const;

  private:
    void node_motion(const VecX& x, double t, int node, Vec3& u_hat, Vec3& c_hat) const;
    MixedElement loaded_element(int e, double t) const;
    double time_value(const TimeFunction& f, double t) const;
    void assemble_element(int e, double t, const VecX& x, const VecX& xdot, VecX& residual,
                          SparseMatrix* J_x, SparseMatrix* J_xdot);
    void add_point_loads(double t, const VecX& x, VecX& residual, SparseMatrix* J_x) const;

    Model model_;
    MixedLayout layout_;  // built without distributed loads: f_dead holds gravity only
    MixedDynamicNumbering numbering_;
    std::vector<Mat6> mass_inverse_;
    SparseMatrix pattern_;
    VecX differential_;
    VecX residual_scale_;
    VecX state_scale_;
    VecX increment_scale_;
    double load_time_floor_ = 0.0;
    AssemblyCounters counters_;
    MixedElementResult static_result_;
    MixedInertiaResult<> inertia_result_;
};

// The fixed sparsity pattern of ∂F/∂X and ∂F/∂Ẋ (all structural entries of both).
SparseMatrix mixed_dynamic_pattern(const MixedLayout& layout, const MixedDynamicNumbering& n);

// The section mass I (material axes) of an element, by discretization.mass_rule: `midpoint` the
// mid-length value (seed 002's GEBT), `consistent` the average over the element (the consistent
// mass of the element's constant momenta; equal to midpoint for a section constant along the
// element, every shipped case), `lumped` refused (no nodal masses). Linear between stations.
// Throws InputError when the member's sections carry no mass.
Mat6 mixed_element_mass(const Model& model, const MixedElement& element);

}  // namespace rotbeam::form
