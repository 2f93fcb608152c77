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
// by the shift-invert Arnoldi of the mixed formulation's modal analysis with its eigenpair checks
// (formulations/mixed/mixed_modal.hpp). The frequency is Im s / 2π, Re s the growth rate.
#pragma once

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

}  // namespace rotbeam::form
