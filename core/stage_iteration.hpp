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
//    matrix is kept (KeptMatrices).
// Besides the project's criteria, an iterate is accepted when the iteration's own contraction
// bounds the error of the corrected iterate (Hairer & Wanner §IV.8, Eq. (8.10)–(8.11)): for an
// iteration contracting by θ per step, ‖Z* − (Z_k + ΔZ_k)‖ ≤ θ/(1 − θ) ‖ΔZ_k‖, so
// θ/(1 − θ) η_k ≤ increment_tolerance accepts Z_k + ΔZ_k with its algebraic error within the
// same increment tolerance that bounds every other accepted state. θ is
// the larger of the last two ratios η_k/η_{k−1}, η_{k−1}/η_{k−2} (so k ≥ 3): the stage corrections
// contract unevenly, alternating fast and slow iterations (measured on the joined beam, Gauss 3
// at 1.25 ms: 5e-5 then 0.2), and one fast ratio alone would understate the next. The residual
// tolerance is not asked of this iterate: the stage residual carries the (λ/h)² M rows of the
// stage matrix, so on the joined beam a residual ≤ 1e-12 asks an error ~1e-16, below what the
// corrections can resolve, and costs 3–5 iterations per step that do not change the stages beyond
// the increment tolerance (docs/solver-convergence.md, "Linearly converging iterations"). Such a
// state carries the criterion residual_and_correction with error_bound θ/(1 − θ) η_k: a correction
// test, which here stands in for the residual's; the enum has no name of its own for it yet.
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

// When the factored stage matrices of an earlier step serve the next one (both schemes). A kept
// matrix changes only the path of the simplified Newton, not where it stops: the residual is
// evaluated exactly at every iterate and the stopping tests (the project's, and the contraction
// bound θ/(1 − θ) η_k ≤ increment tolerance with θ measured on the iteration actually run) are
// the same, so a step ends within the same tolerance of its exact stages whichever matrix drove
// it; a worse matrix only contracts more slowly (larger θ, a later stop). The rule is about cost
// alone, as in the production stiff integrators (Hairer & Wanner II §IV.8: RADAU5 keeps the
// Jacobian while the contraction θ stays small, and the LU while h is unchanged; CVODE while γ
// changes little), and the convergence rate is monitored on every step:
//  - the scheme's KeptMatrixRule (below) says the kept matrices are still worth their iterations;
//  - the step size: within kKeptStepChange (relative) of the one the matrices were made for. The
//    matrices are K₀ + (λ/h) C₀ + (λ/h)² M₀ (Gauss) or ∂F/∂X + (λ/h) ∂F/∂Ẋ (Radau): a relative
//    change δ of h changes their (λ/h)-terms by at most 2δ, and the contraction by as much,
//    nothing at δ = 1e-6 against contractions of 1e-3 and more. It admits the fixed-step loop's
//    steps t_{n+1} − t_n, which differ from the case's Δt in the last bits (on 616 of the 1 600
//    steps of the joined beam at 1.25 ms, where an exact comparison refused the matrix), and,
//    but by chance, refuses an adaptive controller's changes, after which fresh ones are made;
//  - the budget: an iteration with kept matrices that has not converged after the iterations of
//    the last step on fresh ones plus `fresh_cost` (the cost of fresh matrices, Jacobian
//    evaluations and factorizations, in stage iterations, from the scheme's measured kernels:
//    docs/performance.md "Cost of one step of the high-order schemes") has cost what a fresh step
//    would; it is abandoned and the step restarts with fresh matrices, as after a failure.
// Dropping the rule for the budget alone (keep while a kept step takes at most `fresh_cost`
// iterations more than the last fresh one) was measured a net loss on the joined beam: Gauss 3 at
// 1.25 ms doubled its iterations (11 860 → 22 793) to save 649 of 1 446 fresh matrices, Radau at
// 0.75 ms 12 990 → 24 743 iterations to save 850 of 891 Jacobians (docs/performance.md, "Kept
// stage matrices").
constexpr double kKeptMatrixRate = 0.05;
constexpr double kKeptStepChange = 1e-6;

// Whether kept matrices are still worth their iterations:
//  - contraction: while the last converged iteration's worst ratio η_k/η_{k−1} ≤ kKeptMatrixRate;
//  - renewal: while the last step's iterations are below the average cost per step since the
//    last fresh matrices, their cost `fresh_cost` included. This is the replacement rule of
//    renewal theory (keep an asset while its marginal cost is below the cycle's average cost per
//    period; with a marginal cost that grows with age, that minimizes the long-run cost per
//    period), with the last step's iterations as the forecast of the next one's. It adapts to the
//    Newton tolerance by itself: a tight one needs more iterations per step, which makes a slow
//    contraction dearer, and the cycles shorten.
// Measured per scheme on the joined beam (callgrind, whole process, 0–2 s; docs/performance.md
// "Kept stage matrices by renewal; the mixed target met"): Radau IIA renews (2/3 ms, Newton 1e-7:
// −20 % instructions against contraction, 933 → 254 Jacobians; 0.25 ms at its default 1e-10:
// −3 % by the kernel costs); Gauss–Legendre keeps the contraction test (GL3 at 1 ms and 1e-7:
// renewal +6.8 %, 796 → 566 fresh matrices for 6 925 → 8 563 iterations; why was not measured).
enum class KeptMatrixRule { contraction, renewal };

class KeptMatrices {
  public:
    // `fresh_cost` ≤ 0: fresh matrices at every step (a reference for the tests).
    KeptMatrices(double fresh_cost, KeptMatrixRule rule) : fresh_cost_(fresh_cost), rule_(rule) {}
    // Whether the factored matrices may serve a step of size h.
    bool usable(double h) const {
        return fresh_cost_ > 0.0 && factored_h_ > 0.0 && worth_keeping() &&
               std::abs(h - factored_h_) <= kKeptStepChange * factored_h_;
    }
    // The iteration budget of a step with kept matrices (iterate_stages): what a fresh step
    // costs in iterations, at least 3 (the contraction test's first chance).
    int iteration_limit() const {
        return static_cast<int>(std::max(3.0, reference_ + fresh_cost_));
    }
    // Fresh matrices were factored for a step of size h (h = 0: none valid, e.g. a singular one).
    void made(double h) { factored_h_ = h; }
    // A step converged in `iterations` (its own iteration, not counting an abandoned kept one),
    // its worst contraction `rate`, on fresh matrices or kept ones.
    void converged(int iterations, double rate, bool fresh) {
        if (fresh) {
            reference_ = iterations;
            cycle_cost_ = fresh_cost_;
            cycle_steps_ = 0;
        }
        cycle_cost_ += iterations;
        ++cycle_steps_;
        last_ = iterations;
        rate_ = rate;
    }

  private:
    bool worth_keeping() const {
        if (rule_ == KeptMatrixRule::contraction) return rate_ <= kKeptMatrixRate;
        return static_cast<double>(last_) * cycle_steps_ < cycle_cost_;
    }

    double fresh_cost_;
    KeptMatrixRule rule_;
    double factored_h_ = 0.0;  // the step the matrices were made for (0: none valid)
    double rate_ = 1.0;        // the last converged iteration's worst η_k/η_{k−1}
    int reference_ = 0;        // the iterations of the last step on fresh matrices
    int last_ = 0;             // the iterations of the last converged step
    double cycle_cost_ = 0.0;  // since the last fresh matrices: their cost and every iteration
    int cycle_steps_ = 0;      // the steps converged since the last fresh matrices
};

// `budget` > 0 (an iteration with kept matrices: KeptMatrices::iteration_limit): after that many
// iterations without acceptance the iteration stops, not converged, with no failure message (the
// caller goes on with fresh matrices; nothing is allocated).
template <class Stages>
NewtonOutcome iterate_stages(Stages& stages, const NewtonSettings& newton, double round_off_floor,
                             int budget = 0) {
    NewtonOutcome out;
    IterateMeasures m;
    m.linear = true;
    const ConvergenceTolerances tol{newton.residual_tolerance, newton.increment_tolerance};
    int growing = 0;
    double rate = 0.0;
    double ratio = 0.0, previous_ratio = 0.0;  // η_k/η_{k−1} and η_{k−1}/η_{k−2}
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
        previous_ratio = ratio;
        if (k > 1) {
            ratio = m.correction / m.previous_correction;
            rate = std::max(rate, ratio);
        }
        m.last_step_full = k > 1;
        m.round_off_floor = round_off_floor;
        Convergence c = accepted(m, tol);
        double bound = m.correction;
        bool contracted = false;
        const double theta = std::max(ratio, previous_ratio);
        if (newton.contraction_stop && c == Convergence::none && k >= 3 && theta < 1.0 &&
            theta / (1.0 - theta) * m.correction <= tol.increment) {
            c = Convergence::residual_and_correction;
            bound = theta / (1.0 - theta) * m.correction;
            contracted = true;
        }
        if (newton.trace != nullptr) {
            *newton.trace << "  stage iteration " << k << ": residual " << m.residual
                          << ", correction " << m.correction;
            if (c != Convergence::none) {
                *newton.trace << ", accepted: " << (contracted ? "contraction" : to_string(c));
            }
            *newton.trace << "\n";
        }
        if (c != Convergence::exact) stages.apply_correction();
        if (c != Convergence::none) {
            out.converged = c != Convergence::stalled_at_round_off;
            out.criterion = c;
            out.iterations = k;
            out.scaled_residual = m.residual;
            out.error_bound = c == Convergence::exact ? 0.0 : bound;
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
        if (k == budget) {
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
