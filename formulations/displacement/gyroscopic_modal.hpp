// Modes of the displacement formulation about a state at rest in a frame turning at constant Ω
// (docs/rotating-frame.md): the small oscillations carry the velocity terms of the inertial
// force, M ẍ + G ẋ + K x = 0, with the gyroscopic matrix G = ∂F^I/∂[u˙; ω] of that state.
//
// Per section (calculate_inertial_forces.hpp, the dynamics' frame kinematics in
// displacement_dynamics.hpp) the velocity terms at relative rest are G^I at the absolute angular
// velocity ω = Ω plus the frame's columns [2 M_u Ω̃, M_ω Ω̃] (Coriolis of the translation rates,
// and ω˙_abs = ω˙ + Ω × ω), M_u and M_ω the rotated section mass's translation and rotation
// columns. Each is linear in the rotated section mass (G^I reads m η and ρ from it), so the
// integral Σ_q w N_a N_b G(M_q) is that map applied to the modal mass matrix's node-pair block
// M_ab = Σ_q w N_a N_b M_q (displacement_modal.hpp): G comes from M block by block, with the same
// quadrature points and rotations. It is skew (a conservative section), checked against central
// differences of the dynamic residual in the velocities (tests/displacement/
// test_dynamics_jacobian.cpp).
//
// The quadratic eigenproblem (s² M + s G + K) φ = 0 is solved in first-order form for
// y = [x; ẋ], scaled by D = diag(M)^(−1/2) as the modal solver scales its pencil,
//   A = [0, −I; DKD, DGD],   B = [I, 0; 0, DMD],   A y = −s B y,
// by the shift-invert Arnoldi of the mixed formulation's modal analysis (core/
// shift_invert_arnoldi.hpp, σ = 0: the modes nearest s = 0). Its eigenvalues are accurate to
// round-off relative to the largest |s| of the pencil (~1e6 1/s for a stiff section with small
// rotary inertia), not to their own size: Re s of a conservative system was left at up to
// 1.8e-6 1/s. So each pair is refined on the quadratic problem itself with the exact (scaled)
// matrices, and carries its own error estimate (core/quadratic_eigenpair.hpp): for a conservative
// system (K symmetric and G skew to kStiffnessSymmetryTolerance, M symmetric) the refinement puts
// a stable s on the imaginary axis exactly.
//
// A deformed state's K is not symmetric even when every load is conservative: the residual tests
// the moment rows with the interpolated spin, not the variation of the interpolated rotation (a
// Petrov–Galerkin weak form, docs/solver-convergence.md "Why not the Newton tangent"), so its
// skew part N is a discretization error, O(h²) and proportional to the load. Through G it gives
// the modes a growth or decay rate the conservative model does not have (1e-7 1/s on the NREL
// 5-MW blade under gravity, docs/rotating-frame.md). With conservative loads that skew part's
// first-order move of s joins each pair's error estimate (core/quadratic_eigenpair.hpp), so the
// verdict does not read it as flutter.
//
// Kept: one of each conjugate pair of oscillatory eigenvalues (Im s > 0) and the growing member
// of each real pair (s > 0, f = 0: divergence; a gyroscopic system's spectrum is symmetric about
// the imaginary axis, so −s is found with it); a real s < 0 without damping is dropped, as it
// was before (the selection and refinement: core/refined_ritz_modes.hpp, shared with the mixed
// formulation). The frequency is Im s / 2π, Re s the growth rate.
#pragma once

#include <complex>
#include <vector>

#include "core/eigenpair_check.hpp"
#include "core/nonlinear_system.hpp"
#include "core/types.hpp"

namespace rotbeam::form {

// G of a state at rest in the frame turning at `omega`, from the modal mass matrix M (6 unknowns
// per node, [u; rotation]).
SparseMatrix gyroscopic_matrix(const SparseMatrix& M, const Vec3& omega);

// The first-order pencil (header comment). The first K.rows() entries of an eigenvector of (A, B)
// times `scaling` (D) are the mode φ. Throws SolverError when M has an entry ≤ 0 on its diagonal.
struct GyroscopicPencil {
    SparseMatrix A, B;
    VecX scaling;
};
GyroscopicPencil gyroscopic_pencil(const SparseMatrix& K, const SparseMatrix& G,
                                   const SparseMatrix& M);

struct GyroscopicMode {
    std::complex<double> s;          // refined: Im s > 0, or a real s > 0 (divergence)
    std::complex<double> arnoldi_s;  // the Arnoldi iteration's, before refinement
    VecXc shape;                     // φ in the problem's unknowns
    EigenpairCheck check;            // on the quadratic problem (core/quadratic_eigenpair.hpp)
    double error = 0.0;              // first-order error estimate of s, absolute (1/time)
    int refinement_steps = 0;
};

struct GyroscopicModes {
    std::vector<GyroscopicMode> modes;  // ascending Im s: divergences first
    int arnoldi_vectors = 0;
    bool conservative = false;  // the refinement's structure (header comment)
    // With conservative loads, K's asymmetry (scaled, relative to its largest entry) when it is
    // the discretization's (header comment); 0 otherwise.
    double discretization_asymmetry = 0.0;
};

// The `count` modes nearest s = 0 (header comment), refined and checked. Throws SolverError as
// gyroscopic_pencil, when K is singular, or when fewer than `count` modes are found.
// `conservative_loads`: every load of the state has a potential (gravity, dead forces, the
// frame's centrifugal load), so a skew part of K is the weak form's discretization error and its
// first-order move of each s joins the error estimate (header comment).
GyroscopicModes solve_gyroscopic_modes(const SparseMatrix& K, const SparseMatrix& G,
                                       const SparseMatrix& M, int count,
                                       bool conservative_loads = false);

}  // namespace rotbeam::form
