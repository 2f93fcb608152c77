// The suite's case runs: which runs `rotbeam suite` makes (every catalog case matching --cases ×
// every parameterization × formulation, and the Table III variants of the modal cases), where
// each result goes, when a result on disk is still valid, and how one run is made. Shared by the
// suite, its shards and `rotbeam merge` (docs/distributed-runs.md).
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace rotbeam::cli {

struct PlannedRun {
    std::string case_name, case_path, rotation, formulation;
    std::string output{};                  // result file
    std::string key{};                     // hash of the inputs
    std::vector<std::string> overrides{};  // further --set overrides (a variant's settings)
    int elements_per_member = 0;           // 0: the case's own mesh
    // With the error estimate (docs/error-estimates.md; off: `suite --estimate off`, or the case's
    // analysis.estimate: false).
    bool estimate = true;
    // Made as `rotbeam run` makes it (a sweep's runs): to the case's analysis.accuracy when it
    // states one.
    bool as_run = false;
    double modelled_seconds = 0.0;  // expected run time by the cost model (run_cost.hpp)
    // Wall-clock limit of the run, seconds (0: none; `--time-limit`): not an input of its result,
    // so not in its key; a run it stopped (status time-limit) is made again on a rerun.
    double time_limit_seconds = 0.0;
};

// The whole file as text ("" when it cannot be read).
std::string read_text_file(const std::string& path);

// The run's input key: a hash of the case text, the run's settings and the rotbeam version.
std::string planned_run_key(const std::string& case_text, const PlannedRun& run);

// The runs of the suite over the catalog cases matching `glob`, results under out_dir/runs/, each
// estimated when `estimate` is set.
std::vector<PlannedRun> plan_runs(const std::string& glob, const std::string& out_dir, bool quick,
                                  bool estimate);

// The run's result file exists and carries the run's input key (same case text, settings and
// rotbeam version), and the run was not stopped by a time limit: resuming skips it. A file there
// that is damaged (runs/run_file.hpp) is refused: InputError naming the file and the key, and
// saying to delete it.
bool up_to_date(const PlannedRun& run);

// Makes the run (the code path of `rotbeam run`, its estimate included); a combination that does
// not exist for the case comes back as status "error" with the loader's or runner's message. The
// result carries the key.
nlohmann::json execute_planned_run(const PlannedRun& run);

// Makes every run not up to date (all with `force`) over `jobs` threads, with one progress line
// titled `what` on stderr (suite.cpp): the list of independent runs that the suite and a sweep
// hand to the distribution.
void run_planned_runs(const std::vector<PlannedRun>& runs, int jobs, bool force,
                      const std::string& what);

// published.md (the published numbers of the cases run) and rotation-study.json; returns the
// published checks (the rows `verify --json` writes) for the report's summary.
nlohmann::json write_suite_summaries(const std::string& out, const std::vector<PlannedRun>& runs);
// The report (index.md, index.html, figures) from the runs' files, the studies' pages and the
// published checks.
void write_suite_report(const std::string& out, const std::vector<PlannedRun>& runs,
                        const nlohmann::json& published_checks);

}  // namespace rotbeam::cli
