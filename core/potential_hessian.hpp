// A static system whose loads have a potential: its total potential energy and the Hessian of it,
// from which the stability of an equilibrium is read (core/static_stability.hpp,
// docs/solver-convergence.md, Stability of the equilibrium). The static driver asks a system for
// it by dynamic_cast: a formulation that does not form the energy (the mixed one) is not one.
#pragma once

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
    // Both leave the state as it was; none when the current loads have no potential.
    virtual std::optional<double> potential_energy() = 0;
    virtual PotentialHessian potential_hessian() = 0;
};

// The inertia of the Hessian (with the system's increment scales): a pivot within its
// scaled_error (or n ε of its largest scaled entry) of zero is `critical`.
StaticStability assess_potential_stability(const PotentialHessian& hessian,
                                           const VecX& increment_scale);

}  // namespace rotbeam
