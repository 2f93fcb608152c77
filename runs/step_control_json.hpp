// What a dynamic run's step control did, in its result (docs/displacement-dynamics.md, "Time
// step control"): nothing when the run took its fixed steps uncut, so such results are unchanged.
#pragma once

#include <nlohmann/json.hpp>

#include "core/step_size_control.hpp"

namespace rotbeam {

// Adds to `integrator` (the result's integrator or dynamics object): `time_tolerance`,
// `rejected_steps`, `smallest_step`, `largest_step` for adaptive steps (tolerance > 0), and
// `step_cuts`, `first_cut_time` when a step was cut after a Newton failure.
inline void add_step_control_json(double tolerance, const StepControlRecord& r,
                                  nlohmann::json& integrator) {
    if (tolerance > 0.0) {
        integrator["time_tolerance"] = tolerance;
        integrator["rejected_steps"] = r.rejected_steps;
        integrator["smallest_step"] = r.smallest_step;
        integrator["largest_step"] = r.largest_step;
    }
    if (r.step_cuts > 0) {
        integrator["step_cuts"] = r.step_cuts;
        integrator["first_cut_time"] = r.first_cut_time;
    }
}

}  // namespace rotbeam
