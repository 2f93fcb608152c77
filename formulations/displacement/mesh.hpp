// The displacement formulation's mesh: Legendre spectral finite elements (LSFE) of order p with
// nodes at the p+1 Gauss–Lobatto–Legendre points, several per member, members joined rigidly at
// shared named points (one node per point, shared by every member that ends there), and the
// quadrature-point data that does not change during a solve (shape functions, the reference
// tangent interpolated from the nodes — which lie on the exact reference line — the frame R^r
// from the exact line, material section matrices).
//
// Stiffness quadrature (Discretization::quadrature): `automatic` = p+1 Gauss points for p ≥ 3,
// p points (reduced) for p ≤ 2 (against shear locking); `full` = p+1 Gauss; `reduced` = p Gauss;
// `gll` = p+1 GLL points (nodal quadrature). quadrature_points > 0 overrides the point count.
// `trapezoidal` = BeamDyn's `quadrature = 2` (docs/beamdyn-import.md): the composite trapezoidal
// rule (core/quadrature.hpp) with breakpoints at the element's ends and at the member's section
// stations inside it, each interval divided into `refine` parts; the section properties at the
// division points are interpolated linearly as everywhere. Fewer points than p+1 in an element
// are refused. The same rule integrates the distributed loads and gravity.
//
// Supports are eliminated: a constrained node has no unknowns (dof = −1); its state is set from
// the load factor (clamped: u = 0, R = I; prescribed: u = λ d, R = exp(λ θ)).
#pragma once

#include <vector>

#include "core/model.hpp"
#include "core/types.hpp"

namespace rotbeam::form {

struct MeshNode {
    Vec3 x0 = Vec3::Zero();  // reference position
    int point = -1;          // the named point at this node, −1 for interior nodes
    int dof = -1;            // first of its 6 unknowns [u; δψ], −1 when constrained
};

struct QuadraturePoint {
    double weight = 0.0;           // Gauss weight × ds/dξ
    double s = 0.0;                // arc length along the member (load fields)
    Vec3 x0_prime = Vec3::Zero();  // x^r′ = Σ N_j′ x^r_j (interpolated from the nodes)
    Mat3 Rr = Mat3::Identity();    // R^r(s)
    Mat6 C_star = Mat6::Zero();    // material-axis stiffness
    double mass = 0.0;             // mass per unit length (gravity), 0 when no mass is given
    Vec3 eta_star = Vec3::Zero();  // centre of mass offset in material axes
    Mat6 M_star = Mat6::Zero();  // material-axis 6×6 mass [m I, m η̃ᵀ; m η̃, ρ], zero when none
    Mat6 D_star = Mat6::Zero();  // material-axis damping μ C* (seed 000 Eq. 10), zero when none
};

struct MeshElement {
    int member = -1;
    std::vector<int> nodes;      // p+1 global node indices
    std::vector<double> node_s;  // their arc lengths along the member
    std::vector<QuadraturePoint> qp;
    MatX N;   // N(j, q): shape function j at quadrature point q (a column per point)
    MatX dN;  // dN_j/ds (per unit reference arc length), same layout
};

struct PrescribedMotion {
    int node = -1;
    Vec3 displacement = Vec3::Zero();
    Vec3 rotation = Vec3::Zero();
};

struct Mesh {
    int order = 1;
    std::vector<MeshNode> nodes;
    std::vector<MeshElement> elements;
    std::vector<int> point_node;  // Model point index → node (−1 when no member uses it)
    std::vector<PrescribedMotion> prescribed;  // constrained nodes (clamped: zeros)
    int unknowns = 0;
    double max_member_length = 0.0;
};

// The number of stiffness quadrature points and whether they are GLL points (see above); not for
// `trapezoidal`, whose count depends on each element's stations.
int quadrature_point_count(const Discretization& d, bool& gll);

// Throws InputError for models it cannot discretize (no members, missing stiffness, order < 1,
// constraints or loads on points no member reaches).
Mesh build_mesh(const Model& model);

}  // namespace rotbeam::form
