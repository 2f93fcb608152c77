// A suite or study split over processes or machines (docs/distributed-runs.md): the job as a list
// of independent units (the suite's case runs, the split studies' runs, the other studies whole),
// the shard that makes some of them into a folder of its own, and the merge of shard folders into
// the output of one uninterrupted run.
//
// A shard folder holds shard.json (the job, the shard, its units), runs/*.json (case runs, as the
// suite writes them), study-runs/STUDY/HASH.json (one run of a split study: its key, input key,
// time and result) and studies/STUDY/ with studies/STUDY.done.json (a study made whole: its
// folder and the list of the files it wrote). Every file is written atomically; a unit counts as
// made when its file is there with the unit's input key, so a shard started again with the same
// arguments resumes and makes only what is missing.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "distribution/shard_manifest.hpp"
#include "distribution/suite_plan.hpp"
#include "runs/shards.hpp"
#include "studies/study_runs.hpp"

namespace rotbeam::cli {

// The command that runs the job's shard I/N into `dir` (for messages).
std::string shard_command(const Job& job, const Shard& shard, const std::string& dir);

// One independent piece of a job.
struct Unit {
    enum class Kind { case_run, study_run, whole_study };
    Kind kind = Kind::case_run;
    std::string file;   // its file inside a shard folder
    std::string label;  // what it is, for progress lines and messages
    std::string key;    // input key: the file is valid for this unit when it carries it
    double modelled_seconds = 0.0;
    size_t plan = 0;    // case run: index into case_runs; study run: index into split
    size_t index = 0;   // study run: index into split[plan].second
    std::string study;  // a study run's study; a whole study's folder name
    std::vector<std::string> studies;  // whole study: the studies it makes, in this order
    bool timed = false;                // its timings are its result: run alone, after the others
};

struct JobPlan {
    Job job;
    std::vector<PlannedRun> case_runs;  // results under the folder the plan was made for
    std::vector<std::pair<std::string, std::vector<StudyRun>>> split;
    std::vector<std::string> whole;  // studies made whole
    std::vector<Unit> units;
};

// The job's units, in a fixed order; case runs' outputs under `dir`. InputError for an unknown
// study or a --cases pattern that matches no catalog case.
JobPlan plan_job(const Job& job, const std::string& dir);

// Whether a shard folder holds the unit: its file absent, there with the unit's input key (and,
// for a whole study, every file it listed), there but made from other inputs (another input key),
// or damaged (runs/run_file.hpp). `problem`: one line, naming the file and the key.
enum class UnitState { made, absent, stale, damaged };
struct UnitCheck {
    UnitState state;
    std::string problem;
};
UnitCheck check_unit(const std::string& dir, const Unit& u);

struct ShardSettings {
    Shard shard;
    std::string dir;
    int jobs = 1;
    bool force = false;                // make every unit again
    std::vector<std::string> timings;  // folders with earlier results whose times balance
    double time_limit = 0.0;           // each case run's wall-clock limit, seconds (0: none)
};

// Makes the units of shard I/N of the job into settings.dir (resuming: units whose file is valid
// are kept). Each shard computes the same split from the same plan and timings.
void run_shard(const Job& job, const ShardSettings& settings);

// The executors' common parts (run_shard here, run_over_ranks in ranks.hpp):
// every unit's expected seconds (its time in the first of `timings` that has its file, else the
// cost model scaled to seconds);
std::vector<double> expected_unit_seconds(const JobPlan& plan,
                                          const std::vector<std::string>& timings);
// makes one unit into settings.dir (kept when its file is valid and settings.force is off: then
// false);
bool make_unit(const JobPlan& plan, const Unit& u, const ShardSettings& settings);
// writes settings.dir/shard.json: the job, shard settings.shard and the files of `units`.
void write_shard_manifest(const JobPlan& plan, const ShardSettings& settings,
                          const std::vector<size_t>& units);

// How a job is run when it is distributed; the one place suite, study (and any command whose runs
// are a Job) choose it. `shard` given (--shard I/N): this process makes that shard (run_shard).
// Started by mpirun with more than one rank: the ranks make the units together and rank 0 writes
// the output into settings.dir (run_over_ranks, ranks.hpp). Otherwise returns nullopt: the command
// runs the job in one process its own way. Returns the exit code otherwise. `jobs_given`: whether
// --jobs was given (under mpirun its default is 1 thread per rank, not every core).
std::optional<int> run_distributed(const Job& job, const std::optional<std::string>& shard,
                                   ShardSettings settings, bool jobs_given);

}  // namespace rotbeam::cli
