// `rotbeam suite`: the main job. Runs every catalog case (static, modal and dynamic; matching
// --cases) with every parameterization × formulation, in parallel over --jobs worker threads,
// writes one result file per run with its error estimate unless --estimate off (skipped on a rerun
// when its inputs and the rotbeam version are unchanged), the rotation study, and a report
// (index.md + index.html) with the runs table and the plots made by gnuplot scripts in reports/.
// With --shard I/N it makes only one shard of the runs and studies, for `rotbeam merge`; under
// mpirun the ranks share them (distributed.hpp).
#include <fnmatch.h>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <thread>

#include "arguments.hpp"
#include "commands.hpp"
#include "core/atomic_file.hpp"
#include "core/errors.hpp"
#include "distribution/distributed.hpp"
#include "distribution/study_registry.hpp"
#include "distribution/suite_plan.hpp"

namespace rotbeam::cli {

namespace fs = std::filesystem;

int command_suite(const Args& args) {
    const CommandSpec spec{
        "suite",
        "",
        0,
        0,
        "Run the benchmark suite: every catalog case (static, modal, dynamic) with every "
        "parameterization and formulation, the rotation study, and the report (DIR/index.md, "
        "DIR/index.html, plots). "
        "Finished runs whose inputs are unchanged are skipped on a rerun.",
        {{"out", "DIR", "output folder (default: out)"},
         {"jobs", "N", "worker threads, 1 to 256 (default: all cores)"},
         {"cases", "GLOB", "only catalog cases matching GLOB (default: *)"},
         {"force", "", "rerun everything"},
         {"quick", "", "the roll-up and the 45-degree bend only (CI smoke test)"},
         {"studies", "", "run the static studies even with --cases (default: only without)"},
         {"no-studies", "", "skip the static studies (docs/studies.md)"},
         {"estimate", "on|off",
          "every case run with its error estimate, companion runs that cost 2-8x the run; off "
          "for timing (default: on, or the case's analysis.estimate; docs/error-estimates.md)"},
         kTimeLimitOption,
         {"shard", "I/N",
          "make only the I-th of N shards of the runs into --out, for `rotbeam merge` "
          "(default: every run, no shard; docs/distributed-runs.md)"},
         {"timings", "DIR",
          "with --shard or under mpirun: balance by the run times in DIR, an earlier output or "
          "shard folder, the same for every shard (default: the cost model; under mpirun: --out)",
          true}}};
    const ParsedArguments a = parse_arguments(spec, args);
    if (a.help) {
        std::cout << help_text(spec);
        return 0;
    }
    const std::string out = a.value("out").value_or("out");
    const int jobs = a.positive_int("suite", "jobs", kMaxJobs)
                         .value_or(std::max(1u, std::thread::hardware_concurrency()));
    const double time_limit = time_limit_option(a, "suite");
    const std::string glob = a.value("cases").value_or("*");
    const std::vector<std::string> catalog = catalog_cases();
    if (std::none_of(catalog.begin(), catalog.end(), [&](const std::string& name) {
            return fnmatch(glob.c_str(), name.c_str(), 0) == 0;
        })) {
        throw InputError("rotbeam suite: --cases: '" + glob +
                         "' matches no catalog case (see 'rotbeam list')");
    }
    // The static studies belong to the main job: on by default for the whole catalog, off
    // for a --cases selection unless --studies asks for them.
    const bool studies = !a.has("no-studies") && (a.has("studies") || !a.has("cases"));
    const std::string estimate = a.value("estimate").value_or("on");
    if (estimate != "on" && estimate != "off") {
        throw InputError("rotbeam suite: --estimate: expected on or off, got '" + estimate + "'");
    }
    Job job;
    job.cases = glob;
    job.quick = a.has("quick");
    job.studies = studies;
    job.estimate = estimate == "on";
    if (const auto code = run_distributed(
            job, a.value("shard"),
            ShardSettings{{}, out, jobs, a.has("force"), a.values("timings"), time_limit},
            a.has("jobs"))) {
        return *code;
    }
    if (a.has("timings"))
        throw InputError("rotbeam suite: --timings: only with --shard I/N or under mpirun");
    std::vector<PlannedRun> runs = plan_runs(glob, out, a.has("quick"), estimate == "on");
    for (PlannedRun& run : runs) run.time_limit_seconds = time_limit;
    std::cout << "rotbeam suite: " << runs.size() << " runs on " << jobs << " threads → " << out
              << "\n";
    // A suite killed with SIGKILL in the middle of a write left a temporary (never a partial
    // result file): clear it so the resumed folder is the one an uninterrupted suite writes.
    if (fs::exists(out)) remove_stale_temporaries(out);
    run_planned_runs(runs, jobs, a.has("force"), "rotbeam suite");
    const nlohmann::json published_checks = write_suite_summaries(out, runs);
    if (studies) run_suite_studies(StudyOptions{out, a.has("quick"), false}, jobs);
    write_suite_report(out, runs, published_checks);
    return 0;
}

}  // namespace rotbeam::cli
