// The simplified Newton iteration of an implicit Runge–Kutta method's stage equations (Hairer &
// Wanner, "Solving ODEs II", §IV.8), shared by the Gauss–Legendre collocation
// (core/gauss_collocation.cpp) and Radau IIA (core/dae_radau.cpp): the iteration matrix is frozen,
// so the iteration converges linearly and the project's convergence test
// (core/convergence.hpp) runs with `linear` set. The schemes differ only in their stages, which
// `Stages` provides:
//  - double residual(): the stage residuals at the iterate, scaled (may be non-finite);
//  - double correction(): solves for the correction of every stage, returns its scaled size;
//  - void apply_correction(): adds it to the iterate;
//  - void converged(double rate): the iteration ended at the iterate; rate is the largest
//    contraction factor η_k/η_{k−1} seen (0 after one iteration), which decides whether the
//    matrix is kept (kKeptMatrixRate).
// Two iterations in a row in which neither the correction nor the residual shrinks mean the frozen
// matrix no longer describes the stage equations (step too large): the iteration stops with that
// message, as after max_iterations.
#pragma once

#include <algorithm>
#include <cmath>
#include <ostream>
#include <sstream>
#include <string>

#include "core/convergence.hpp"
#include "core/static_driver.hpp"

namespace rotbeam {

// The stage matrices are kept for the next step (of the same size) when the last iteration
// contracted at least this fast (its `rate`, above). A kept matrix costs nothing but iterations,
// each s residuals and the transformed solves, against the Jacobian evaluations and the
// factorizations of fresh ones (docs/performance.md, "Cost of one step of the high-order
// schemes").
constexpr double kKeptMatrixRate = 0.05;

template <class Stages>
NewtonOutcome iterate_stages(Stages& stages, const NewtonSettings& newton, double round_off_floor) {
    NewtonOutcome out;
    IterateMeasures m;
    m.linear = true;
    const ConvergenceTolerances tol{newton.residual_tolerance, newton.increment_tolerance};
    int growing = 0;
    double rate = 0.0;
    for (int k = 1; k <= newton.max_iterations; ++k) {
        m.previous_residual = m.residual;
        m.previous_correction = m.correction;
        m.residual = stages.residual();
        if (!std::isfinite(m.residual)) {
            out.failure = "non-finite stage residual at iteration " + std::to_string(k);
            out.iterations = k;
            return out;
        }
        m.correction = stages.correction();
        if (k > 1) rate = std::max(rate, m.correction / m.previous_correction);
        m.last_step_full = k > 1;
        m.round_off_floor = round_off_floor;
        const Convergence c = accepted(m, tol);
        if (newton.trace != nullptr) {
            *newton.trace << "  stage iteration " << k << ": residual " << m.residual
                          << ", correction " << m.correction << "\n";
        }
        if (c != Convergence::exact) stages.apply_correction();
        if (c != Convergence::none) {
            out.converged = c != Convergence::stalled_at_round_off;
            out.criterion = c;
            out.iterations = k;
            out.scaled_residual = m.residual;
            out.error_bound = c == Convergence::exact ? 0.0 : m.correction;
            out.round_off_floor = round_off_floor;
            stages.converged(rate);
            return out;
        }
        const bool stuck =
            m.correction >= m.previous_correction && m.residual >= m.previous_residual;
        growing = stuck ? growing + 1 : 0;
        if (growing >= 2) {
            std::ostringstream s;
            s << "the simplified Newton iteration of the stages does not contract (iteration " << k
              << ", scaled correction " << m.correction << ", residual " << m.residual << ")";
            out.failure = s.str();
            out.iterations = k;
            return out;
        }
    }
    std::ostringstream s;
    s << "the stage equations did not converge in " << newton.max_iterations
      << " iterations (scaled residual " << m.residual << ", correction " << m.correction << ")";
    out.failure = s.str();
    out.iterations = newton.max_iterations;
    return out;
}

}  // namespace rotbeam
