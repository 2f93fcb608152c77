// A static run's load steps as CSV (next to its result JSON, like a dynamic run's history,
// history_csv.hpp): one row per load step; per named point the displacement, the principal
// rotation vector and the unwrapped rotation angle, then BeamDyn's frame (`run --frame beamdyn`,
// beamdyn_frame.hpp) and the estimate columns (estimate_columns.hpp) when the run was estimated.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace rotbeam {

// True when the result is a static analysis's load steps (steps carry `load_factor`; a modal
// result's static state is not one).
bool has_load_steps(const nlohmann::json& result);

// Header line `load_factor,<point>_ux,…,<point>_angle[,estimate columns]` and one line per step,
// full precision.
std::string steps_csv(const nlohmann::json& result);

}  // namespace rotbeam
