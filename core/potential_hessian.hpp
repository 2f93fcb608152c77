// A static system whose loads have a potential: its total potential energy and the Hessian of it,
// from which the stability of an equilibrium is read (core/static_stability.hpp,
// docs/solver-convergence.md, Stability of the equilibrium). The static driver asks a system for
// it by dynamic_cast: a formulation that does not form the energy (the mixed one) is not one.
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "core/nonlinear_system.hpp"
#include "core/static_stability.hpp"

namespace rotbeam {

// The Hessian at the current state, in the chart ψ ↦ exp(ψ) R of each node's rotation (the
// normal coordinates of SO(3)'s bi-invariant metric) and the displacements.
struct PotentialHessian {
    SparseMatrix matrix;        // symmetric; the Jacobian's pattern
    double scaled_error = 0.0;  // the error of its entries scaled by the increment scales
    std::string unavailable;    // why there is none (the matrix is then empty)
};

class PotentialSystem {
  public:
    virtual ~PotentialSystem() = default;
    // These three leave the state as it was; none when the current loads have no potential.
    virtual std::optional<double> potential_energy() = 0;
    virtual PotentialHessian potential_hessian() = 0;
    // The gradient along the Hessian's chart (the residual's units); false when there is none.
    virtual bool potential_gradient(VecX& gradient) = 0;
    // state ← state ⊕ dx along the Hessian's chart: u + δu and exp(δψ) R at every free node —
    // not necessarily the Newton solve's retraction (which may be additive in the parameters).
    // May throw SingularityError; the state is then unchanged.
    virtual void move_along_potential_chart(const Eigen::Ref<const VecX>& dx) = 0;
};

// The inertia of the Hessian (with the system's increment scales): a pivot within its
// scaled_error (or n ε of its largest scaled entry) of zero is `critical`.
StaticStability assess_potential_stability(const PotentialHessian& hessian,
                                           const VecX& increment_scale);

// The stability of the energy's stationary point next to the system's equilibrium. The residual a
// formulation solves need not be the energy's gradient (the displacement formulation's is a
// Petrov–Galerkin form, and every parameterization is assessed with one energy), so its
// equilibrium is a stationary point of the energy only to its discretization error, and a
// Hessian read there can count negative eigenvalues the energy has nowhere near its own
// stationary point. Newton's method on the energy's gradient (with the difference Hessian, from
// the system's state) finds that point; the inertia is read there, the distance moved reported
// (`stationary_point_distance`), and the system's state restored bit for bit (through its
// checkpoint slot kLineSearchSlot). docs/solver-convergence.md, Stability of the equilibrium.
// When the energy has no Hessian at the equilibrium itself (loads without a potential, a chart
// singular next to it), `unavailable` says why and the result is not assessed.
// `tangent`, when given, solves J x = b with the Newton solve's last tangent (its first iteration
// matrix; empty: the Hessian from the start).
using TangentSolve = std::function<void(const VecX& b, VecX& x)>;
StaticStability assess_stability_at_stationary_point(StaticSystem& system,
                                                     PotentialSystem& potential,
                                                     const TangentSolve& tangent,
                                                     std::string& unavailable);

}  // namespace rotbeam
