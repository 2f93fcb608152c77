// One element of the displacement formulation's mesh (mesh.hpp) at given points: its shape
// functions and their derivatives on `basis` (the element's nodes in ξ ∈ [−1, 1]), and at every
// point of `rule` (in ξ) the data that does not change during a solve: arc length, weight × ds/dξ,
// the reference frame R^r(s) and the section matrices. The element's nodes and the reference
// tangent x^r′ (set_reference_tangents, once the nodes are set) are the caller's to set.
#pragma once

#include "core/geometry.hpp"
#include "core/lagrange.hpp"
#include "core/model.hpp"
#include "core/quadrature.hpp"
#include "formulations/displacement/mesh.hpp"

namespace rotbeam::form {

// Element [s0, s1] of `member`, whose reference geometry is g.
MeshElement make_element(const Model& model, int member, const ReferenceGeometry& g, double s0,
                         double s1, const LagrangeBasis& basis, const QuadratureRule& rule);

// x^r′ = Σ N_j′ x^r_j at every point of e from the reference positions of its nodes in `mesh`.
void set_reference_tangents(const Mesh& mesh, MeshElement& e);

}  // namespace rotbeam::form
