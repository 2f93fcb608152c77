// KINSOL (SUNDIALS) for additive nonlinear systems (docs/architecture.md, Analyses and drivers):
// Newton with KINSOL's line search (KIN_LINESEARCH), the system's analytic sparse Jacobian handed
// to KLU through a compressed-sparse-column SUNMatrix, unknowns and residuals scaled by
// 1/increment_scale and 1/residual_scale.
//
// Callbacks are thin C trampolines: a SingularityError inside the system becomes a recoverable
// failure (return 1: KINSOL's line search backs off), any other exception a fatal one (−1); no C++
// exception ever crosses into SUNDIALS.
#pragma once

#include <limits>
#include <string>

#include "core/convergence.hpp"
#include "core/nonlinear_system.hpp"

namespace rotbeam {

// Acceptance follows core/convergence.hpp at KINSOL's last iterate (the Newton correction there is
// computed and applied); KINSOL's own tests only decide when it stops iterating.
struct KinsolSettings {
    double residual_tolerance = 1e-12;   // on max_i |r_i| / residual_scale_i (KINSOL's fnormtol)
    double increment_tolerance = 1e-12;  // on the scaled Newton correction at the last iterate
    double step_tolerance = 1e-14;       // on the scaled step (KINSOL's scsteptol)
    int max_iterations = 200;
    bool line_search = true;  // KIN_LINESEARCH, else KIN_NONE (plain Newton)
};

struct KinsolOutcome {
    bool converged = false;  // the tolerances were met
    Convergence criterion = Convergence::none;
    double error_bound = std::numeric_limits<double>::infinity();  // scaled, as NewtonOutcome's
    double round_off_floor = 0.0;
    bool accepted() const { return converged || criterion == Convergence::stalled_at_round_off; }
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
