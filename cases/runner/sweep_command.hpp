// `rotbeam sweep FILE` (docs/sweeps.md): a sweep file's runs through the suite's distribution —
// the list of independent runs over --jobs threads, or one shard of them for `rotbeam merge` —
// and the sweep table over their results.
#pragma once

#include <string>
#include <vector>

#include "commands.hpp"
#include "suite_plan.hpp"
#include "sweep_file.hpp"

namespace rotbeam::cli {

// The sweep's runs as the suite plans its own: results under out_dir/runs/, named
// NAME-NNNN_CASE_ROTATION_FORMULATION.json (NNNN: the run's place in the sweep, from 0001).
std::vector<PlannedRun> plan_sweep_runs(const Sweep& sweep, const std::string& out_dir);

// The sweep table from the runs' result files (sweep_table.cpp): DIR/sweep.csv, every step of
// every run; DIR/index.md and DIR/index.html, the last step (or every step, output.steps: all).
void write_sweep_report(const std::string& out, const Sweep& sweep,
                        const std::vector<PlannedRun>& runs);

int command_sweep(const Args& args);

}  // namespace rotbeam::cli
