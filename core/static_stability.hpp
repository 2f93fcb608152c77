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
// for (loads without a potential are assessed kinetically instead where the system has a mass:
// core/static_stability_kinetic.hpp); an LDLᵀ that is not accurate (it does not pivot for
// stability: an indefinite S may grow its entries).
#pragma once

#include <optional>
#include <string>

#include "core/nonlinear_system.hpp"

namespace rotbeam {

// The status of a run with an unstable reported equilibrium (a solver status is in
// core/static_driver.hpp).
inline constexpr const char* kUnstableEquilibrium = "unstable-equilibrium";

// What a kinetic assessment (core/static_stability_kinetic.hpp) checked and found.
struct KineticSummary {
    int modes = 0;                    // eigenvalues checked: the lowest |s|
    double highest_frequency_hz = 0;  // the largest |s| / 2π among them
    int divergent = 0;                // real s > 0 beyond its error
    int fluttering = 0;               // complex s with Re s > 0 beyond its error
    double growth_rate = 0.0;         // the largest |Re s| beyond its error [1/time]
    double growth_rate_error = 0.0;   // the error estimate of that eigenvalue
    // The largest error estimate of the eigenvalues checked: no growth rate below it is seen.
    double largest_error = 0.0;
};

struct StaticStability {
    enum class Criterion {
        none,     // not assessed by either
        energy,   // the inertia of the potential energy's Hessian (or a symmetric tangent)
        kinetic,  // the eigenvalues of the linearized free motion (no potential)
    };
    enum class Assessment {
        not_assessed,  // `reason` says why
        stable,        // energy: the Hessian is positive definite; kinetic: no growing mode
        unstable,      // energy: `negative` directions decrease it; kinetic: a growing mode
        critical,      // a pivot at round-off level: singular to working precision (`reason`)
    };
    Assessment assessment = Assessment::not_assessed;
    Criterion criterion = Criterion::none;  // the one applied (`none` when not assessed)
    int negative = 0;  // negative pivots (energy) or growing modes (kinetic), when assessed
    std::string reason;
    // Where the energy's Hessian was read: the largest scaled distance (|δx_i| / increment
    // scale_i) from the reported equilibrium to the energy's stationary point next to it.
    std::optional<double> stationary_point_distance;
    std::optional<KineticSummary> kinetic;  // the kinetic criterion's findings
};
const char* to_string(StaticStability::Assessment a);
const char* to_string(StaticStability::Criterion c);

// The inertia of `tangent` (a Jacobian at a converged state, with its increment scales).
StaticStability assess_stability(const SparseMatrix& tangent, const VecX& increment_scale);

}  // namespace rotbeam
