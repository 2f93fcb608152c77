// Modal analysis of the displacement formulation about its current (static) state (issue 6
// point 3): the tangent stiffness K = ∂r/∂x through the retraction (the static Jacobian, with
// follower-load stiffness when there are follower loads) and the mass matrix M in the same
// unknowns [δu; δψ] per node (δψ spatial, so ψ̇ is the spatial angular velocity ω):
//   M_ab = Σ_q w_q N_a N_b [m I, m (Q η)~ᵀ; m (Q η)~, Q ρ Qᵀ],   Q = R(s_q) R^r(s_q),
// the sectional mass of seed 000 rotated to inertial axes. About an equilibrium at rest the
// gyroscopic and centrifugal blocks vanish, so the small oscillations obey M ẍ + K x = 0 and the
// eigenproblem is K x = ω² M x.
//
// Mass rule (Discretization::mass_rule), independent of the stiffness quadrature:
//   consistent — p+1 Gauss points (exact for the N_a N_b products);
//   midpoint   — one Gauss point per element (the element mid-point, as GEBT's midpoint inertia);
//   lumped     — p+1 Gauss–Lobatto–Legendre points (nodal quadrature: block-diagonal M).
// Rotations at mass points: Q = exp(Σ_j N_j log(R_0ᵀ R_j)) R_0 from the element's nodal rotations
// (relative to its first node: objective, exact for the undeformed state).
//
// Solver: dense generalized eigenproblem. K is checked for symmetry (dead loads, no follower
// stiffness: symmetric to round-off; follower loads or a deformed state under dead moments: not);
// symmetric → Eigen's GeneralizedSelfAdjointEigenSolver (M symmetric positive definite), otherwise
// the real QZ of Eigen::GeneralizedEigenSolver, keeping finite eigenvalues with Re ω² > 0.
#pragma once

#include <vector>

#include "core/model.hpp"
#include "core/nonlinear_system.hpp"
#include "core/types.hpp"
#include "formulations/displacement/mesh.hpp"

namespace rotbeam::form {

struct ModalSolution {
    std::vector<double> frequencies_hz;  // ascending
    std::vector<VecX> shapes;            // eigenvectors in the problem's unknowns
    std::vector<double> imaginary_parts; // Im ω² / (2π)² of the kept eigenvalues (0 if symmetric)
    bool symmetric = true;               // which solver was used
    double asymmetry = 0.0;              // ‖K − Kᵀ‖_max / ‖K‖_max
};

// The mass matrix in the unknowns of `mesh` (nodes with dof ≥ 0). `node_rotation(i)` returns the
// rotation of node i relative to its reference (R R^rᵀ of the node; identity when undeformed).
// Throws InputError when a member's section has no mass.
template <class NodeRotation>
SparseMatrix assemble_mass_matrix(const Model& model, const Mesh& mesh,
                                  const NodeRotation& node_rotation);

// The `count` lowest natural frequencies of K x = ω² M x. Throws SolverError when fewer exist.
ModalSolution solve_modal(const SparseMatrix& K, const SparseMatrix& M, int count);

// The mesh whose quadrature points are the mass rule's (same nodes and unknowns as `model`'s).
Mesh build_mass_mesh(const Model& model);

}  // namespace rotbeam::form

#include "formulations/displacement/displacement_modal_mass.hpp"
