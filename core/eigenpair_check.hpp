// A posteriori checks of computed eigenpairs of a pencil A x = λ B x: a frequency is reported
// only when its pair passes them (docs/displacement-modal.md, "Checks").
//
// - Backward error (every pencil): η = ‖Ax − λBx‖ / ((‖A‖ + |λ|‖B‖)‖x‖), Frobenius norms of A, B
//   and 2-norms of vectors: the smallest relative perturbation of (A, B) of which (λ, x) is an
//   exact pair (Higham & Higham, "Structured backward error and condition of generalized
//   eigenvalue problems", SIAM J. Matrix Anal. Appl. 20, 1998, Thm. 1 for the normwise case).
//   A backward-stable solver leaves η at a small multiple of the unit round-off.
// - Error bound (symmetric A, positive definite B): with r = Ax − ρBx, ρ = xᵀAx / xᵀBx the
//   Rayleigh quotient, some eigenvalue λ satisfies |λ − ρ| ≤ ‖r‖_{B⁻¹} / ‖x‖_B (the residual bound
//   of the symmetric definite pencil, Parlett, "The Symmetric Eigenvalue Problem", Thm. 15.9.1
//   after the congruence L⁻¹AL⁻ᵀ, B = LLᵀ), and when the other eigenvalues are at least δ away,
//   |λ − ρ| ≤ ‖r‖²_{B⁻¹} / (‖x‖²_B δ) (Kato–Temple, Thm. 10.5.1 there). Both are rigorous in exact
//   arithmetic, invariant under a diagonal scaling of the pencil, and blow up when B is
//   near-singular (‖·‖_{B⁻¹} grows like 1/μ_min(B)): the failure of a rank-deficient mass rule,
//   where the Cholesky-based solver turns round-off into eigenvalues of any size.
// - Mass orthogonality (symmetric definite): max_j≠i |x_iᵀBx_j| / √(x_iᵀBx_i x_jᵀBx_j) over the
//   reported pairs; exact eigenvectors of distinct eigenvalues are B-orthogonal.
// - Mass participation (non-symmetric pencils): |xᴴBx| / (‖B‖₁ ‖x‖²). An eigenvector of an
//   infinite (or nearly infinite) eigenvalue of a singular B has xᴴBx ≈ 0: its "frequency" is
//   round-off, whatever its backward error.
// - Error estimate (quadratic problems, core/quadratic_eigenpair.hpp): the first-order error of
//   the eigenvalue s relative to |s|, from the pair's residual and its left eigenvector.
#pragma once

#include <complex>
#include <string>
#include <vector>

#include "core/nonlinear_system.hpp"
#include "core/types.hpp"

namespace rotbeam {

using VecXc = Eigen::Matrix<std::complex<double>, Eigen::Dynamic, 1>;

// Accepted relative error of an eigenvalue λ = ω²: the bound must certify the frequency to
// ½ of this (5e-9), two orders below the finest comparison the repository makes of a frequency
// (the bench's 1e-6 of the converged value, and the 6-digit converged Table III column).
inline constexpr double kEigenvalueErrorTolerance = 1e-8;
// Accepted mass orthogonality: the dense solvers leave ~1e-12; a pair further from orthogonal
// than 1e-6 is not an eigenvector of a distinct eigenvalue to the accuracy claimed above.
inline constexpr double kMassOrthogonalityTolerance = 1e-6;
// Accepted backward error of a non-symmetric pair: QZ and converged Arnoldi leave ≲ 1e-13.
inline constexpr double kBackwardErrorTolerance = 1e-10;
// Smallest accepted mass participation: a finite eigenvalue of a positive definite B has
// participation ≥ μ_min(B)/‖B‖₁; 1e-10 is far below any usable mass and far above round-off.
inline constexpr double kMassParticipationTolerance = 1e-10;

struct EigenpairCheck {
    double backward_error = 0.0;       // η
    double error_bound = -1.0;         // relative bound on λ (symmetric definite); −1: none
    double error_estimate = -1.0;      // first-order relative error of λ (quadratic); −1: none
    double mass_orthogonality = -1.0;  // symmetric definite; −1: not applicable
    double mass_participation = -1.0;  // non-symmetric; −1: not applicable
    bool accepted = false;
    std::string failure;  // which check failed (empty when accepted)
};

// The symmetric definite pencil (A, B) with B = LLᵀ (llt). `pairs`: the reported (ρ, x), ρ
// replaced by the Rayleigh quotient; `spectrum`: every computed eigenvalue, ascending (for the
// gap δ of the Kato–Temple bound).
struct SymmetricPair {
    double lambda;
    VecX x;
};
std::vector<EigenpairCheck> check_symmetric_definite(const SparseMatrix& A, const SparseMatrix& B,
                                                     const Eigen::LLT<MatX>& llt,
                                                     std::vector<SymmetricPair>& pairs,
                                                     const std::vector<double>& spectrum);

// One pair (λ, x) of a general real pencil: backward error, and the mass participation when B is
// a mass matrix (`mass`; the mixed formulation's B = ∂F/∂Ẋ is singular by design).
EigenpairCheck check_general_pair(const SparseMatrix& A, const SparseMatrix& B,
                                  std::complex<double> lambda, const VecXc& x, bool mass);

// The JSON-facing name of the first failed check, or "" (for messages).
std::string describe(const EigenpairCheck& c);

}  // namespace rotbeam
