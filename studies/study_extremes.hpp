// The parts of `rotbeam study extremes`, each a list of runs and the step that writes its
// Markdown section and figure from their results: study_extremes.cpp (slenderness, tiny loads),
// study_extremes_newton.cpp (one big load step, refinement down to round-off).
#pragma once

#include <nlohmann/json.hpp>
#include <sstream>

#include "study_common.hpp"
#include "study_runs.hpp"

namespace rotbeam::cli {

// Each part: its runs (added to the study's plan), and its section from their results.
void plan_extremes_slenderness(const StudyOptions& o, std::vector<StudyRun>& plan);
void plan_extremes_tiny_loads(const StudyOptions& o, std::vector<StudyRun>& plan);
void plan_extremes_single_step(const StudyOptions& o, std::vector<StudyRun>& plan);
void plan_extremes_round_off(const StudyOptions& o, std::vector<StudyRun>& plan);
nlohmann::json extremes_slenderness(const StudyOptions& o, const StudyResults& results,
                                    std::ostringstream& md);
nlohmann::json extremes_tiny_loads(const StudyOptions& o, const StudyResults& results,
                                   std::ostringstream& md);
nlohmann::json extremes_single_step(const StudyOptions& o, const StudyResults& results,
                                    std::ostringstream& md);
nlohmann::json extremes_round_off(const StudyOptions& o, const StudyResults& results,
                                  std::ostringstream& md);

}  // namespace rotbeam::cli
