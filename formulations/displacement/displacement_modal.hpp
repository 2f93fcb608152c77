// Modal analysis of the displacement formulation about its current (static) state:
// the tangent stiffness K = ∂r/∂x through the retraction (the static Jacobian, with
// follower-load stiffness when there are follower loads) and the mass matrix M in the same
// unknowns [δu; δψ] per node (δψ spatial, so ψ̇ is the spatial angular velocity ω):
//   M_ab = Σ_q w_q N_a N_b [m I, m (Q η)~ᵀ; m (Q η)~, Q ρ Qᵀ],   Q = R(s_q) R^r(s_q),
// the sectional mass of seed 000 rotated to inertial axes. About an equilibrium at rest the
// gyroscopic and centrifugal blocks vanish, so the small oscillations obey M ẍ + K x = 0 and the
// eigenproblem is K x = ω² M x.
//
// Mass rule (Discretization::mass_rule), independent of the stiffness quadrature:
//   consistent — p+1 Gauss points (exact for the N_a N_b products); with the trapezoidal
//                stiffness rule that rule (at the section stations, as BeamDyn integrates);
//   midpoint   — one Gauss point per element (the element mid-point, as GEBT's midpoint inertia);
//   lumped     — p+1 Gauss–Lobatto–Legendre points (nodal quadrature: block-diagonal M).
// Rotations at mass points: Q = exp(Σ_j N_j log(R_0ᵀ R_j)) R_0 from the element's nodal rotations
// (relative to its first node: objective, exact for the undeformed state).
//
// Solver: dense generalized eigenproblem on the pencil scaled by D = diag(M)^(−1/2) (DKD, DMD:
// same eigenvalues, unit mass diagonal). K is checked for symmetry (dead loads, no follower
// stiffness: symmetric to round-off; follower loads or a deformed state under dead moments: not).
// Symmetric → Cholesky of DMD = LLᵀ and the symmetric eigensolver on L⁻¹DKDL⁻ᵀ; otherwise the real
// QZ of Eigen::GeneralizedEigenSolver, dropping infinite eigenvalues, one of each conjugate pair.
// Every reported pair is checked (core/eigenpair_check.hpp) on the scaled pencil; the runner
// reports a frequency only for an accepted pair. A mass matrix with a zero diagonal entry or
// without a Cholesky factor is a SolverError naming it (no eigenvalue is computed from it).
#pragma once

#include <complex>
#include <vector>

#include "core/eigenpair_check.hpp"
#include "core/model.hpp"
#include "core/nonlinear_system.hpp"
#include "core/types.hpp"
#include "formulations/displacement/mesh.hpp"

namespace rotbeam::form {

// K (scaled by D) counts as symmetric when ‖K − Kᵀ‖_max ≤ this × ‖K‖_max: assembled from a
// potential's Hessian it is symmetric to ~1e-15; a follower load's stiffness is not, by orders.
inline constexpr double kStiffnessSymmetryTolerance = 1e-10;

// One eigenpair K φ = ω² M φ. Oscillation e^{st} with s² = −ω²: `growth_rate` = |Re s| (zero for
// a real ω² > 0; the growing member of the pair ±Re s for a complex ω² — flutter — and for a
// negative ω² — divergence, f = 0), `frequency_hz` = Im s / 2π = Re √ω² / 2π.
struct ModalPair {
    std::complex<double> omega2;
    double frequency_hz = 0.0;
    double growth_rate = 0.0;
    VecXc shape;  // in the problem's unknowns
    EigenpairCheck check;
};

struct ModalSolution {
    std::vector<double> frequencies_hz;  // of `pairs`, whether accepted or not (runner filters)
    std::vector<VecX> shapes;            // real parts of the pairs' shapes
    std::vector<ModalPair> pairs;        // the `count` lowest |ω²|, ascending
    bool symmetric = true;               // which solver was used
    double asymmetry = 0.0;              // ‖K − Kᵀ‖_max / ‖K‖_max
    bool accepted() const;               // every pair passed its check
};

// The mass matrix in the unknowns of `mesh` (nodes with dof ≥ 0). `node_rotation(i)` returns the
// rotation of node i relative to its reference (R R^rᵀ of the node; identity when undeformed).
// Throws InputError when a member's section has no mass.
template <class NodeRotation>
SparseMatrix assemble_mass_matrix(const Model& model, const Mesh& mesh,
                                  const NodeRotation& node_rotation);

// The `count` eigenpairs of K x = ω² M x lowest in |ω²|, checked. Throws SolverError when fewer
// finite eigenvalues exist or when M is singular (zero diagonal, no Cholesky factor).
ModalSolution solve_modal(const SparseMatrix& K, const SparseMatrix& M, int count);

// The mesh whose quadrature points are the mass rule's (same nodes and unknowns as `model`'s).
Mesh build_mass_mesh(const Model& model);

}  // namespace rotbeam::form

#include "formulations/displacement/displacement_modal_mass.hpp"
