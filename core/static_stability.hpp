// The stability of a converged static equilibrium, read from the inertia of its tangent.
//
// At a conservative (dead) load the consistent tangent of the displacement formulation is the
// Hessian of the potential energy on the free unknowns: symmetric, and the equilibrium is stable
// when it is positive definite. By Sylvester's law of inertia the number of its negative
// eigenvalues, the number of directions in which the energy decreases, is that of any congruent
// matrix: of S = D ½(J + Jᵀ) D (D the increment scales, which equilibrate displacement and
// rotation columns) and of the diagonal D_LDL of a sparse LDLᵀ of S (P S Pᵀ = L D_LDL Lᵀ). A
// negative pivot count is therefore the count of unstable directions, at the cost of one sparse
// factorization of the Jacobian the Newton solve already has (docs/solver-convergence.md,
// Stability of the equilibrium).
//
// Not assessed, and said so: a tangent that is not symmetric (follower loads, the mixed
// formulation), where no energy and no Sylvester count exist; an LDLᵀ that is not accurate (it
// does not pivot for stability: an indefinite S may grow its entries).
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
