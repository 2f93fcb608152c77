// Newton convergence: the criteria every nonlinear driver applies (core/static_driver's
// solve_newton, core/kinsol_driver), in one place. docs/solver-convergence.md derives them.
//
// Norms are scaled max norms: ρ = max_i |r_i| / residual_scale_i for a residual, and
// η = max_i |δ_i| / increment_scale_i for the Newton correction δ = −J⁻¹ r. At an iterate x_k
// the drivers know ρ_k, ρ_{k−1} and, once J(x_k) is factorized, η_k and the residual's expected
// round-off floor. A state is accepted by exactly one of:
//
//  - exact: r(x_k) = 0 in floating point; algebraic error 0.
//  - residual-and-correction: ρ_k ≤ residual_tolerance and η_k ≤ increment_tolerance. The
//    correction is applied; the algebraic error of x_k + δ_k is bounded by η_k.
//  - stalled-at-round-off: ρ_k is within kRoundOffMargin of the expected round-off floor, and the
//    last full Newton step did not halve it, but the tolerances are not both met (the user asked
//    for less than the arithmetic can give). The correction is applied; the algebraic error is
//    bounded by η_k as above. Not `converged`: the run says so, with the floor reached and
//    expected.
//    A linearly converging iteration (simplified Newton with a frozen matrix: the Gauss stage
//    equations, core/gauss_collocation.hpp) pauses: its residual can stay nearly flat for an
//    iteration while the correction still drops by orders of magnitude (measured on the joined
//    beam: ρ 4.4e-9 → 3.8e-9 while η 1.1e-10 → 3.5e-13; continued, the residual reaches 1.3e-12).
//    For it the stall also needs the correction to have stopped contracting, η_k ≥ ½ η_{k−1}: a
//    correction still shrinking moves the iterate by more than round-off.
//
// No tolerance is ever multiplied: a residual above residual_tolerance that is not at its
// round-off floor is never accepted. The error bound needs the correction at the accepted state
// itself: the increment that led there does not bound its error where the residual is still
// large (a stiff axial row far from its linear regime: measured on the 45° bend, an error 3.6×
// the last increment).
#pragma once

#include <limits>

#include "core/nonlinear_system.hpp"

namespace rotbeam {

enum class Convergence {
    none,  // not (yet) accepted
    exact,
    residual_and_correction,
    stalled_at_round_off
};
const char* to_string(Convergence c);

// A residual counts as at its round-off floor when it is at most this multiple of the floor
// estimated by round_off_floor (the estimate is the rounding of one term per row; a row sums tens
// of them). Measured floors reached, displacement formulation at 1e-12: 0.12 (45° bend), 0.28
// (helix), 0.37 (roll-up) of the estimate (docs/solver-convergence.md).
constexpr double kRoundOffMargin = 100.0;

// ε_mach ‖D_r⁻¹ |J| D_x‖_∞: the residual's expected round-off floor. A residual row sums terms
// J_ij x_j whose scaled size is |J_ij| increment_scale_j / residual_scale_i for an unknown of the
// size of its scale (positions of the length scale, rotations of order 1); when they cancel (as in
// equilibrium they do), each leaves a rounding error of ε times its size. `work` is a buffer (no
// allocation once it has the right size).
double round_off_floor(const SparseMatrix& J, const VecX& residual_scale,
                       const VecX& increment_scale, VecX& work);

// max_i |v_i| / scale_i; +∞ when any entry is not finite.
double scaled_max_norm(const VecX& v, const VecX& scale);

struct IterateMeasures {
    static constexpr double kInf = std::numeric_limits<double>::infinity();
    double residual = kInf;           // ρ_k
    double previous_residual = kInf;  // ρ_{k−1} (∞ at the first iterate)
    bool last_step_full = false;      // x_k = x_{k−1} + δ_{k−1} (undamped)
    double correction = kInf;         // η_k
    double round_off_floor = 0.0;     // at x_k
    // A linearly converging iteration (simplified Newton): the stall needs η_k ≥ ½ η_{k−1} too.
    bool linear = false;
    double previous_correction = kInf;  // η_{k−1} (∞ at the first iterate)
};

struct ConvergenceTolerances {
    double residual = 1e-12;
    double increment = 1e-12;
};

// With η_k and the floor known: exact, residual_and_correction, stalled_at_round_off or none.
Convergence accepted(const IterateMeasures& m, const ConvergenceTolerances& t);
// ρ_k within kRoundOffMargin of its expected floor: a Newton step there moves the state by
// round-off only and needs no damping (no monotonicity test can be passed at the floor).
bool at_round_off(const IterateMeasures& m);

}  // namespace rotbeam
