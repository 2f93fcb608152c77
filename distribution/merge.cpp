// The merge of `rotbeam merge DIR... --out DIR`: the shard folders of one job (`suite`, `study` or
// `sweep` with --shard I/N) into the output of one uninterrupted run: the same result files, the
// split studies combined from their runs' results, the whole studies' files, and (suite) the
// summaries and the report. Every shard file is checked before anything is written: a damaged one
// is refused by name (exit 2), missing runs are listed with the commands that make them (exit 5),
// and in both cases nothing is written.
#include "distribution/merge.hpp"

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <map>
#include <set>

#include "core/atomic_file.hpp"
#include "core/errors.hpp"
#include "core/version.hpp"
#include "distribution/distributed.hpp"
#include "distribution/study_registry.hpp"
#include "distribution/sweep_runs.hpp"
#include "runs/run_file.hpp"

namespace rotbeam::cli {

namespace fs = std::filesystem;

namespace {

struct ShardFolder {
    std::string dir;
    Shard shard;
    std::set<std::string> units;  // the unit files its shard.json lists
};

// The shard folders' manifests, checked: one job, made by this rotbeam version.
Job read_shards(const std::vector<std::string>& dirs, std::vector<ShardFolder>& shards) {
    Job job;
    std::string first;
    for (const std::string& dir : dirs) {
        const std::string file = (fs::path(dir) / "shard.json").string();
        if (!fs::exists(file)) {
            throw InputError(
                "rotbeam merge: " + file +
                ": missing: not a shard folder (written by `rotbeam suite|study|sweep ... "
                "--shard I/N --out DIR`)");
        }
        // A folder given twice (under the same name or another) would count its runs twice.
        for (const ShardFolder& earlier : shards) {
            std::error_code ec;
            if (fs::equivalent(dir, earlier.dir, ec)) {
                throw InputError("rotbeam merge: " + dir + ": the same folder as " + earlier.dir +
                                 ", given twice (give each shard folder once)");
            }
        }
        const ShardManifest m = [&] {
            try {
                return parse_shard_manifest(read_text_file(file), file);
            } catch (const InputError& e) {
                throw InputError("rotbeam merge: " + std::string(e.what()));
            }
        }();
        if (m.version != kGitDescribe) {
            throw InputError("rotbeam merge: " + file + ": version: made by rotbeam " +
                             nlohmann::json(m.version).dump() + ", this is rotbeam " +
                             kGitDescribe + " (results of one version only)");
        }
        if (first.empty()) {
            job = m.job;
            first = file;
        } else if (!(m.job == job)) {
            throw InputError("rotbeam merge: " + file + ": job: " + m.job.to_json().dump() +
                             " is another job than " + first + "'s " + job.to_json().dump());
        }
        shards.push_back({dir, m.shard, {m.units.begin(), m.units.end()}});
    }
    return job;
}

// Lists the missing units, which shard was to make each, and the commands that make them.
void report_missing(const JobPlan& plan, const std::vector<const Unit*>& missing,
                    const std::vector<ShardFolder>& shards) {
    std::cerr << "rotbeam merge: " << missing.size() << " of " << plan.units.size()
              << " runs are missing from the shard folders; nothing was written:\n";
    std::map<std::string, const ShardFolder*> rerun;  // by folder
    for (const Unit* u : missing) {
        const ShardFolder* owner = nullptr;
        for (const ShardFolder& s : shards) {
            if (s.units.count(u->file)) owner = &s;
        }
        std::cerr << "  " << u->file;
        if (u->kind != Unit::Kind::case_run) std::cerr << " (" << u->label << ")";
        std::cerr << ": ";
        if (owner) {
            std::cerr << "shard " << owner->shard.index << "/" << owner->shard.count << ", "
                      << owner->dir << "\n";
            rerun.emplace(owner->dir, owner);
        } else {
            std::cerr << "in no shard folder given\n";
        }
    }
    if (!rerun.empty()) {
        std::cerr << "rotbeam merge: make them by running these shards again (each resumes and "
                     "makes only its missing runs), then merge again:\n";
        for (const auto& [dir, s] : rerun)
            std::cerr << "  " << shard_command(plan.job, s->shard, dir) << "\n";
    }
    // A shard folder not given (or shards split with different --timings: then the unit is in
    // none of them).
    const int count = shards.empty() ? 0 : shards.front().shard.count;
    std::set<int> given;
    for (const ShardFolder& s : shards) given.insert(s.shard.index);
    for (int i = 1; i <= count; ++i) {
        if (!given.count(i)) {
            std::cerr << "rotbeam merge: no folder of shard " << i << "/" << count
                      << " was given: " << shard_command(plan.job, {i, count}, "DIR") << "\n";
        }
    }
}

// Writes the merged output: every unit's file from the folder that has it, then what one run
// writes after its runs.
void write_merged(const JobPlan& plan, const std::map<const Unit*, std::string>& found,
                  const std::string& out) {
    fs::create_directories(fs::path(out) / "runs");
    remove_stale_temporaries(out);
    std::vector<std::vector<nlohmann::json>> results(plan.split.size());
    for (size_t s = 0; s < plan.split.size(); ++s) results[s].resize(plan.split[s].second.size());
    for (const Unit& u : plan.units) {
        const fs::path from = fs::path(found.at(&u)) / u.file;
        switch (u.kind) {
            case Unit::Kind::case_run:
                write_file_atomically(plan.case_runs[u.plan].output, read_text_file(from.string()));
                break;
            case Unit::Kind::study_run:
                results[u.plan][u.index] =
                    read_run_file(from.string(), RunFileKind::study_run, std::nullopt)
                        ->at("result");
                break;
            case Unit::Kind::whole_study: {
                const fs::path folder = fs::path(found.at(&u)) / "studies" / u.study;
                const nlohmann::json record =
                    *read_run_file(from.string(), RunFileKind::whole_study, std::nullopt);
                for (const auto& name : record.at("files")) {
                    const fs::path target = fs::path(out) / name.get<std::string>();
                    fs::create_directories(target.parent_path());
                    write_file_atomically(
                        target.string(),
                        read_text_file((folder / name.get<std::string>()).string()));
                }
                break;
            }
        }
    }
    nlohmann::json published_checks = nlohmann::json::array();
    if (plan.job.command == "suite") published_checks = write_suite_summaries(out, plan.case_runs);
    const StudyOptions o{out, plan.job.quick, plan.job.reduced_follower};
    for (size_t s = 0; s < plan.split.size(); ++s) {
        const std::string& name = plan.split[s].first;
        const std::vector<StudyRun>& runs = plan.split[s].second;
        const auto study = std::find_if(split_studies().begin(), split_studies().end(),
                                        [&](const auto& e) { return e.first == name; });
        study->second.combine(o, results_by_key(runs, std::move(results[s])));
        std::cout << "study " << name << ": combined from " << runs.size() << " runs → "
                  << (fs::path(out) / ("study-" + name + ".md")).string() << "\n";
    }
    if (plan.job.command == "suite") write_suite_report(out, plan.case_runs, published_checks);
    if (plan.job.command == "sweep")
        write_sweep_report(out, read_sweep(plan.job.sweep), plan.case_runs);
}

}  // namespace

int merge_shard_folders(const std::vector<std::string>& dirs, const std::string& out) {
    std::vector<ShardFolder> shards;
    const Job job = read_shards(dirs, shards);
    // A sweep is planned again from its file: the file the shards ran, or every run would look
    // damaged (another input key) or missing (other run files).
    if (job.command == "sweep" &&
        (!std::filesystem::exists(job.sweep) || sweep_file_key(job.sweep) != job.sweep_key)) {
        throw InputError("rotbeam merge: " + job.sweep + ": " +
                         (std::filesystem::exists(job.sweep) ? "changed" : "gone") +
                         " since the shards were made (" +
                         (fs::path(dirs.front()) / "shard.json").string() +
                         " records its text); merge with the sweep file the shards ran, or run "
                         "the shards again");
    }
    const JobPlan plan = plan_job(job, out);
    std::map<const Unit*, std::string> found;
    std::vector<const Unit*> missing;
    for (const Unit& u : plan.units) {
        for (const ShardFolder& s : shards) {
            const UnitCheck check = check_unit(s.dir, u);
            if (check.state == UnitState::damaged || check.state == UnitState::stale) {
                throw InputError("rotbeam merge: " + check.problem + "; remove it and run shard " +
                                 std::to_string(s.shard.index) + "/" +
                                 std::to_string(s.shard.count) + " again");
            }
            if (check.state == UnitState::made && !found.count(&u)) found[&u] = s.dir;
        }
        if (!found.count(&u)) missing.push_back(&u);
    }
    if (!missing.empty()) {
        report_missing(plan, missing, shards);
        return kExitIncomplete;
    }
    write_merged(plan, found, out);
    std::cout << "rotbeam merge: " << plan.units.size() << " runs from " << shards.size()
              << " shard folders → " << out << "\n";
    return 0;
}

}  // namespace rotbeam::cli
