// The stability of a converged static equilibrium, read from the inertia of a symmetric matrix.
//
// At conservative loads the equilibrium is stable when the Hessian of the potential energy on the
// free unknowns is positive definite. By Sylvester's law of inertia the number of its negative
// eigenvalues, the number of directions in which the energy decreases, is that of any congruent
// matrix: of S = D H D (D the increment scales, which equilibrate displacement and rotation
// columns) and of the diagonal D_LDL of a sparse LDLᵀ of S (P S Pᵀ = L D_LDL Lᵀ). A negative pivot
// count is therefore the count of unstable directions (docs/solver-convergence.md, Stability of
// the equilibrium). The driver passes the Hessian a system forms (core/potential_hessian.hpp);
// otherwise the Newton tangent, which is that Hessian only where it is symmetric to round-off
// (the displacement formulation's straight states: its residual tests with the interpolated
// spin, and is not the energy's gradient at deformed ones).
//
// Not assessed, and said so: a tangent that is not symmetric (follower loads, dead moments, the
// mixed formulation, deformed states without a potential), where no Sylvester count is vouched
// for; an LDLᵀ that is not accurate (it does not pivot for stability: an indefinite S may grow its
// entries).
#pragma once

#include <string>

#include "core/nonlinear_system.hpp"

namespace rotbeam {

// The status of a run with an unstable reported equilibrium (a solver status is in
// core/static_driver.hpp).
inline constexpr const char* kUnstableEquilibrium = "unstable-equilibrium";

struct StaticStability {
    enum class Assessment {
        not_assessed,  // `reason` says why
        stable,        // the tangent is positive definite
        unstable,      // `negative` directions decrease the energy
        critical,      // a pivot at round-off level: singular to working precision (`reason`)
    };
    Assessment assessment = Assessment::not_assessed;
    int negative = 0;  // negative pivots (when assessed)
    std::string reason;
};
const char* to_string(StaticStability::Assessment a);

// The inertia of `tangent` (a Jacobian at a converged state, with its increment scales).
StaticStability assess_stability(const SparseMatrix& tangent, const VecX& increment_scale);

}  // namespace rotbeam
