// What a formulation exposes to the time integrators and the modal solver for an implicit
// differential-algebraic system F(t, X, Ẋ) = 0 (seed 002 Eq. 56): the residual and its two
// Jacobians ∂F/∂X and ∂F/∂Ẋ, which share one fixed sparsity pattern (so the iteration matrix
// ∂F/∂X + c ∂F/∂Ẋ is a sum of value arrays and the symbolic factorization is reused). The state is
// held by the caller, not by the system: IDA owns its vectors.
//
// Unknowns are additive (X + δ), as in the mixed formulation. `differential()` marks the unknowns
// whose rates appear in F (1) and the algebraic ones (0): IDASetId's vector.
#pragma once

#include <string>

#include "core/nonlinear_system.hpp"
#include "core/types.hpp"

namespace rotbeam {

class DaeSystem {
  public:
    virtual ~DaeSystem() = default;

    virtual int size() const = 0;
    // F(t, X, Ẋ) and, when non-null, ∂F/∂X and ∂F/∂Ẋ (both in pattern()). May throw
    // SingularityError (a parameterization refused the state). Allocates nothing after the first
    // call with a given pattern.
    virtual void evaluate(double t, const VecX& x, const VecX& xdot, VecX& residual,
                          SparseMatrix* J_x, SparseMatrix* J_xdot) = 0;
    virtual const SparseMatrix& pattern() const = 0;
    virtual const VecX& differential() const = 0;
    // The split used for consistent initial conditions at state x (consistent_initial_conditions,
    // every integrator's start): X is solved where 0, Ẋ where 1. The same as differential() unless
    // a differential direction is not a component (the quaternion's tangential directions:
    // formulations/mixed/mixed_dynamics.hpp), where a chart chosen at x makes that system regular.
    virtual VecX initial_condition_differential(const VecX& /*x*/) const { return differential(); }
    // After consistent initial conditions: sets the rates of directions F does not see (the
    // quaternion's radial rate) to their natural value. Nothing for most systems.
    virtual void complete_initial_rates(const VecX& /*x*/, VecX& /*xdot*/) const {}
    // 1 on the unknowns that describe the configuration (positions and rotation parameters), 0
    // elsewhere: what an error tolerance on the configuration measures. All differential unknowns
    // unless the system says otherwise.
    virtual const VecX& configuration() const { return differential(); }
    // Characteristic magnitudes of the residual rows and of the unknowns (O(1) after division).
    virtual const VecX& residual_scale() const = 0;
    virtual const VecX& state_scale() const = 0;
    // The scale of a Newton increment of each unknown: the state scale, or larger where an
    // increment at the state scale times the tolerance would be below the unknown's round-off
    // (a stiff section's force: see MixedDynamics).
    virtual const VecX& increment_scale() const { return state_scale(); }
    virtual AssemblyCounters counters() const = 0;
    virtual std::string describe_state(const VecX& /*x*/) const { return {}; }
};

// values(out) = values(a) + c values(b) for matrices in one pattern (no allocation when `out`
// already has that pattern).
inline void combine_same_pattern(const SparseMatrix& a, double c, const SparseMatrix& b,
                                 SparseMatrix& out) {
    if (out.nonZeros() != a.nonZeros() || out.rows() != a.rows()) out = a;
    const double* va = a.valuePtr();
    const double* vb = b.valuePtr();
    double* vo = out.valuePtr();
    for (Eigen::Index k = 0; k < a.nonZeros(); ++k) vo[k] = va[k] + c * vb[k];
}

}  // namespace rotbeam
