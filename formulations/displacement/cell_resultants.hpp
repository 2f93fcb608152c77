// The displacement formulation's section resultants where the ParaView output (runs/vtk_output.hpp)
// draws its line cells: midway (in the element coordinate ξ) between neighbouring nodes of every
// element, one per pair, in the order of the elements and their nodes, which is the arc-length
// order of StaticState::node_frames. At each point the state is interpolated from the nodal
// field as the residual interpolates it at a quadrature point (displacement_statics_assembly.hpp)
// and the resultant is the elastic one, F^E1 = C [ε; κ] (calculate_elastic_forces.hpp): the force
// and moment the part of the member beyond the point exerts on the part before it, in inertial
// components, and in the deformed section's axes (Q = R R^r, Qᵀ F), as the mixed formulation's
// unknowns are written. A damped dynamic run's damping force is not in it.
#pragma once

#include <vector>

#include "core/model.hpp"
#include "core/nodal_field.hpp"
#include "core/static_state.hpp"

namespace rotbeam::form {

// `field`: the displacement formulation's state (DisplacementStatics::nodal_field) on the mesh
// of `model`. Empty when the field is not one of that mesh (another element count or order, an
// unknown parameterization).
std::vector<SectionResultants> displacement_cell_resultants(const Model& model,
                                                            const NodalField& field);

}  // namespace rotbeam::form
