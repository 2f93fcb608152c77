// A dynamic run's CSV time history (docs/architecture.md, The program and its results), built from
// the result JSON's `steps`: one row per output time; per named point the displacement, the
// principal rotation vector and the unwrapped rotation angle; with turning supports the same
// relative to the turning frame (`<point>_rel_ux` … `_rel_angle`); then, when the steps carry them,
// each support's reaction (force and moment on the beam) and the kinetic and strain energy; with
// `run --frame beamdyn` the points and reactions in BeamDyn's frame (beamdyn_frame.hpp); last,
// when the run was estimated, the estimate columns in space, in time and combined
// (estimate_columns.hpp).
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace rotbeam {

// True when the result holds a time history (its steps carry `time`).
bool has_time_history(const nlohmann::json& result);

// Header line `time,<point>_ux,…,<point>_angle` and one line per step, full precision.
std::string history_csv(const nlohmann::json& result);

}  // namespace rotbeam
