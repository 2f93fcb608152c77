// The registry of the studies behind `rotbeam study NAME` and the suite: which name means which
// study (studies/studies.hpp, benches/study_speed.hpp), in report order, and how the suite runs
// them.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "studies/study_common.hpp"
#include "studies/study_runs.hpp"

namespace rotbeam::cli {

using StudyFunction = nlohmann::json (*)(const StudyOptions&);
// The studies in report order (study_commands.cpp).
const std::vector<std::pair<std::string, StudyFunction>>& static_studies();

// The studies split into independent runs and a combine step (studies/study_runs.hpp), by name.
const std::vector<std::pair<std::string, SplitStudy>>& split_studies();

// The suite's studies: the accuracy studies in parallel over `jobs` threads (the split ones as
// their runs, pooled with the others, then combined), then the speed-accuracy study alone (its
// timings must not share the cores; its untimed references on `jobs` threads before them);
// joined-beam-dynamics only by name or `all`
// (study_commands.cpp says why).
void run_suite_studies(const StudyOptions& o, int jobs);

// Runs the named study (InputError for an unknown name) or, for "all", every study, with a
// progress line on stderr (runs/progress.hpp).
void run_named_study(const std::string& name, const StudyOptions& o);
// InputError unless `name` is a study of the registry or "all".
void check_study_name(const std::string& name);
// Every name `rotbeam study` takes: "rotations, convergence, …, all" (the registry's in report
// order between them), for the top-level help and the unknown-study message.
std::string study_name_list();
// InputError (one line naming the option and the study) unless the option of `rotbeam study`
// (without its dashes) applies to the study `name` ("rotations", a study of the registry or
// "all"): --json and --samples are the rotation study's, --out and --quick the registry's,
// --reduced-follower joined-beam-dynamics's; the others apply everywhere or are checked where
// they are read (--shard, --jobs, --timings: distributed.hpp).
void check_study_option(const std::string& name, const std::string& option);
// Runs one study of the registry whole into o.out_dir and prints its time.
void run_study_whole(const std::string& name, const StudyOptions& o);

// Studies whose timings are their results (speed-accuracy): run alone, after the others.
bool timed_study(const std::string& name);
// Studies the suite leaves out (joined-beam-dynamics, -agreement: tens of CPU-minutes); run by
// name or `all`.
bool standalone_study(const std::string& name);

// The cache of references a study reads and writes under its output folder, shared with the other
// studies of the same group ("joined-beam" for joined-beam-dynamics and -agreement: their
// same-mesh references, joined-beam-references/); "" when it has none. Studies of one group run
// in one folder, one after the other, so that the references are computed once.
std::string reference_group(const std::string& name);

// The names of the studies, in report order (the report reads DIR/study-NAME.md of each).
std::vector<std::string> study_names();

}  // namespace rotbeam::cli
