// The dynamic part of the effectivity study (study_effectivity.cpp): the manufactured motion's
// sequences (effectivity_motion.hpp) as runs of the study's plan, and their rows, counts and
// tables, in the report's effectivity section after the static and modal ones.
#pragma once

#include <nlohmann/json.hpp>
#include <sstream>
#include <vector>

#include "study_runs.hpp"

namespace rotbeam::cli {

// Adds every level of every dynamic sequence (motion_sequences(quick)) to the plan.
void plan_motion_runs(std::vector<StudyRun>& plan, bool quick);

// Measures the dynamic sequences from their runs' results, writes their section to `md` and
// returns the study JSON's `dynamic`: {sequences, asymptotic_rows, band_violations,
// estimator_failures, unexplained_failures, other_state_failures}.
nlohmann::json dynamic_effectivity(bool quick, const StudyResults& results, std::ostringstream& md);

}  // namespace rotbeam::cli
