// The static studies (`rotbeam study NAME`, and the suite's report). Each study is one
// function: it runs through run_case() (the code path of `rotbeam run`), writes
// DIR/study-<name>.json (the data), DIR/study-<name>.md (tables, figures, what they show) and the
// figures (reports/study_<name>.gp), and returns its JSON.
//
// Extension point: a further study is a function of this signature, added to the registry
// (cases/runner/study_commands.hpp, static_studies()) — the command and the report pick it up
// from there. The speed-accuracy study is benches/study_speed.hpp.
#pragma once

#include <nlohmann/json.hpp>

#include "study_common.hpp"
#include "study_runs.hpp"

namespace rotbeam::cli {

nlohmann::json study_convergence(const StudyOptions& o);  // study_convergence.cpp
nlohmann::json study_singularity(const StudyOptions& o);  // study_singularity.cpp
// The same studies as independent runs plus the combine step (study_runs.hpp).
SplitStudy convergence_study();                                    // study_convergence.cpp
SplitStudy singularity_study();                                    // study_singularity.cpp
SplitStudy extremes_study();                                       // study_extremes_newton.cpp
SplitStudy effectivity_study();                                    // study_effectivity.cpp
nlohmann::json study_effectivity(const StudyOptions& o);           // study_effectivity.cpp
nlohmann::json study_extremes(const StudyOptions& o);              // study_extremes.cpp
nlohmann::json study_manufactured_time(const StudyOptions& o);     // study_manufactured_time.cpp
nlohmann::json study_free_vibration_time(const StudyOptions& o);   // study_free_vibration_time.cpp
nlohmann::json study_joined_beam_modal(const StudyOptions& o);     // study_joined_beam_modal.cpp
nlohmann::json study_joined_beam_dynamics(const StudyOptions& o);  // study_joined_beam_dynamics.cpp
nlohmann::json study_joined_beam_agreement(
    const StudyOptions& o);  // study_joined_beam_agreement.cpp

}  // namespace rotbeam::cli
