// KINSOL (SUNDIALS) as an alternative driver for additive nonlinear systems (DESIGN.md §Analyses):
// Newton with KINSOL's line search (KIN_LINESEARCH), the system's analytic sparse Jacobian handed
// to KLU through a compressed-sparse-column SUNMatrix, unknowns and residuals scaled by
// 1/increment_scale and 1/residual_scale.
//
// Callbacks are thin C trampolines: a SingularityError inside the system becomes a recoverable
// failure (return 1: KINSOL's line search backs off), any other exception a fatal one (−1); no C++
// exception ever crosses into SUNDIALS.
#pragma once

#include <string>

#include "core/nonlinear_system.hpp"

namespace rotbeam {

struct KinsolSettings {
    double residual_tolerance = 1e-12;  // on max_i |r_i| / residual_scale_i (KINSOL's fnormtol)
    double step_tolerance = 1e-14;      // on the scaled step (KINSOL's scsteptol)
    int max_iterations = 200;
    bool line_search = true;  // KIN_LINESEARCH, else KIN_NONE (plain Newton)
};

struct KinsolOutcome {
    bool converged = false;
    int flag = 0;         // KINSol's return flag
    long iterations = 0;  // nonlinear iterations
    long residual_evaluations = 0;
    long jacobian_evaluations = 0;
    double scaled_residual = 0.0;  // max_i |r_i| / residual_scale_i at the returned state
    bool singular = false;         // a parameterization refused a state it was asked about
    std::string failure;           // KINSOL's message when it did not converge
};

// Solves system(x) = 0 from its current state; the system is left at KINSOL's last iterate.
// Throws InputError when the system is not additive.
KinsolOutcome solve_kinsol(NonlinearSystem& system, const KinsolSettings& settings);

}  // namespace rotbeam
