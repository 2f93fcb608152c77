#include "distribution/distributed.hpp"

#include <fnmatch.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <iostream>
#include <numeric>

#include "core/atomic_file.hpp"
#include "core/errors.hpp"
#include "core/version.hpp"
#include "distribution/ranks.hpp"
#include "distribution/study_cost.hpp"
#include "distribution/study_registry.hpp"
#include "distribution/sweep_runs.hpp"
#include "runs/catalog.hpp"
#include "runs/parallel.hpp"
#include "runs/progress.hpp"
#include "runs/run_file.hpp"

namespace rotbeam::cli {

namespace fs = std::filesystem;

namespace {

RunFileKind run_file_kind(const Unit& u) {
    switch (u.kind) {
        case Unit::Kind::case_run:
            return RunFileKind::case_run;
        case Unit::Kind::study_run:
            return RunFileKind::study_run;
        case Unit::Kind::whole_study:
            return RunFileKind::whole_study;
    }
    return RunFileKind::case_run;
}

std::string case_text(const std::string& case_name) {
    try {
        return read_text_file(resolve_case_path(case_name));
    } catch (const InputError&) {
        return "";
    }
}

// Every file under `root` (relative paths, sorted), leaving out interrupted writes' temporaries.
std::vector<std::string> files_under(const fs::path& root) {
    std::vector<std::string> files;
    if (!fs::exists(root)) return files;
    for (const auto& entry : fs::recursive_directory_iterator(root)) {
        if (!entry.is_regular_file()) continue;
        const std::string name = entry.path().filename().string();
        if (name.find(".rotbeam-tmp.") != std::string::npos) continue;
        files.push_back(fs::relative(entry.path(), root).string());
    }
    std::sort(files.begin(), files.end());
    return files;
}

double since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The time an earlier run of the unit took, from the first of `folders` (shard or output
// folders) that has its file: the run's wall_seconds, or the shard file's seconds.
std::optional<double> measured_seconds(const std::vector<std::string>& folders, const Unit& u) {
    for (const std::string& folder : folders) {
        const fs::path file = fs::path(folder) / u.file;
        if (!fs::exists(file)) continue;
        try {
            const nlohmann::json j = *read_run_file(file.string(), run_file_kind(u), std::nullopt);
            for (const char* key : {"wall_seconds", "seconds"}) {
                if (j.contains(key) && j[key].get<double>() >= 0.0) return j[key].get<double>();
            }
        } catch (const InputError&) {
            // a damaged file's timing is no timing: the cost model stands in
        }
    }
    return std::nullopt;
}

}  // namespace

std::string shard_command(const Job& job, const Shard& shard, const std::string& dir) {
    std::string c = "rotbeam " + job.command;
    if (job.command == "study") c += " " + job.study;
    if (job.command == "sweep") c += " " + job.sweep;
    if (job.command == "suite" && job.cases != "*") c += " --cases '" + job.cases + "'";
    if (job.quick) c += " --quick";
    if (job.command == "suite" && job.cases != "*" && job.studies) c += " --studies";
    if (job.command == "suite" && job.cases == "*" && !job.studies) c += " --no-studies";
    if (job.reduced_follower) c += " --reduced-follower";
    if (job.command == "suite" && !job.estimate) c += " --estimate off";
    return c + " --shard " + std::to_string(shard.index) + "/" + std::to_string(shard.count) +
           " --out " + dir;
}

JobPlan plan_job(const Job& job, const std::string& dir) {
    JobPlan p{job, {}, {}, {}, {}};
    const StudyOptions o{dir, job.quick, job.reduced_follower};
    std::vector<std::string> studies;
    if (job.command == "suite") {
        const std::vector<std::string> catalog = catalog_cases();
        if (std::none_of(catalog.begin(), catalog.end(), [&](const std::string& name) {
                return fnmatch(job.cases.c_str(), name.c_str(), 0) == 0;
            })) {
            throw InputError("rotbeam suite: --cases: '" + job.cases +
                             "' matches no catalog case (see 'rotbeam list')");
        }
        p.case_runs = plan_runs(job.cases, dir, job.quick, job.estimate);
        if (job.studies) {
            for (const auto& entry : static_studies()) {
                if (!standalone_study(entry.first)) studies.push_back(entry.first);
            }
        }
    } else if (job.command == "sweep") {
        p.case_runs = plan_sweep_runs(read_sweep(job.sweep), dir);
    } else {
        if (job.study == "rotations") {
            throw InputError(
                "rotbeam study: --shard: 'rotations' is one sweep of a second; run it whole");
        }
        check_study_name(job.study);
        for (const auto& entry : static_studies()) {
            if (job.study == "all" || job.study == entry.first) studies.push_back(entry.first);
        }
    }
    for (const std::string& name : studies) {
        const auto s = std::find_if(split_studies().begin(), split_studies().end(),
                                    [&](const auto& e) { return e.first == name; });
        if (s != split_studies().end() && !timed_study(name)) {
            p.split.emplace_back(name, s->second.plan(o));
        } else {
            p.whole.push_back(name);
        }
    }
    for (size_t i = 0; i < p.case_runs.size(); ++i) {
        const PlannedRun& run = p.case_runs[i];
        Unit u;
        u.kind = Unit::Kind::case_run;
        u.file = "runs/" + fs::path(run.output).filename().string();
        u.label = fs::path(run.output).stem().string();
        u.key = run.key;
        u.modelled_seconds = run.modelled_seconds;
        u.plan = i;
        p.units.push_back(u);
    }
    for (size_t s = 0; s < p.split.size(); ++s) {
        const auto& [name, runs] = p.split[s];
        for (size_t r = 0; r < runs.size(); ++r) {
            const StudyRun& run = runs[r];
            Unit u;
            u.kind = Unit::Kind::study_run;
            u.file = "study-runs/" + name + "/" + stable_hash(run.key) + ".json";
            u.label = name + " " + run.key;
            u.key = stable_hash(name + "\n" + run.key + "\n" +
                                std::to_string(static_cast<int>(run.kind)) + "\n" +
                                (job.quick ? "quick" : "full") + "\n" +
                                case_text(run.spec.case_name) + "\n" + kGitDescribe);
            u.modelled_seconds = study_run_seconds(run);
            u.plan = s;
            u.index = r;
            u.study = name;
            p.units.push_back(u);
        }
    }
    // Whole studies sharing a cache of references are one unit: made one after the other into one
    // folder, they compute the references once, as one process does.
    std::vector<std::vector<std::string>> groups;
    for (const std::string& name : p.whole) {
        const auto g = std::find_if(groups.begin(), groups.end(), [&](const auto& members) {
            return !reference_group(name).empty() &&
                   reference_group(members.front()) == reference_group(name);
        });
        if (g == groups.end()) {
            groups.push_back({name});
        } else {
            g->push_back(name);
        }
    }
    for (const std::vector<std::string>& members : groups) {
        const std::string name =
            members.size() == 1 ? members.front() : reference_group(members.front());
        std::string names, labels;
        Unit u;
        u.kind = Unit::Kind::whole_study;
        for (const std::string& m : members) {
            names += m + "\n";
            labels += (labels.empty() ? "" : " + ") + m;
            u.modelled_seconds += whole_study_seconds(m, job.quick);
            u.timed = u.timed || timed_study(m);
        }
        u.file = "studies/" + name + ".done.json";
        u.label = "study " + labels;
        u.key = stable_hash("study\n" + names + (job.quick ? "quick" : "full") + "\n" +
                            (job.reduced_follower ? "reduced-follower" : "") + "\n" + kGitDescribe);
        u.study = name;
        u.studies = members;
        p.units.push_back(u);
    }
    return p;
}

namespace {

// A relative path that stays inside the folder it is taken from: a non-empty JSON string, no root,
// no `..` component.
bool inside_folder(const nlohmann::json& name) {
    if (!name.is_string() || name.get<std::string>().empty()) return false;
    const fs::path p = name.get<std::string>();
    if (p.has_root_path()) return false;
    return std::none_of(p.begin(), p.end(), [](const fs::path& part) { return part == ".."; });
}

}  // namespace

UnitCheck check_unit(const std::string& dir, const Unit& u) {
    const fs::path file = fs::path(dir) / u.file;
    if (!fs::exists(file)) return {UnitState::absent, ""};
    std::optional<nlohmann::json> read;
    try {
        read = read_run_file(file.string(), run_file_kind(u), u.key);
    } catch (const InputError& e) {
        return {UnitState::damaged, e.what()};
    }
    if (!read) {
        return {UnitState::stale, file.string() +
                                      ": input_key: made from other inputs or another rotbeam "
                                      "version (not the plan's)"};
    }
    const nlohmann::json& j = *read;
    if (u.kind == Unit::Kind::whole_study) {
        if (j["files"].empty())
            return {UnitState::damaged, file.string() + ": files: empty (no study file listed)"};
        const fs::path folder = fs::path(dir) / "studies" / u.study;
        for (const auto& name : j["files"]) {
            // Merge copies these files into its output folder: names inside the study's folder
            // only (relative, no `..`), never a path that would read or write elsewhere.
            if (!inside_folder(name)) {
                return {UnitState::damaged,
                        file.string() + ": files: " + name.dump() + " is not a file name"};
            }
            const fs::path f = folder / name.get<std::string>();
            if (!fs::exists(f))
                return {UnitState::damaged,
                        file.string() + ": files: " + f.string() + " is missing"};
            if (f.extension() == ".json") {
                if (!nlohmann::json::accept(read_text_file(f.string())))
                    return {UnitState::damaged, f.string() + ": not complete JSON"};
            }
        }
    }
    return {UnitState::made, ""};
}

bool make_unit(const JobPlan& plan, const Unit& u, const ShardSettings& s) {
    if (!s.force && u.kind != Unit::Kind::case_run &&
        check_unit(s.dir, u).state == UnitState::made) {
        return false;
    }
    const fs::path file = fs::path(s.dir) / u.file;
    const auto start = std::chrono::steady_clock::now();
    switch (u.kind) {
        case Unit::Kind::case_run: {
            PlannedRun run = plan.case_runs[u.plan];
            run.time_limit_seconds = s.time_limit;
            if (!s.force && up_to_date(run)) return false;
            write_file_atomically(run.output, execute_planned_run(run).dump(1) + "\n");
            return true;
        }
        case Unit::Kind::study_run: {
            nlohmann::json result = execute_run(plan.split[u.plan].second[u.index]);
            const nlohmann::json record = {{"study", u.study},
                                           {"key", plan.split[u.plan].second[u.index].key},
                                           {"input_key", u.key},
                                           {"seconds", since(start)},
                                           {"result", std::move(result)}};
            fs::create_directories(file.parent_path());
            write_file_atomically(file.string(), record.dump(1) + "\n");
            return true;
        }
        case Unit::Kind::whole_study: {
            // A study stopped halfway left some of its files: start its folder afresh.
            const fs::path folder = fs::path(s.dir) / "studies" / u.study;
            fs::remove_all(folder);
            fs::remove(file);
            // A timed unit runs alone, so its untimed parallel work may take every worker
            // thread; a pooled one has one thread, as each of its neighbours.
            const StudyOptions o{folder.string(), plan.job.quick, plan.job.reduced_follower,
                                 u.timed ? s.jobs : 1};
            for (const std::string& study : u.studies) run_study_whole(study, o);
            const nlohmann::json record = {{"study", u.study},
                                           {"input_key", u.key},
                                           {"seconds", since(start)},
                                           {"files", files_under(folder)}};
            write_file_atomically(file.string(), record.dump(1) + "\n");
            return true;
        }
    }
    return true;  // every kind returned above
}

std::vector<double> expected_unit_seconds(const JobPlan& plan,
                                          const std::vector<std::string>& timings) {
    std::vector<double> modelled;
    std::vector<std::optional<double>> measured;
    for (const Unit& u : plan.units) {
        modelled.push_back(u.modelled_seconds);
        measured.push_back(measured_seconds(timings, u));
    }
    return expected_seconds(modelled, measured);
}

void write_shard_manifest(const JobPlan& plan, const ShardSettings& s,
                          const std::vector<size_t>& units) {
    nlohmann::json manifest = {
        {"format", "rotbeam-shard"},       {"version", kGitDescribe}, {"job", plan.job.to_json()},
        {"shard", s.shard.index},          {"of", s.shard.count},     {"timed_by", s.timings},
        {"units", nlohmann::json::array()}};
    for (const size_t i : units) manifest["units"].push_back(plan.units[i].file);
    write_file_atomically((fs::path(s.dir) / "shard.json").string(), manifest.dump(1) + "\n");
}

void run_shard(const Job& job, const ShardSettings& s) {
    fs::create_directories(s.dir);
    remove_stale_temporaries(s.dir);
    const JobPlan plan = plan_job(job, s.dir);
    const std::vector<double> expected = expected_unit_seconds(plan, s.timings);
    const std::vector<int> shard_of = assign_longest_first(expected, s.shard.count);
    std::vector<size_t> mine;
    for (size_t i = 0; i < plan.units.size(); ++i) {
        if (shard_of[i] == s.shard.index - 1) mine.push_back(i);
    }
    // Longest first within the shard too: the worker threads end together.
    std::stable_sort(mine.begin(), mine.end(),
                     [&](size_t a, size_t b) { return expected[a] > expected[b]; });
    // Every unit's file already there is checked before any is made: a damaged one is refused
    // (a unit of other inputs is made again), as a suite refuses its damaged results.
    if (!s.force) {
        for (const size_t i : mine) {
            const UnitCheck check = check_unit(s.dir, plan.units[i]);
            if (check.state == UnitState::damaged)
                throw InputError(check.problem + "; delete it to make it again");
        }
    }
    double my_seconds = 0.0;
    for (const size_t i : mine) my_seconds += expected[i];
    write_shard_manifest(plan, s, mine);
    const std::string what = "rotbeam " + job.command + " shard " + std::to_string(s.shard.index) +
                             "/" + std::to_string(s.shard.count);
    std::cout << what << ": " << mine.size() << " of " << plan.units.size() << " units, expected "
              << human_seconds(my_seconds) << " of "
              << human_seconds(std::accumulate(expected.begin(), expected.end(), 0.0)) << " on "
              << s.jobs << " threads → " << s.dir << "\n";
    std::vector<size_t> pooled, alone;
    for (const size_t i : mine) (plan.units[i].timed ? alone : pooled).push_back(i);
    double alone_seconds = 0.0;
    for (const size_t i : alone) alone_seconds += expected[i];
    ProgressOptions options = progress_options_for_stderr();
    options.workers = s.jobs;
    Progress progress(what, mine.size(), std::cerr, options);
    progress.set_total_cost(my_seconds - alone_seconds, alone_seconds);
    const auto make = [&](size_t i) {
        progress.started(plan.units[i].label, expected[i], plan.units[i].timed);
        if (make_unit(plan, plan.units[i], s)) {
            progress.finished(plan.units[i].label);
        } else {
            progress.skipped(plan.units[i].label);  // made by an earlier run of the shard
        }
    };
    for_each_parallel(pooled.size(), s.jobs, [&](size_t k) { make(pooled[k]); });
    for (const size_t i : alone) make(i);
    std::cout << what << ": done → " << s.dir << " (merge with 'rotbeam merge DIR... --out DIR')\n";
}

std::optional<int> run_distributed(const Job& job, const std::optional<std::string>& shard,
                                   ShardSettings settings, bool jobs_given) {
    const std::string command = "rotbeam " + job.command;
    const int ranks = launched_ranks(command);
    if (ranks > 1) {
        if (shard) {
            throw InputError(command + ": --shard: not under mpirun (" + std::to_string(ranks) +
                             " ranks): the ranks already share the runs");
        }
        if (!jobs_given) settings.jobs = 1;  // one rank per core is what mpirun -np N means
        return run_over_ranks(job, settings);
    }
    if (!shard) return std::nullopt;
    settings.shard = parse_shard(job.command, *shard);
    run_shard(job, settings);
    return 0;
}

}  // namespace rotbeam::cli
