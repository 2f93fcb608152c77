// The static studies (`rotbeam study NAME`, and the suite's report). Each study is one
// function: it runs through run_case() (the code path of `rotbeam run`), writes
// DIR/study-<name>.json (the data), DIR/study-<name>.md (tables, figures, what they show) and the
// figures (reports/study_<name>.gp), and returns its JSON.
//
// Extension point: the dynamic and modal studies (the joined-beam frequencies, the manufactured
// solutions in time, Δt / IDA-tolerance vs accuracy) are further functions of this signature,
// added to static_studies() — the command and the report pick them up from there.
#pragma once

#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "study_common.hpp"

namespace rotbeam::cli {

nlohmann::json study_convergence(const StudyOptions& o);     // study_convergence.cpp
nlohmann::json study_singularity(const StudyOptions& o);     // study_singularity.cpp
nlohmann::json study_extremes(const StudyOptions& o);        // study_extremes.cpp
nlohmann::json study_speed_accuracy(const StudyOptions& o);  // study_speed.cpp
nlohmann::json study_manufactured_time(const StudyOptions& o);  // study_manufactured_time.cpp
nlohmann::json study_joined_beam_modal(const StudyOptions& o);     // study_joined_beam_modal.cpp
nlohmann::json study_joined_beam_dynamics(const StudyOptions& o);  // study_joined_beam_dynamics.cpp
nlohmann::json study_joined_beam_agreement(const StudyOptions& o);  // study_joined_beam_agreement.cpp
// The time "model only what the scene requires" saves against solver.assemble_all_terms: a
// section of the speed study (study_assembly.cpp).
nlohmann::json assembly_savings(const StudyOptions& o, std::ostringstream& md);

using StudyFunction = nlohmann::json (*)(const StudyOptions&);
// The studies in report order (study_commands.cpp).
const std::vector<std::pair<std::string, StudyFunction>>& static_studies();

// The suite's studies: the accuracy studies in parallel over `jobs` threads, then the
// speed-accuracy study alone (its timings must not share the cores); joined-beam-dynamics only by
// name or `all` (study_commands.cpp says why).
void run_suite_studies(const StudyOptions& o, int jobs);

// Runs the named study (InputError for an unknown name) or, for "all", every study.
void run_named_study(const std::string& name, const StudyOptions& o);

}  // namespace rotbeam::cli
