// The expected time of the studies' parts, before they have run (docs/distributed-runs.md, "Cost
// model"): what a shard deals out longest first and what the progress line weighs its items by.
#pragma once

#include <string>

#include "studies/study_runs.hpp"

namespace rotbeam::cli {

// A study made whole (one unit of a shard, one item of the suite's studies), in seconds of one
// core, from the table measured on the 2-core machine.
double whole_study_seconds(const std::string& name, bool quick);

// One run of a split study: the cost model of its case run (with its estimate's companions when
// it has one), or the measured time of a continuum reference.
double study_run_seconds(const StudyRun& run);

// A split study's combine step (reading its runs' results, writing its files and figures).
double combine_step_seconds();

}  // namespace rotbeam::cli
