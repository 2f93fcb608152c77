// A sweep (docs/sweeps.md) as the suite's runs: its planned runs, which the suite's distribution
// makes (--jobs threads, shards, MPI ranks), and the sweep table over their results.
#pragma once

#include <string>
#include <vector>

#include "distribution/suite_plan.hpp"
#include "distribution/sweep_file.hpp"

namespace rotbeam::cli {

// The sweep's runs as the suite plans its own: results under out_dir/runs/, named
// NAME-NNNN_CASE_ROTATION_FORMULATION.json (NNNN: the run's place in the sweep, from 0001).
std::vector<PlannedRun> plan_sweep_runs(const Sweep& sweep, const std::string& out_dir);

// The key of the sweep file's text (runs/shards.hpp, stable_hash) that a sweep job records, so
// that merge can refuse a sweep file changed since the shards were made.
std::string sweep_file_key(const std::string& path);

// The sweep table from the runs' result files (sweep_table.cpp): DIR/sweep.csv, every step of
// every run; DIR/index.md and DIR/index.html, the last step (or every step, output.steps: all).
void write_sweep_report(const std::string& out, const Sweep& sweep,
                        const std::vector<PlannedRun>& runs);

}  // namespace rotbeam::cli
