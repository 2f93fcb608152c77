// Modal analysis of the mixed formulation about a static state (seed 002 §IV.C:
// "GEBT calculates the steady state solution first, and the eigenvalue analysis is performed
// corresponding to this state").
//
// Linearizing F(t, X, Ẋ) = 0 (Eq. 56) about an equilibrium X₀ at rest, F(X₀ + x, ẋ) ≈ A x + B ẋ
// with A = ∂F/∂X, B = ∂F/∂Ẋ. Modes x = φ e^{st} solve A φ = −s B φ. B is singular (the algebraic
// unknowns F, M and the node unknowns have no rate: infinite eigenvalues) and A is not symmetric
// (the mixed equations are not a potential's Hessian), so neither a symmetric nor a definite
// solver applies. Shift-invert with a real shift σ: (A + σB)⁻¹ B φ = θ φ with θ = 1/(σ − s), so the
// s nearest σ have the largest |θ| and the infinite ones map to θ = 0 and drop out by themselves.
// Arnoldi (Spectra's GenEigsSolver, implicitly restarted) on that operator with a sparse LU of
// A + σB (Eigen's SparseLU, factorized once; core/shift_invert_arnoldi.hpp). σ = 0 (the lowest |s|)
// needs A itself regular: it is the static tangent augmented by the momentum rows, regular at a
// stable equilibrium.
//
// An undamped structure has s = ±iω pairs; one of each pair is kept (Im s > 0) and reported as
// f = |Im s|/2π with Re s (zero to round-off without damping or gyroscopic terms). About a
// spinning state (solve_dae_modal_refined) a real s > 0 is kept too (divergence), and each pair is
// refined on A + sB with an error estimate of its own (core/refined_ritz_modes.hpp).
//
// Each reported pair is checked against the pencil it claims to solve (core/eigenpair_check.hpp):
// the backward error of (s, φ) for A φ = s (−B) φ. B = ∂F/∂Ẋ is no mass matrix (singular by
// design, not symmetric), so no mass orthogonality or participation applies; the infinite
// eigenvalues of the algebraic unknowns are separated by the shift-invert itself (θ = 0).
#pragma once

#include <complex>
#include <string>
#include <vector>

#include "core/eigenpair_check.hpp"
#include "core/model.hpp"
#include "core/nonlinear_system.hpp"
#include "core/types.hpp"

namespace rotbeam::form {

using rotbeam::VecXc;

struct DaeModalSolution {
    std::vector<double> frequencies_hz;  // ascending, f = |Im s| / 2π
    std::vector<double> growth_rates;    // Re s [1/time]
    std::vector<VecXc> shapes;           // φ in the DAE's unknowns
    std::vector<EigenpairCheck> checks;  // per pair
    int arnoldi_vectors = 0;             // Spectra's ncv
    int converged = 0;                   // Ritz pairs converged
    // solve_dae_modal_refined only (empty otherwise): per pair, the Arnoldi value before the
    // refinement and the refinement steps taken.
    std::vector<std::complex<double>> arnoldi_s;
    std::vector<int> refinement_steps;
    bool accepted() const;  // every pair passed its check
};

// The `count` lowest-frequency oscillatory modes of A φ = −s B φ by shift-invert Arnoldi.
// Throws SolverError when A + σB is singular or fewer than `count` oscillatory modes converge.
DaeModalSolution solve_dae_modal(const SparseMatrix& A, const SparseMatrix& B, int count,
                                 double shift = 0.0);

// The `count` modes nearest s = 0 of A φ = −s B φ where a growth is the question (the modes about a
// spinning state, docs/rotating-frame.md, or about a loaded static state): from the same Arnoldi
// iteration, one of each conjugate pair and, unlike solve_dae_modal, the growing member of each
// real pair (s > 0, f = 0: divergence), each refined on A + sB by the two-sided Rayleigh functional
// iteration with its first-order error estimate in check.error_estimate
// (core/refined_ritz_modes.hpp, core/quadratic_eigenpair.hpp with M = 0): the flutter/divergence
// verdict's threshold (runs/modal_checks.cpp). Ascending Im s: divergences first. Throws
// SolverError as solve_dae_modal.
DaeModalSolution solve_dae_modal_refined(const SparseMatrix& A, const SparseMatrix& B, int count);

// The same by a dense eigen-decomposition of (A + σB)⁻¹B (all eigenvalues; for small models and
// as the cross-check of the Arnoldi iteration in the tests).
DaeModalSolution solve_dae_modal_dense(const SparseMatrix& A, const SparseMatrix& B, int count,
                                       double shift = 0.0);

// The model with its loads frozen at load factor λ and time t: every load's vector multiplied by
// λ·time(t) (prescribed motion and gravity by λ, as MixedStatics does) and its time function made
// constant 1, so the dynamic residual at any time holds the static state's loads, follower
// stiffness included.
Model frozen_loads(const Model& model, double lambda, double t = 0.0);

}  // namespace rotbeam::form
