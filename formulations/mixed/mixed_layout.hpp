// The discrete layout of the mixed formulation (seed 002 §III): nodes, elements, their frames and
// loads, and the numbering of unknowns and equations. Independent of the parameterization.
//
// Nodes: every model point is a node (index = point index); each member of N elements adds N − 1
// interior nodes. Every node carries 6 unknowns: a free node its displacement û (3) and rotation
// parameters ĉ (3), a supported node (clamped/prescribed) the reaction force and moment it receives
// (inertial components) — û, ĉ are then given. Every node carries 6 equilibrium equations, the sum
// of the f_u, f_ψ halves of the elements meeting there minus the applied load and reaction: Eqs.
// (31)–(32), (35)–(36), (39)–(40) of seed 002. Keeping û, ĉ as unknowns at interior nodes is Eqs.
// (41)–(42) before eliminating them (the added equations are linear in û, ĉ, so Newton's iterates
// are unchanged), and it lets any number of members meet at a connection point.
//
// Elements: 12 unknowns u_i (inertial), c_i (rotation parameters of the rotation relative to the
// reference, seed 002's c_a, Eq. 28), F_i, M_i (deformed-frame B components), and 12 equations:
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
};

struct MixedLayout {
    std::vector<MixedNode> nodes;
    std::vector<MixedElement> elements;
    double length_scale = 1.0;
    double force_scale = 1.0;
    bool has_follower = false;

    int size() const { return 6 * static_cast<int>(nodes.size()) + 12 * element_count(); }
    int element_count() const { return static_cast<int>(elements.size()); }
    int node_offset(int node) const { return 6 * node; }
    int element_offset(int e) const { return 6 * static_cast<int>(nodes.size()) + 12 * e; }
    bool supported(int node) const { return nodes[static_cast<std::size_t>(node)].constraint >= 0; }
};

// Builds the layout; throws InputError for what the mixed statics cannot represent.
MixedLayout build_mixed_layout(const Model& model);

// Residual scales (equilibrium rows: force, force × length; kinematic rows: length, 1) and
// increment scales (û: length, ĉ: 1, reactions and F: force, M: force × length).
void mixed_scales(const MixedLayout& layout, VecX& residual_scale, VecX& increment_scale);

// The fixed sparsity pattern of the Jacobian (all structural entries, values zero).
SparseMatrix mixed_pattern(const MixedLayout& layout);

}  // namespace rotbeam::form
