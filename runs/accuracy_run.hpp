// A run under accuracy control (docs/accuracy-control.md): estimates/accuracy_control.hpp with
// the program's run_case and add_run_estimate, the code path of `rotbeam run`.
#pragma once

#include <nlohmann/json.hpp>

#include "runs/run_case.hpp"

namespace rotbeam {

// Refines request.model until its estimates meet request.model.analysis.accuracy / 2 (> 0), or
// says why not. The budget's time is request.time_limit_seconds when set, else the default of
// estimates::AccuracyBudget: a limit on the whole control, which every run (companions included)
// gets as the time the budget has left.
nlohmann::json run_to_accuracy(const RunRequest& request);

}  // namespace rotbeam
