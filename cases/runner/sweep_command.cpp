#include "sweep_command.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <thread>

#include "arguments.hpp"
#include "core/atomic_file.hpp"
#include "core/errors.hpp"
#include "distributed.hpp"

namespace rotbeam::cli {

namespace fs = std::filesystem;

std::vector<PlannedRun> plan_sweep_runs(const Sweep& sweep, const std::string& out_dir) {
    std::vector<PlannedRun> runs;
    std::vector<std::pair<std::string, std::string>> texts;  // case path → text
    for (size_t i = 0; i < sweep.runs.size(); ++i) {
        const SweepRun& s = sweep.runs[i];
        PlannedRun run{s.case_name, s.case_path, s.rotation, s.formulation};
        run.overrides = s.overrides(sweep.keys);
        run.as_run = true;
        char number[24];
        std::snprintf(number, sizeof number, "%04zu", i + 1);
        run.output = (fs::path(out_dir) / "runs" /
                      (sweep.name + "-" + number + "_" + s.case_name + "_" + s.rotation + "_" +
                       s.formulation + ".json"))
                         .string();
        auto text = std::find_if(texts.begin(), texts.end(),
                                 [&](const auto& t) { return t.first == s.case_path; });
        if (text == texts.end()) {
            texts.emplace_back(s.case_path, read_text_file(s.case_path));
            text = texts.end() - 1;
        }
        run.key = planned_run_key(text->second, run);
        run.modelled_seconds = s.modelled_seconds;
        runs.push_back(std::move(run));
    }
    return runs;
}

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
    const Sweep sweep = read_sweep(a.positional[0]);
    const std::string out = a.value("out").value_or(sweep.folder);
    if (a.has("list")) {
        list_runs(sweep, plan_sweep_runs(sweep, out));
        return 0;
    }
    Job job;
    job.command = "sweep";
    job.sweep = fs::absolute(a.positional[0]).lexically_normal().string();
    if (const auto code = run_distributed(
            job, a.value("shard"),
            ShardSettings{{}, out, jobs, a.has("force"), a.values("timings")}, a.has("jobs"))) {
        return *code;
    }
    if (a.has("timings"))
        throw InputError("rotbeam sweep: --timings: only with --shard I/N or under mpirun");
    const std::vector<PlannedRun> runs = plan_sweep_runs(sweep, out);
    std::cout << "rotbeam sweep: " << runs.size() << " runs on " << jobs << " threads → " << out
              << "\n";
    fs::create_directories(fs::path(out) / "runs");
    remove_stale_temporaries(out);
    run_planned_runs(runs, jobs, a.has("force"), "rotbeam sweep");
    write_sweep_report(out, sweep, runs);
    return 0;
}

}  // namespace rotbeam::cli
