// Numbering of the mixed statics with four rotation unknowns (the quaternion).
// The nodes, elements, frames and loads are MixedLayout's (mixed_layout.hpp); only the count and
// order of unknowns and equations change, so rows and columns get separate offsets.
//
// Unknowns (columns)                              Equations (rows)
//   element i: u (3), q (4), F (3), M (3) = 13      f_F^−, f_M^−, f_F^+, f_M^+ = 3 + 4 + 3 + 4 = 14
//   free node: û (3), q̂ (4) = 7                     equilibrium (Eqs. 31–32, 35–36, 39–40) = 6
//   supported node: reaction force, moment = 6     equilibrium = 6
//     (+ ρ, 1, at every support after the first: q̂ = ρ q_given, see below)
//
// Eq. 48 in four components: f_M^± = ±q − (ΔL/2) H_m⁺(q) C^ab κ with the right inverse
// H_m⁺(q) = Gᵀ(q)/2 of the quaternion's material tangent, i.e. H_m⁺ a = ½ q ⊗ (0, a): the
// discrete q′ = ½ q ⊗ κ̄. Subtracting f_M^+ from f_M^− gives q_i = (q̂_a + q̂_b)/2; adding them,
// q̂_b − q̂_a = ΔL · ½ q_i ⊗ κ̄ — the implicit midpoint rule of a linear ODE whose matrix is skew
// (right multiplication by a pure quaternion), a Cayley transform: |q̂_b| = |q̂_a| exactly. So the
// four kinematic rows per element end carry no norm equation and need none: the supported node's
// unit quaternion fixes the norm of every node reachable from it. Rotations are evaluated as
// C(q)/|q|² (homogeneous), so the element's |q_i| = cos(δ/4) < 1 (δ its relative rotation) is
// harmless.
//
// Count on a tree with one support (every node but the support is free, E elements, E + 1 nodes):
// 13E + 7E + 6 unknowns = 14E + 6(E + 1) equations. Each further support closes a path whose
// four closure rows hold only three independent conditions (the norm arrives preserved) and whose
// given quaternion a Newton iterate far from the continuation path could reach as −q_given (the
// double cover): its q̂ is ρ q_given with the scalar ρ an unknown (ρ = ±1 at a solution, 1 along a
// continuation), which restores the count.
// A closed loop of members would need the same for its closing node; it is refused with an
// InputError (no shipped case has one), as is a part without support.
#pragma once

#include <vector>

#include "core/model.hpp"
#include "core/nonlinear_system.hpp"
#include "formulations/mixed/mixed_layout.hpp"

namespace rotbeam::form {

struct MixedQuaternionLayout {
    static constexpr int kElementUnknowns = 13;
    static constexpr int kElementRows = 14;
    static constexpr int kNodeRows = 6;

    MixedLayout base;
    std::vector<int> node_columns;  // first unknown of each node
    std::vector<int> node_sizes;    // 7 free, 6 the first support, 7 every further support (ρ)
    int first_support = -1;
    int node_unknowns = 0;  // Σ node_sizes
    // A free tree (no support, dynamics only): nothing fixes the common norm of the q̂, so one
    // more row, ½(|q̂_0|² − 1) = 0 at node 0, is appended after all others (norm_row()).
    bool free_norm = false;

    int size() const { return node_unknowns + kElementUnknowns * base.element_count(); }
    int node_row(int node) const { return kNodeRows * node; }
    int node_column(int node) const { return node_columns[static_cast<std::size_t>(node)]; }
    int element_row(int e) const {
        return kNodeRows * static_cast<int>(base.nodes.size()) + kElementRows * e;
    }
    int element_column(int e) const { return node_unknowns + kElementUnknowns * e; }
    bool supported(int node) const { return base.supported(node); }
    // A support whose given quaternion is scaled by the unknown ρ (column node_column + 6).
    bool has_scale(int node) const { return supported(node) && node != first_support; }
};

// Builds the numbering; throws InputError when the structure is not a tree held by its supports
// (closed loop, unsupported part) — then the four-component system is not square. With
// `allow_free` (the dynamics, where momentum fixes the rigid motion) a single tree without any
// support is accepted with the norm row (free_norm); statics keep refusing it (rigid motions).
MixedQuaternionLayout build_mixed_quaternion_layout(const Model& model, bool allow_free = false);

// Residual scales by row (force, force × length; kinematic rows length, 1) and increment scales by
// column (û length, q̂ and ρ 1, reactions and F force, M force × length).
void mixed_quaternion_scales(const MixedQuaternionLayout& layout, VecX& residual_scale,
                             VecX& increment_scale);

// The fixed sparsity pattern of the Jacobian (all structural entries, values zero).
SparseMatrix mixed_quaternion_pattern(const MixedQuaternionLayout& layout);

}  // namespace rotbeam::form
