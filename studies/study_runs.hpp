// A study as a list of independent runs plus a step that combines their results. plan() says what
// to run and where each result goes (a key); every run depends only on its own description, so
// the runs can be made in any order, over threads, or handed to other processes or machines;
// combine() turns the results into the study's outputs (DIR/study-NAME.json, .md, data and
// figures) and never runs a solve itself. The result of a study depends only on the results of
// its runs, so it is the same however they were distributed.
#pragma once

#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "study_common.hpp"

namespace rotbeam::cli {

// One independent run of a study.
struct StudyRun {
    enum class Kind {
        case_run,             // run_spec(spec): the code path of `rotbeam run`
        continuum_reference,  // continuum_reference(spec.case_name, spec.overrides)
        estimated_case_run,   // run_spec(spec, true): with its error estimate (add_run_estimate)
    };
    std::string key;  // where the result goes: unique within the study's plan
    Kind kind = Kind::case_run;
    RunSpec spec;
};

// The results of a plan's runs by key.
using StudyResults = std::map<std::string, nlohmann::json>;

// A key that names a case run by its description (case, combination, elements, overrides), for
// studies whose parts look their runs up by what was run; the same spec gives the same key.
std::string spec_key(const RunSpec& spec);

// Adds a case run under spec_key(spec) unless the plan has it already (two parts of a study may
// ask for the same run; it is made once).
void plan_case_run(std::vector<StudyRun>& plan, const RunSpec& spec);

// The result of the case run planned for `spec` (plan_case_run).
const nlohmann::json& result_for(const StudyResults& results, const RunSpec& spec);

// One run's result (the JSON of run_spec or of continuum_reference).
nlohmann::json execute_run(const StudyRun& run);

// Every run of the plan over `jobs` threads (runs/parallel.hpp).
StudyResults execute_runs(const std::vector<StudyRun>& plan, int jobs);

// The results of a plan's runs, made elsewhere (results[i] of plan[i]), by key. A key used twice is
// API misuse (ROTBEAM_VERIFY).
StudyResults results_by_key(const std::vector<StudyRun>& plan, std::vector<nlohmann::json> results);

// The result stored under `key`; API misuse (ROTBEAM_VERIFY) when the plan made no such run.
const nlohmann::json& result_of(const StudyResults& results, const std::string& key);

struct SplitStudy {
    std::vector<StudyRun> (*plan)(const StudyOptions& o);
    nlohmann::json (*combine)(const StudyOptions& o, const StudyResults& results);
};

// plan, execute every run over `jobs` threads, combine: the whole study in this process.
nlohmann::json run_split_study(const SplitStudy& study, const StudyOptions& o, int jobs = 1);

}  // namespace rotbeam::cli
