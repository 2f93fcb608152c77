// `rotbeam sweep FILE` (docs/sweeps.md): a sweep file's runs through the suite's distribution —
// the list of independent runs over --jobs threads, or one shard of them for `rotbeam merge` —
// and the sweep table over their results.

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <thread>

#include "arguments.hpp"
#include "commands.hpp"
#include "core/atomic_file.hpp"
#include "core/errors.hpp"
#include "distribution/distributed.hpp"
#include "distribution/sweep_runs.hpp"
#include "runs/shards.hpp"

namespace rotbeam::cli {

namespace fs = std::filesystem;

namespace {

void list_runs(const Sweep& sweep, const std::vector<PlannedRun>& runs) {
    for (const PlannedRun& run : runs) {
        std::cout << fs::path(run.output).filename().string() << ": " << run.case_name << " "
                  << run.formulation << "/" << run.rotation;
        for (const std::string& o : run.overrides) std::cout << " " << o;
        std::cout << "\n";
    }
    std::cout << "rotbeam sweep: " << sweep.file << ": " << runs.size() << " runs\n";
}

}  // namespace

int command_sweep(const Args& args) {
    const CommandSpec spec{
        "sweep",
        "FILE",
        1,
        1,
        "Run a sweep file: its cases × combinations × values of case keys, each run as "
        "`rotbeam run CASE --set KEY=VALUE ...` makes it, through the suite's distribution, then "
        "the sweep table (DIR/sweep.csv, DIR/index.md, DIR/index.html; docs/sweeps.md). The "
        "whole file is validated before any run. Finished runs whose inputs are unchanged are "
        "skipped on a rerun.",
        {{"out", "DIR", "output folder (default: the file's output.folder, else sweep-NAME)"},
         {"jobs", "N", "worker threads, 1 to 256 (default: all cores)"},
         {"force", "", "rerun everything"},
         {"list", "", "print the runs the file expands to and stop"},
         kTimeLimitOption,
         {"shard", "I/N",
          "make only the I-th of N shards of the runs into --out, for `rotbeam merge` "
          "(default: every run, no shard; docs/distributed-runs.md)"},
         {"timings", "DIR",
          "with --shard: balance by the run times in DIR, an earlier output or shard folder, "
          "the same for every shard (default: the cost model)",
          true}}};
    const ParsedArguments a = parse_arguments(spec, args);
    if (a.help) {
        std::cout << help_text(spec);
        return 0;
    }
    const int jobs = a.positive_int("sweep", "jobs", kMaxJobs)
                         .value_or(std::max(1u, std::thread::hardware_concurrency()));
    const double time_limit = time_limit_option(a, "sweep");
    const Sweep sweep = read_sweep(a.positional[0]);
    const std::string out = a.value("out").value_or(sweep.folder);
    // --shard is checked before --list: a bad shard is refused whatever else is asked.
    if (const auto shard = a.value("shard")) parse_shard("sweep", *shard);
    if (a.has("list")) {
        list_runs(sweep, plan_sweep_runs(sweep, out));
        return 0;
    }
    Job job;
    job.command = "sweep";
    job.sweep = fs::absolute(a.positional[0]).lexically_normal().string();
    job.sweep_key = sweep_file_key(job.sweep);
    if (const auto code = run_distributed(
            job, a.value("shard"),
            ShardSettings{{}, out, jobs, a.has("force"), a.values("timings"), time_limit},
            a.has("jobs"))) {
        return *code;
    }
    if (a.has("timings"))
        throw InputError("rotbeam sweep: --timings: only with --shard I/N or under mpirun");
    std::vector<PlannedRun> runs = plan_sweep_runs(sweep, out);
    for (PlannedRun& run : runs) run.time_limit_seconds = time_limit;
    std::cout << "rotbeam sweep: " << runs.size() << " runs on " << jobs << " threads → " << out
              << "\n";
    fs::create_directories(fs::path(out) / "runs");
    remove_stale_temporaries(out);
    run_planned_runs(runs, jobs, a.has("force"), "rotbeam sweep");
    write_sweep_report(out, sweep, runs);
    return 0;
}

}  // namespace rotbeam::cli
