// The discrete layout of the mixed formulation (seed 002 §III): nodes, elements, their frames and
// loads, and the numbering of unknowns and equations (MixedNumbering, which depends on the
// parameterization only through its parameter count and redundancy).
//
// Nodes: every model point is a node (index = point index); each member of N elements adds N − 1
// interior nodes. A free node carries its displacement û (3) and rotation
// parameters ĉ (3, or 4: MixedNumbering), a supported node (clamped/prescribed) the reaction force
// and moment it receives (inertial components) — û, ĉ are then given. Every node carries 6
// equilibrium equations, the sum of the f_u, f_ψ halves of the elements meeting there minus the
// applied load and reaction: Eqs. (31)–(32), (35)–(36), (39)–(40) of seed 002. Keeping û, ĉ as
// unknowns at interior nodes is Eqs. (41)–(42) before eliminating them (the added equations are
// linear in û, ĉ, so Newton's iterates are unchanged), and it lets any number of members meet at a
// connection point.
//
// Elements: unknowns u_i (inertial), c_i (rotation parameters of the rotation relative to the
// reference, seed 002's c_a, Eq. 28), F_i, M_i (deformed-frame B components), and the equations
// f_F^−, f_M^− (Eqs. 33–34 / 41–42 with the start node's û, ĉ), f_F^+, f_M^+ (Eqs. 37–38).
//
// Initial curvature and twist enter via per-element frames C^ab (docs/benchmarks.md, Errata: Eqs.
// 45–48 carry no k): each element is the straight chord between its end nodes on the exact
// reference line, of length ΔL_i = |Δr|, with e1 along the chord and e2 the reference frame's e2 at
// mid-length projected normal to it. Inside an element the reference triad is constant; the
// relative rotation carries the jump between neighbouring element frames. The reference
// configuration is then an exact solution (f_F = 0 at u = 0, c = 0, F = M = 0), and the polygonal
// geometry differs from the curve by O(ΔL²), the order of the element itself.
#pragma once

#include <vector>

#include "core/model.hpp"
#include "core/nonlinear_system.hpp"
#include "core/types.hpp"

namespace rotbeam::form {

// A section property at arc-length fraction s/L of a member, `get(section)` linear between
// stations (constant with one station): the stiffness (or compliance) and mass of the layout, the
// damping of the dynamics.
template <class Get>
auto section_property_at(const Member& member, double fraction, Get get) {
    const std::vector<SectionStation>& st = member.sections;
    if (st.size() == 1 || fraction <= st.front().s_fraction) return get(st.front().section);
    for (std::size_t k = 1; k < st.size(); ++k) {
        if (fraction <= st[k].s_fraction) {
            const double w =
                (fraction - st[k - 1].s_fraction) / (st[k].s_fraction - st[k - 1].s_fraction);
            return decltype(get(st[k].section))((1.0 - w) * get(st[k - 1].section) +
                                                w * get(st[k].section));
        }
    }
    return get(st.back().section);
}

struct MixedNode {
    int point = -1;       // model point index, −1 for an interior node
    int constraint = -1;  // index into Model::constraints, −1 when free
    Vec3 reference = Vec3::Zero();
};

struct MixedElement {
    int member = -1;
    int start_node = -1;
    int end_node = -1;
    double s_mid = 0.0;           // arc length of the mid-point along the member
    double length = 0.0;          // ΔL_i = |Δr| (the straight element's length)
    Vec3 chord = Vec3::Zero();    // Δr = x^r(end) − x^r(start)
    Mat3 Cab = Mat3::Identity();  // the element's reference frame (material → inertial)
    Mat6 S = Mat6::Zero();        // compliance at mid-length, [γ; κ] = S [F; M]
    // Distributed loads per unit reference length at load factor 1.
    Vec3 f_dead = Vec3::Zero();
    Vec3 m_dead = Vec3::Zero();
    Vec3 f_follower = Vec3::Zero();  // in the reference frame orientation: f = R_rel f0
    Vec3 m_follower = Vec3::Zero();

    // Adds `factor` times a distributed load of the element's member to its dead or follower
    // part.
    void add_load(const DistributedLoad& load, double factor) {
        if (load.frame == LoadFrame::dead) {
            f_dead += factor * load.force;
            m_dead += factor * load.moment;
        } else {
            f_follower += factor * load.force;
            m_follower += factor * load.moment;
        }
    }
};

struct MixedLayout {
    std::vector<MixedNode> nodes;
    std::vector<MixedElement> elements;
    double length_scale = 1.0;
    double force_scale = 1.0;
    bool has_follower = false;
    bool rotating = false;  // a steady rotating frame (core/model.hpp): widens the pattern

    int element_count() const { return static_cast<int>(elements.size()); }
    bool supported(int node) const { return nodes[static_cast<std::size_t>(node)].constraint >= 0; }
};

// Builds the layout; throws InputError for what the mixed formulation cannot represent.
MixedLayout build_mixed_layout(const Model& model);

// The numbering of unknowns (columns) and equations (rows) for K rotation parameters, of which
// `constraint_rows` are redundant (param::ParameterConstraint: 0 for three parameters, 1 for the
// quaternion), in statics or dynamics. Rows and columns have separate offsets because with a
// redundant parameter their counts differ per element and per node:
//
//   Unknowns (columns)                          Equations (rows)
//   element i: u (3), c (K), F (3), M (3)       f_F^−, f_M^− (K), f_F^+, f_M^+ (K)     (Eqs. 47–48)
//     dynamics: + P (3), H (3)                    dynamics: + f_P, f_H                  (Eqs.
//     49–50)
//   free node: û (3), ĉ (K)                     equilibrium (Eqs. 31–32, 35–36, 39–40) = 6
//   supported node: reaction force, moment      equilibrium = 6
//     (+ ρ at every support after the first when constraint_rows = 1, see below)
//
// Three parameters: 12 (18) per element and 6 per node on both sides, square for any structure.
// The quaternion (docs/mixed-formulation.md): Eq. 48 in four components is the implicit midpoint
// rule of q′ = ½ q ⊗ κ̄, a Cayley transform, so |q̂_b| = |q̂_a| exactly and the kinematic rows
// carry the norm from the support to every node without a norm equation. On a tree with one
// support (E elements, E + 1 nodes) 13E + 7E + 6 unknowns = 14E + 6(E + 1) rows. Each further
// support closes a path whose four closure rows hold only three independent conditions and whose
// given quaternion an iterate could reach as −q_given (the double cover): its q̂ is ρ q_given with
// the scalar ρ an unknown (ρ = ±1 at a solution, 1 along a continuation). A closed loop of members
// would need the same at its closing node and is refused with an InputError, as is a part without
// support — except a free tree in dynamics (`allow_free`, momentum fixes the rigid motion), which
// gets the parameterization's constraint row ½(|q̂_0|² − 1) = 0 at node 0 as its last row.
struct MixedNumbering {
    int rotation_size = 3;          // K
    int constraint_rows = 0;        // redundant parameters per rotation
    bool dynamic = false;           // element momenta P, H and rows f_P, f_H
    std::vector<int> node_columns;  // first unknown of each node
    std::vector<int> node_sizes;    // 3 + K free, 6 supported (+ ρ)
    std::vector<bool> node_supported;
    int first_support = -1;
    int node_unknowns = 0;  // Σ node_sizes
    int element_count = 0;
    bool free_norm = false;  // a free tree: the constraint row closes the count (last row)

    int node_count() const { return static_cast<int>(node_columns.size()); }
    int element_unknowns() const { return 9 + rotation_size + (dynamic ? 6 : 0); }
    int element_rows() const { return 6 + 2 * rotation_size + (dynamic ? 6 : 0); }
    int size() const { return node_unknowns + element_unknowns() * element_count; }
    int node_row(int node) const { return 6 * node; }
    int node_column(int node) const { return node_columns[static_cast<std::size_t>(node)]; }
    int element_row(int e) const { return 6 * node_count() + element_rows() * e; }
    int element_column(int e) const { return node_unknowns + element_unknowns() * e; }
    bool supported(int node) const { return node_supported[static_cast<std::size_t>(node)]; }
    // A support whose given rotation is scaled by the unknown ρ (column node_column + 6).
    bool has_scale(int node) const {
        return constraint_rows > 0 && supported(node) && node != first_support;
    }
    // Offsets inside an element's block of unknowns and of rows.
    int u() const { return 0; }
    int c() const { return 3; }
    int F() const { return 3 + rotation_size; }
    int M() const { return 6 + rotation_size; }
    int P() const { return 9 + rotation_size; }
    int H() const { return 12 + rotation_size; }
    int kinematic_rows() const { return 6 + 2 * rotation_size; }
    int fP() const { return kinematic_rows(); }
    int fH() const { return kinematic_rows() + 3; }
};

// Numbers the layout's unknowns; throws InputError (constraint_rows > 0) when the structure is not
// a tree held by its supports (or, with allow_free, a single free tree).
MixedNumbering number_mixed_unknowns(const MixedLayout& layout, int rotation_size,
                                     int constraint_rows, bool dynamic, bool allow_free = false);

// Residual scales by row (equilibrium: force, force × length; kinematic: length, 1) and increment
// scales by column (û: length, ĉ and ρ: 1, reactions and F: force, M: force × length) of the
// static numbering.
void mixed_scales(const MixedLayout& layout, const MixedNumbering& n, VecX& residual_scale,
                  VecX& increment_scale);

// The fixed sparsity pattern of the Jacobian (statics), or of ∂F/∂X and ∂F/∂Ẋ together
// (dynamics): all structural entries, values zero.
SparseMatrix mixed_pattern(const MixedLayout& layout, const MixedNumbering& n);

}  // namespace rotbeam::form
