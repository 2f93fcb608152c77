// ParaView output of a run (`rotbeam run CASE --vtk DIR`): per load step (statics), output time
// (dynamics) or mode (modal analyses) one VTK XML UnstructuredGrid file, and a `.pvd` collection
// that ParaView opens as a time series (the load factor, the time, or the mode number 1, 2, …).
//
// Each file holds the deformed reference line (a line cell per pair of neighbouring nodes) and a
// ribbon along it (a quad per pair) spanned by the section's second director d2 = R R^r(s) e2, so
// that twist shows; its width is 1/20 of the longest member. Point data (every point, the
// ribbon's two edge points carry their node's values): displacement, rotation_vector (principal
// value of R = R^c R^rᵀ), director_1..3 (the section frame R R^r(s), d1 the reference tangent
// carried along), reference_position, arc_length, member; modes: mode_displacement,
// mode_rotation (normalized like the result's modes); a static step's error estimate,
// estimate_displacement and estimate_rotation with estimate_..._reliable (1 or 0) at the named
// points' nodes, −1 ("no estimate") at every other point. Cell data: member, and per line cell
// section_force, section_moment (inertial components) and section_force_material,
// section_moment_material (the deformed section's axes): the mixed formulation's unknowns (one
// per element), the displacement formulation's elastic resultant C [ε; κ] midway between the
// cell's nodes (formulations/displacement/cell_resultants.hpp). Field data: TimeValue, and the
// run's error estimate of the step where it has one (per named point
// estimate_<point>_displacement and _rotation, the estimated error; or a mode's
// estimate_frequency_hz), with estimate_..._reliable 1 or 0.
//
// With turning supports (a dynamic run with `rotating_frame`) the files show the inertial motion,
// as the result's `points` do: position c + Q(t)(x^r + u − c), rotation Q(t) R, directors and
// section_force, section_moment turned by Q(t); the motion relative to the turning frame (in its
// axes) is the point data relative_displacement and relative_rotation_vector, and Q(t) the field
// data frame_rotation_vector.
//
// The files are written by this small writer (ASCII, 17 significant digits: every double is
// written exactly) rather than by VTK's library, which the fully static program cannot link.
// Every file is written atomically (core/atomic_file.hpp).
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/model.hpp"
#include "frame_recorder.hpp"

namespace rotbeam {

// One file's text: the snapshot of result step (or mode) `index`.
std::string vtk_unstructured_grid(const Model& model, const nlohmann::json& result, size_t index,
                                  const FrameSnapshot& snapshot);

// Writes DIR/BASE_NNNN.vtu for every snapshot and DIR/BASE.pvd, BASE =
// <case>_<rotation>_<formulation> as for `run --out`. Returns the .pvd's path. Throws OutputError
// when a file cannot be written.
std::string write_vtk(const std::string& directory, const Model& model,
                      const nlohmann::json& result, const std::vector<FrameSnapshot>& snapshots);

}  // namespace rotbeam
