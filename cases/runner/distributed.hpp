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
#include <string>
#include <vector>

#include "runs/shards.hpp"
#include "studies/study_runs.hpp"
#include "suite_plan.hpp"

namespace rotbeam::cli {

// What is run: the suite or a study, with the arguments that decide its results.
struct Job {
    std::string command = "suite";  // "suite", "study" or "sweep"
    std::string study;              // study: its name, or "all"
    std::string sweep;              // sweep: the sweep file (absolute path)
    std::string cases = "*";        // suite: --cases
    bool quick = false;
    bool studies = true;  // suite: the static studies are part of the job
    bool reduced_follower = false;
    nlohmann::json to_json() const;
    bool operator==(const Job&) const = default;
};
// The job of a shard.json; InputError naming `file` when it is not one.
Job job_from_json(const nlohmann::json& j, const std::string& file);
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
    size_t plan = 0;   // case run: index into case_runs; study run: index into split
    size_t index = 0;  // study run: index into split[plan].second
    std::string study;
    bool timed = false;  // its timings are its result: run alone, after the others
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
// for a whole study, every file it listed), or there but damaged (the problem in words).
enum class UnitState { made, absent, damaged };
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
};

// Makes the units of shard I/N of the job into settings.dir (resuming: units whose file is valid
// are kept). Each shard computes the same split from the same plan and timings.
void run_shard(const Job& job, const ShardSettings& settings);

// `rotbeam merge DIR... --out DIR` (merge_command.cpp).
int command_merge(const std::vector<std::string>& args);

// Exit code of `rotbeam merge` when runs are missing from the shard folders (nothing is written).
constexpr int kExitIncomplete = 5;

}  // namespace rotbeam::cli
