// Shift-invert Arnoldi for a real pencil A φ = −s B φ (B may be singular): Spectra's
// GenEigsSolver (implicitly restarted Arnoldi) on (A + σB)⁻¹ B with a sparse LU of A + σB
// (Eigen's SparseLU, factorized once). With θ = 1/(σ − s) the eigenvalues s nearest the real shift
// σ have the largest |θ|; the infinite eigenvalues of a singular B map to θ = 0.
//
// Users: the mixed formulation's modal analysis (formulations/mixed/mixed_modal.hpp) and the
// displacement formulation's modes about a spinning state
// (formulations/displacement/gyroscopic_modal.hpp), which each choose from the Ritz pairs.
#pragma once

#include <Eigen/Dense>
#include <complex>
#include <optional>

#include "core/nonlinear_system.hpp"
#include "core/types.hpp"

namespace rotbeam {

struct ShiftInvertRitz {
    Eigen::VectorXcd theta;    // converged Ritz values of (A + σB)⁻¹B, largest |θ| first
    Eigen::MatrixXcd vectors;  // their Ritz vectors, one per column
    int arnoldi_vectors = 0;   // Spectra's ncv of the successful attempt
    int converged = 0;         // Ritz pairs converged
};

// |θ| at most this fraction of the largest: |s| above 1e12 × the lowest, an infinite eigenvalue
// (an unknown without rate) left at round-off.
inline constexpr double kInfiniteRitzValue = 1e-12;
// |Im s| at most this fraction of |s| is a real eigenvalue: a nonsymmetric solver leaves
// ~1e-14 |s| on one.
inline constexpr double kRealEigenvalueTolerance = 1e-10;

// The `nev` Ritz pairs of largest |θ|. Throws SolverError when A + σB is singular or the
// iteration does not converge (after one restart with twice the subspace).
ShiftInvertRitz shift_invert_arnoldi(const SparseMatrix& A, const SparseMatrix& B, int nev,
                                     double shift);

// s = σ − 1/θ of Ritz value i, or nothing for an infinite eigenvalue (kInfiniteRitzValue).
std::optional<std::complex<double>> ritz_eigenvalue(const ShiftInvertRitz& ritz, Eigen::Index i,
                                                    double shift);

}  // namespace rotbeam
