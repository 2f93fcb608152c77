// The sparse LU factorization of the Newton driver (core/static_driver.cpp).
//
// Default: Eigen's SparseLU (COLAMD ordering, partial pivoting at every factorization), the
// symbolic analysis done once per pattern. `refactor_in_place`: KLU (SuiteSparse, as SUNDIALS
// uses it) factors once with pivoting and afterwards refactors with the same pivot order into the
// same memory (klu_refactor) and solves in place (klu_solve): no heap allocation per
// factorization, for drivers that factor one pattern many times (a time integration). When the
// reciprocal pivot ratio (klu_rcond) of a refactorization falls below 1e-3 of the pivoted one's,
// the pivot order has gone stale and the matrix is factored again with pivoting.
// `dense` (solver.linear_solver: dense): the matrix copied into a dense array and factored by
// Eigen's PartialPivLU in place — for the systems of one or two spectral elements, which are
// dense blocks anyway: Eigen's supernodal SparseLU spends ~1.5 M instructions on an 84 × 84
// matrix whose dense factorization is 0.4 Mflop (docs/performance.md).
#pragma once

#include <memory>

#include "core/nonlinear_system.hpp"
#include "core/types.hpp"

namespace rotbeam {

class SparseLUSolver {
  public:
    enum class Kind { sparse_lu, klu_refactor, dense };
    explicit SparseLUSolver(bool refactor_in_place = false);
    explicit SparseLUSolver(Kind kind);
    ~SparseLUSolver();
    SparseLUSolver(SparseLUSolver&&) noexcept;
    SparseLUSolver& operator=(SparseLUSolver&&) noexcept;

    // Factors J (compressed, column-major); analyses the pattern when it is new. False when J is
    // numerically singular.
    bool factorize(const SparseMatrix& J);
    // x = J⁻¹ b for the last factorized J; x must not alias b.
    void solve(const VecX& b, VecX& x);

    // Symbolic analyses made so far (one per new pattern): the witness that repeated
    // factorizations of one pattern reuse the analysis (tests/core, the scaling benchmarks).
    int symbolic_analyses() const;
    // Non-zeros of the last factorization's L + U (dense: n²), for the fill nnz(L + U) / nnz(J).
    double factor_nonzeros() const;

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace rotbeam
