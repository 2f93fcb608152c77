// Refinement, error estimate and check of an eigenpair of the quadratic eigenvalue problem
//   Q(s) x = (s² M + s G + K) x = 0,   Q'(s) = 2 s M + G,
// from an approximation (s₀, x₀) — the shift-invert Arnoldi on its first-order form
// (formulations/displacement/gyroscopic_modal.hpp), whose eigenvalues are accurate to the
// first-order pencil's round-off relative to the largest eigenvalue, not to their own size
// (core/refined_ritz_modes.hpp). A linear pencil A + sB is the case M = 0, G = B, K = A (the
// mixed formulation's linearized DAE, formulations/mixed/mixed_modal.hpp): its functional below is
// the two-sided Rayleigh quotient s = −yᴴAx / yᴴBx, its estimate and check those of the linear
// pencil.
//
// Refinement (Rayleigh functional iteration; Lancaster, "Lambda-matrices and Vibrating Systems",
// 1966, §5.7; Voss, "Nonlinear eigenvalue problems", Handbook of Linear Algebra, 2014, §115.3),
// each step on the exact matrices with a sparse LU of Q(s_k):
//   x_{k+1} ∝ Q(s_k)⁻¹ Q'(s_k) x_k,   y_{k+1} ∝ Q(s_k)⁻ᴴ Q'(s_k)ᴴ y_k   (inverse iteration, right
//   and left eigenvector, y₀ = x₀), s_{k+1} = the root of the Rayleigh functional nearest s_k:
// - `conservative` (M, K symmetric, G skew: a gyroscopic system without damping or circulatory
//   forces): Q(iω) = K + iωG − ω²M is Hermitian, so an imaginary eigenvalue's left eigenvector is
//   its right one and the two-sided functional is xᴴQ(s)x = m s² + i g s + k with m = xᴴMx,
//   k = xᴴKx and g = Im xᴴGx real (xᴴGx is imaginary for a skew G). With s = iω:
//   m ω² + g ω − k = 0. When g² + 4mk ≥ 0 both roots are real ω and s = iω exactly (Re s = 0 in
//   floating point, as the Hamiltonian spectrum of a stable conservative system has it);
//   otherwise s = (±√(−g² − 4mk) − i g)/2m: divergence (a real x has g = 0) or flutter.
// - otherwise the two-sided functional yᴴQ(s)x = 0 (quadratically convergent for a simple s).
// Stops when a step moves s by no more than the new pair's error estimate, or after kMaxSteps.
//
// Error estimate (first order): for the exact left eigenvector y (yᴴQ(s*) = 0) and any x,
// yᴴQ(s)x = (s − s*) yᴴQ'(s*)x + (s − s*)² yᴴMx, so s − s* = yᴴr / yᴴQ'(s)x to first order in
// s − s*, r = Q(s)x the residual, whatever the error of x (the eigenvalue's condition times the
// pair's backward error in the direction that moves it: Tisseur, "Backward error and condition of
// polynomial eigenvalue problems", Linear Algebra Appl. 309, 2000, Thms. 1 and 5). The computed
// yᴴr, and the matrices' entries themselves, carry a relative round-off u per entry, which moves
// s by up to u |y|ᵀ(|s|²|M| + |s||G| + |K|)|x| / |yᴴQ'(s)x| (the componentwise first-order bound):
// no eigenvalue of the assembled matrices is known better. So
//   δ = (|yᴴr| + u |y|ᵀ(|s|²|M| + |s||G| + |K|)|x|) / |yᴴQ'(s)x| + u |s|
// (the last term: s itself is a floating-point number), infinite at a defective eigenvalue
// (yᴴQ'x = 0: two eigenvalues meeting, where a growth rate is undecidable). A growth rate
// |Re s| ≤ δ is that error, not a growth (runs/modal_checks.cpp). The Cauchy–Schwarz form
// ‖y‖‖r‖ in place of |yᴴr| is no use on a stiff model: the residual of the floating-point x
// itself is u ‖|K||x|‖ (1.5e-5 on the spinning beams, GA/ρ = 1e12), a bound of 1e-6 |s|, while
// the componentwise term, of the same origin but seen by the eigenvalue, gives ≤ 7e-8 |s|.
//
// A stiffness asymmetry of the discretization, not of the model (`discretization_skew` N, the
// skew part of K when every load is conservative: the displacement formulation's Petrov–Galerkin
// weak form, docs/rotating-frame.md) moves s to first order by −yᴴNx / yᴴQ'(s)x; with a
// gyroscopic G that move is a real growth or decay rate (xᴴNx is imaginary, yᴴQ'x too), which
// the model does not have. So its modulus joins δ: the eigenvalue of the conservative model is
// known to no better than that.
//
// Check (core/eigenpair_check.hpp): the backward error η = ‖r‖ / ((|s|²‖M‖_F + |s|‖G‖_F +
// ‖K‖_F)‖x‖) (Tisseur's Thm. 1 with Frobenius norms, as the linear pencils' check) at most
// kBackwardErrorTolerance; a finite δ; and the refined s is the eigenvalue s₀ approximates:
// |s − s₀| ≤ β₀ + δ with β₀ = ‖Q(s₀)x₀‖ / |yᴴQ'(s₀)x₀| (‖x₀‖ = ‖y‖ = 1, y the refined left
// vector), the first-order bound on the distance from s₀ to its eigenvalue; a larger move is a
// jump to another eigenvalue (the intended one then unreported, another reported twice).
#pragma once

#include <complex>

#include "core/eigenpair_check.hpp"
#include "core/nonlinear_system.hpp"
#include "core/types.hpp"

namespace rotbeam {

struct QuadraticPencil {
    const SparseMatrix& M;
    const SparseMatrix& G;
    const SparseMatrix& K;
    bool conservative;  // M, K symmetric and G skew (to round-off: the caller decides)
    // The skew part of K that is the discretization's, not the model's (header comment); none
    // when null.
    const SparseMatrix* discretization_skew = nullptr;
};

struct RefinedQuadraticPair {
    std::complex<double> s;
    VecXc x;               // right eigenvector, unit 2-norm
    VecXc y;               // left eigenvector (yᴴQ(s) = 0), unit 2-norm
    double error = 0.0;    // δ (header comment), absolute, in the unit of s
    int steps = 0;         // refinement steps taken
    EigenpairCheck check;  // backward error, error_estimate = δ/|s|, and the refinement check
};

// At most this many steps: from the Arnoldi pairs of the spinning beams (|s − s₀| ~ 1e-6 |s|) one
// step reaches the estimate's floor and the second confirms it (docs/rotating-frame.md).
inline constexpr int kMaxQuadraticRefinementSteps = 3;

RefinedQuadraticPair refine_quadratic_pair(const QuadraticPencil& pencil, std::complex<double> s0,
                                           const VecXc& x0);

// δ of (s, x) with left vector y (header comment).
double quadratic_eigenvalue_error(const QuadraticPencil& pencil, std::complex<double> s,
                                  const VecXc& x, const VecXc& y);

}  // namespace rotbeam
