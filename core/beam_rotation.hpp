// The rotation angle a result reports for a named point (docs/case-format.md §Results): the norm
// of the rotation vector continued along the beam from the root, so that it does not depend on the
// load or time path that led to the state. A roll-up closed into a full circle in one load step
// reports 2π at the tip, as it does after many.
//
// Continuation: starting from a supported point's principal rotation vector (0 for a clamp), each
// next station's rotation is given the rotation vector equivalent to it (ψ + 2πk n, either sense of
// the axis) that lies nearest the previous station's (so3::unwrap_rotation_vector). Through the
// members this walks outwards from the supported points (a joint passes its vector on to every
// member that leaves it). The stations are the formulation's nodes (and the mixed elements'
// rotations between them), a fraction of a turn apart on any mesh that resolves the rotation, so
// the nearest equivalent is the continuous one. About a fixed axis the result is the exact
// unwrapped angle (κL for a helix); about an axis that varies along the beam it is the angle of
// the continuous lift of R(s) sampled at the stations.
#pragma once

#include <vector>

#include "core/model.hpp"
#include "core/static_state.hpp"

namespace rotbeam {

// The continued rotation vector of every named point (indexed like model.points), from the
// stations of StaticProblem::rotation_stations(). Without a supported point (a free–free
// structure) the walk starts at the first member's start point, taken at its principal value; a
// point on no member has no beam to continue along and keeps the principal value of `states[i]`
// (its PointState). Throws SolverError when `stations` do not match the model's members (each
// member's first station is its start point, its last its end point).
std::vector<Vec3> rotation_vectors_along_beam(
    const Model& model, const std::vector<StaticProblem::RotationStation>& stations,
    const std::vector<PointState>& states);

// The largest continued rotation angle over all stations (0 without stations): what a run's
// message calls the largest rotation.
double largest_continued_angle(const Model& model,
                               const std::vector<StaticProblem::RotationStation>& stations);

}  // namespace rotbeam
