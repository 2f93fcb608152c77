#include "distribution/suite_plan.hpp"

#include <fnmatch.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <sstream>

#include "cases/loader/case_loader.hpp"
#include "cases/loader/deck_case.hpp"
#include "combinations/registry.hpp"
#include "core/atomic_file.hpp"
#include "core/errors.hpp"
#include "core/results.hpp"
#include "core/version.hpp"
#include "distribution/gate.hpp"
#include "distribution/study_registry.hpp"
#include "parameterizations/registry.hpp"
#include "parameterizations/rotation_study.hpp"
#include "reports/report.hpp"
#include "runs/accuracy_run.hpp"
#include "runs/catalog.hpp"
#include "runs/estimate_cost.hpp"
#include "runs/parallel.hpp"
#include "runs/progress.hpp"
#include "runs/run_case.hpp"
#include "runs/run_file.hpp"

namespace rotbeam::cli {

namespace fs = std::filesystem;

std::string read_text_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

std::string planned_run_key(const std::string& case_text, const PlannedRun& run) {
    std::string settings = run.rotation + "\n" + run.formulation;
    for (const std::string& o : run.overrides) settings += "\n" + o;
    if (run.elements_per_member > 0)
        settings += "\nelements " + std::to_string(run.elements_per_member);
    if (!run.estimate) settings += "\nestimate off";
    if (run.as_run) settings += "\nas run";
    const size_t h = std::hash<std::string>{}(case_text + "\n" + settings + "\n" + kGitDescribe);
    std::ostringstream s;
    s << std::hex << h;
    return s.str();
}

namespace {

// Table III's converged column: a modal case refined to this many elements per member with its
// own formulation and parameterization (0.1 s for the joined beam, whose paper mesh of 10 per
// member sits 0.4–3.9 % above it).
constexpr int kConvergedElementsPerMember = 160;

// A modal case's runs beyond formulation × parameterization, for Table III: one with the
// settings of each published column (its references' `applies_to`, as `verify` runs them) and
// one refined to kConvergedElementsPerMember. `output` is the file's base name.
std::vector<PlannedRun> modal_variants(const std::string& name, const std::string& path,
                                       const Model& model) {
    std::vector<PlannedRun> variants;
    std::vector<std::map<std::string, std::string>> seen;
    for (const ReferenceValue& ref : model.references) {
        if (ref.applies_to.empty() ||
            std::find(seen.begin(), seen.end(), ref.applies_to) != seen.end()) {
            continue;
        }
        seen.push_back(ref.applies_to);
        PlannedRun run{name, path, std::string(param::name_of(model.discretization.rotation)),
                       std::string(choice_name(model.discretization.formulation))};
        run.overrides = reference_overrides(ref);
        const auto get = [&](const char* key, std::string& value) {
            const auto it = ref.applies_to.find(key);
            if (it != ref.applies_to.end()) value = it->second;
        };
        get("rotation", run.rotation);
        get("formulation", run.formulation);
        std::string elements = "0";
        get("elements", elements);
        run.elements_per_member = std::stoi(elements);
        run.output = name + "-as-published-" + std::to_string(seen.size()) + "_" + run.rotation +
                     "_" + run.formulation;
        variants.push_back(run);
    }
    PlannedRun refined{name, path, std::string(param::name_of(model.discretization.rotation)),
                       std::string(choice_name(model.discretization.formulation))};
    refined.elements_per_member = kConvergedElementsPerMember;
    refined.output = name + "-" + std::to_string(kConvergedElementsPerMember) + "-per-member_" +
                     refined.rotation + "_" + refined.formulation;
    variants.push_back(refined);
    return variants;
}

// The cost model's expected time of the run (run_cost.hpp), its estimate included when it has
// one; a combination that does not exist for the case costs only the fixed part.
double run_cost(const PlannedRun& run) {
    std::vector<std::string> overrides = {"discretization.rotation=" + run.rotation,
                                          "discretization.formulation=" + run.formulation};
    overrides.insert(overrides.end(), run.overrides.begin(), run.overrides.end());
    try {
        Model model = load_case(run.case_path, overrides);
        if (run.elements_per_member > 0) {
            for (Member& m : model.members) m.elements = run.elements_per_member;
        }
        return modelled_seconds(model, run.estimate && model.analysis.estimate);
    } catch (const InputError&) {
        return kFixedSeconds;
    }
}

// Whether the result, or a run inside it (a companion of its estimate, an attempt of accuracy
// control), has the status `time-limit`: an answer cut short, not a result of its inputs.
bool stopped_by_time_limit(const nlohmann::json& j) {
    if (j.is_object()) {
        const auto status = j.find("status");
        if (status != j.end() && *status == "time-limit") return true;
    }
    if (!j.is_object() && !j.is_array()) return false;
    return std::any_of(j.begin(), j.end(),
                       [](const nlohmann::json& item) { return stopped_by_time_limit(item); });
}

}  // namespace

bool up_to_date(const PlannedRun& run) {
    if (!fs::exists(run.output)) return false;
    try {
        // A file of other inputs or another version (another input_key) is made again, and so
        // is a run stopped by the time limit.
        const std::optional<nlohmann::json> j =
            read_run_file(run.output, RunFileKind::case_run, run.key);
        return j.has_value() && !stopped_by_time_limit(*j);
    } catch (const InputError& e) {
        // A damaged file is refused, not run again over: something other than rotbeam changed
        // the folder (an interrupted write leaves only a hidden temporary, never a damaged file).
        throw InputError(std::string(e.what()) + "; delete it to make the run again");
    }
}

std::vector<PlannedRun> plan_runs(const std::string& glob, const std::string& out_dir, bool quick,
                                  bool estimate) {
    std::vector<PlannedRun> runs;
    for (const std::string& name : catalog_cases()) {
        if (fnmatch(glob.c_str(), name.c_str(), 0) != 0) continue;
        const std::string path = resolve_case_path(name);
        // Static, modal and dynamic cases alike; --quick keeps two static ones (no dynamics).
        if (quick && name != "cantilever-moment" && name != "bend-45") continue;
        const Model model = load_case(path, {});
        const std::string text = cases::case_input_text(path);
        for (const comb::Combination& c : comb::all_combinations(false)) {
            PlannedRun run{name, path, std::string(param::name_of(c.rotation)),
                           std::string(choice_name(c.formulation))};
            run.output = (fs::path(out_dir) / "runs" /
                          (name + "_" + run.rotation + "_" + run.formulation + ".json"))
                             .string();
            run.estimate = estimate;
            run.key = planned_run_key(text, run);
            run.modelled_seconds = run_cost(run);
            runs.push_back(run);
        }
        if (!quick && model.analysis.kind == AnalysisKind::modal) {
            for (PlannedRun& run : modal_variants(name, path, model)) {
                run.output = (fs::path(out_dir) / "runs" / (run.output + ".json")).string();
                run.estimate = estimate;
                run.key = planned_run_key(text, run);
                run.modelled_seconds = run_cost(run);
                runs.push_back(std::move(run));
            }
        }
    }
    return runs;
}

namespace {

// The result of a run the case or the combination refuses: its status `error` and the reason,
// with the schema version and the build like every result.
nlohmann::json refused_run(const PlannedRun& run, const std::string& message) {
    return {{"schema_version", kSchemaVersion},
            {"version", kGitDescribe},
            {"case", run.case_name},
            {"rotation", run.rotation},
            {"formulation", run.formulation},
            {"status", "error"},
            {"message", message},
            {"steps", nlohmann::json::array()},
            {"wall_seconds", 0.0}};
}

nlohmann::json execute_unkeyed(const PlannedRun& run) {
    Model model;
    try {
        std::vector<std::string> overrides = {"discretization.rotation=" + run.rotation,
                                              "discretization.formulation=" + run.formulation};
        overrides.insert(overrides.end(), run.overrides.begin(), run.overrides.end());
        model = load_case(run.case_path, overrides);
        if (run.elements_per_member > 0) {
            for (Member& m : model.members) m.elements = run.elements_per_member;
        }
    } catch (const InputError& e) {
        return refused_run(run, e.what());
    }
    try {
        const bool estimate = run.estimate && model.analysis.estimate;
        // The run's solved path: its estimate's companions start from it (add_run_estimate).
        SolvedPath solved;
        RunRequest request{run.case_path, model, false, run.time_limit_seconds};
        if (run.as_run && model.analysis.accuracy > 0.0) return run_to_accuracy(request);
        if (estimate) request.path = &solved;
        nlohmann::json result = run_case(request);
        if (estimate) {
            add_run_estimate(request, result);
        } else {
            result["estimate"] = estimate_off();
        }
        return result;
    } catch (const InputError& e) {
        // The combination does not exist for this case (e.g. a formulation not built yet).
        return refused_run(run, e.what());
    }
}

}  // namespace

nlohmann::json execute_planned_run(const PlannedRun& run) {
    nlohmann::json result = execute_unkeyed(run);
    result["input_key"] = run.key;
    return result;
}

nlohmann::json write_suite_summaries(const std::string& out, const std::vector<PlannedRun>& runs) {
    // The published numbers of the cases run (Tables I–III), as `verify` computes them.
    std::vector<std::string> names;
    for (const PlannedRun& r : runs) {
        if (names.empty() || names.back() != r.case_name) names.push_back(r.case_name);
    }
    PublishedReferences published = published_references(names);
    write_file_atomically((fs::path(out) / "published.md").string(), published.markdown);
    write_file_atomically((fs::path(out) / "rotation-study.json").string(),
                          param::rotation_study(721).dump(1) + "\n");
    return std::move(published.checks);
}

void write_suite_report(const std::string& out, const std::vector<PlannedRun>& runs,
                        const nlohmann::json& published_checks) {
    std::vector<std::string> files;
    for (const PlannedRun& r : runs) files.push_back(r.output);
    write_report(out, files, study_names(), published_checks);
    std::cout << "report: " << (fs::path(out) / "index.md").string() << "\n";
}

void run_planned_runs(const std::vector<PlannedRun>& runs, int jobs, bool force,
                      const std::string& what) {
    double total_cost = 0.0;
    for (const PlannedRun& run : runs) total_cost += run.modelled_seconds;
    ProgressOptions options = progress_options_for_stderr();
    options.workers = jobs;
    // Every result already there is checked before any run starts: a damaged one stops the
    // command before it has written anything.
    std::vector<char> current(runs.size(), 0);
    if (!force) {
        for (size_t i = 0; i < runs.size(); ++i) current[i] = up_to_date(runs[i]);
    }
    Progress progress(what, runs.size(), std::cerr, options);
    progress.set_total_cost(total_cost);
    for_each_parallel(runs.size(), jobs, [&](size_t i) {
        const PlannedRun& run = runs[i];
        const std::string label = fs::path(run.output).stem().string();
        progress.started(label, run.modelled_seconds);
        if (!current[i]) {
            write_file_atomically(run.output, execute_planned_run(run).dump(1) + "\n");
            progress.finished(label);
        } else {
            progress.skipped(label);  // a resumed suite's result: no measure of the speed
        }
    });
}

}  // namespace rotbeam::cli
