// The complex sparse LU of the implicit Runge–Kutta stage systems (core/gauss_collocation.cpp,
// core/dae_radau.cpp): the eigen-transformed system of a conjugate pair of eigenvalues,
// E = K + μ C (+ μ² M) with complex μ, in the problem's real pattern.
//
// KLU in complex arithmetic (SuiteSparse's klu_z_*, values as (real, imaginary) pairs, which is
// std::complex<double>'s layout): the pattern analysed once, the first factorization pivoted,
// later ones refactored with the same pivot order into the same memory (klu_z_refactor) and solved
// in place (klu_z_solve), so a factorization or a solve allocates nothing, as the real KLU of
// core/sparse_lu.hpp. When the reciprocal pivot ratio of a refactorization falls below 1e-3 of the
// pivoted one's, the matrix is factored again with pivoting (the same rule as the real KLU).
// Measured against Eigen's complex SparseLU it replaces: docs/performance.md, "Cost of one step of
// the high-order schemes".
#pragma once

#include <Eigen/SparseCore>
#include <complex>
#include <memory>

namespace rotbeam {

using ComplexSparse = Eigen::SparseMatrix<std::complex<double>, Eigen::ColMajor, int>;

class ComplexKlu {
  public:
    ComplexKlu();
    ~ComplexKlu();
    ComplexKlu(const ComplexKlu&) = delete;
    ComplexKlu& operator=(const ComplexKlu&) = delete;

    // Factors E (compressed); analyses the pattern when it is new. False when E is singular.
    bool factorize(const ComplexSparse& E);
    // x ← E⁻¹ x for the last factorized E.
    void solve_in_place(Eigen::VectorXcd& x);
    // Factorizations with pivoting so far (the first, a new pattern, a stale pivot order).
    int pivoted_factorizations() const;

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace rotbeam
