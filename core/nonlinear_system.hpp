// What a formulation exposes to the solver drivers: a residual, its consistent Jacobian and a
// retraction. The drivers (core/static_driver, KINSOL) know nothing else — not the
// parameterization, not the formulation (MFEM's "residual + Jacobian" habit).
//
// The state lives inside the system. `retract(dx)` moves it to x ⊕ dx: for rotations this composes
// the increment (multiplicative update), for additive systems it is x + dx. The Jacobian is the
// derivative of the residual with respect to dx at dx = 0, through the retraction.
#pragma once

#include <Eigen/SparseCore>
#include <string>

#include "core/types.hpp"

namespace rotbeam {

using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

// Counts of what an assembly built: the "model only what the scene requires" evidence.
struct AssemblyCounters {
    long residual_evaluations = 0;
    long jacobian_evaluations = 0;
    long elastic_terms = 0;       // quadrature-point evaluations of elastic forces
    long inertial_terms = 0;      // ... of inertial forces (zero in statics)
    long damping_terms = 0;       // ... of damping forces (zero without damping)
    long follower_stiffness = 0;  // follower-load stiffness contributions (zero for dead loads)
    long distributed_load_terms = 0;
    long gravity_terms = 0;
};

class NonlinearSystem {
public:
    virtual ~NonlinearSystem() = default;

    // Number of unknowns (the dimension of dx and of the residual).
    virtual int size() const = 0;
    // Residual at the current state; the Jacobian too when `jacobian` is non-null. The sparsity
    // pattern of the Jacobian must not change between calls (drivers reuse the symbolic
    // factorization). May throw SingularityError.
    virtual void evaluate(VecX& residual, SparseMatrix* jacobian) = 0;
    // state ← state ⊕ dx. May throw SingularityError (the state is then unchanged).
    virtual void retract(const Eigen::Ref<const VecX>& dx) = 0;
    // Checkpoints: slot kLineSearchSlot is used by the Newton line search, kStepSlot by the
    // load-step cutting (the last converged state). A system keeps kCheckpointSlots copies.
    static constexpr int kLineSearchSlot = 0;
    static constexpr int kStepSlot = 1;
    static constexpr int kCheckpointSlots = 2;
    virtual void save_state(int slot) = 0;
    virtual void restore_state(int slot) = 0;
    // Characteristic scales: r_i / residual_scale_i and dx_i / increment_scale_i are O(1)
    // (forces by a force scale, moments by force × length, displacements by a length, rotations
    // and dimensionless parameters by 1).
    virtual const VecX& residual_scale() const = 0;
    virtual const VecX& increment_scale() const = 0;

    // Additive systems (retract(dx) is x + dx) can also be driven by KINSOL through these.
    virtual bool additive() const { return false; }
    virtual VecX state_vector() const { return VecX(); }
    virtual void set_state_vector(const Eigen::Ref<const VecX>& /*x*/) {}

    // A short description of the current state for messages (e.g. the largest rotation angle).
    virtual std::string describe_state() const { return {}; }
};

// What the static driver (run_static, core/static_driver.hpp) drives: the nonlinear system and
// the load factor it is solved at. What a run reports of the solved state is read through
// StaticState (core/static_state.hpp), never through this interface.
class StaticSystem : public NonlinearSystem {
  public:
    virtual void set_load_factor(double lambda) = 0;
};

}  // namespace rotbeam
