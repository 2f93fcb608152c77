// `rotbeam suite`: the main job. Runs every catalog case (static, modal and dynamic; matching
// --cases) with every parameterization × formulation, in parallel over --jobs worker threads,
// writes one result file per run (skipped on a rerun when its inputs and the rotbeam version are
// unchanged), the rotation study, and a report (index.md + index.html) with the runs table and the
// plots made by gnuplot scripts in reports/.
#include <fnmatch.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <map>
#include <mutex>
#include <sstream>
#include <thread>

#include "arguments.hpp"
#include "cases/loader/case_loader.hpp"
#include "combinations/registry.hpp"
#include "commands.hpp"
#include "core/errors.hpp"
#include "core/results.hpp"
#include "core/version.hpp"
#include "parameterizations/registry.hpp"
#include "parameterizations/rotation_study.hpp"
#include "reports/report.hpp"
#include "runs/parallel.hpp"
#include "runs/run_case.hpp"
#include "study_commands.hpp"

namespace rotbeam::cli {

namespace fs = std::filesystem;

namespace {

struct PlannedRun {
    std::string case_name, case_path, rotation, formulation;
    std::string output{};                  // result file
    std::string key{};                     // hash of the inputs
    std::vector<std::string> overrides{};  // further --set overrides (a variant's settings)
    int elements_per_member = 0;           // 0: the case's own mesh
};

// Table III's converged column: a modal case refined to this many elements per member with its
// own formulation and parameterization (0.1 s for the joined beam, whose paper mesh of 10 per
// member sits 0.4–3.9 % above it).
constexpr int kConvergedElementsPerMember = 160;

std::string read_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

std::string input_key(const std::string& case_text, const PlannedRun& run) {
    std::string settings = run.rotation + "\n" + run.formulation;
    for (const std::string& o : run.overrides) settings += "\n" + o;
    if (run.elements_per_member > 0)
        settings += "\nelements " + std::to_string(run.elements_per_member);
    const size_t h = std::hash<std::string>{}(case_text + "\n" + settings + "\n" + kGitDescribe);
    std::ostringstream s;
    s << std::hex << h;
    return s.str();
}

bool up_to_date(const PlannedRun& run) {
    if (!fs::exists(run.output)) return false;
    try {
        const nlohmann::json j = nlohmann::json::parse(read_file(run.output));
        return j.value("input_key", "") == run.key;
    } catch (const std::exception&) {
        return false;  // a damaged file is simply run again
    }
}

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

std::vector<PlannedRun> plan_runs(const std::string& glob, const std::string& out_dir, bool quick) {
    std::vector<PlannedRun> runs;
    for (const std::string& name : catalog_cases()) {
        if (fnmatch(glob.c_str(), name.c_str(), 0) != 0) continue;
        const std::string path = resolve_case_path(name);
        // Static, modal and dynamic cases alike; --quick keeps two static ones (no dynamics).
        if (quick && name != "cantilever-moment" && name != "bend-45") continue;
        const Model model = load_case(path, {});
        const std::string text = read_file(path);
        for (const comb::Combination& c : comb::all_combinations(false)) {
            PlannedRun run{name, path, std::string(param::name_of(c.rotation)),
                           std::string(choice_name(c.formulation))};
            run.output = (fs::path(out_dir) / "runs" /
                          (name + "_" + run.rotation + "_" + run.formulation + ".json"))
                             .string();
            run.key = input_key(text, run);
            runs.push_back(run);
        }
        if (!quick && model.analysis.kind == AnalysisKind::modal) {
            for (PlannedRun& run : modal_variants(name, path, model)) {
                run.output = (fs::path(out_dir) / "runs" / (run.output + ".json")).string();
                run.key = input_key(text, run);
                runs.push_back(std::move(run));
            }
        }
    }
    return runs;
}

nlohmann::json execute(const PlannedRun& run) {
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
        return {
            {"case", run.case_name}, {"rotation", run.rotation}, {"formulation", run.formulation},
            {"status", "error"},     {"message", e.what()},      {"steps", nlohmann::json::array()},
            {"wall_seconds", 0.0}};
    }
    try {
        return run_case(RunRequest{run.case_path, model});
    } catch (const InputError& e) {
        // The combination does not exist for this case (e.g. a formulation not built yet).
        return {
            {"case", run.case_name}, {"rotation", run.rotation}, {"formulation", run.formulation},
            {"status", "error"},     {"message", e.what()},      {"steps", nlohmann::json::array()},
            {"wall_seconds", 0.0}};
    }
}

void run_all(const std::vector<PlannedRun>& runs, int jobs, bool force) {
    std::atomic<size_t> done{0};
    std::mutex print;
    const auto start = std::chrono::steady_clock::now();
    const bool terminal = isatty(STDOUT_FILENO);
    for_each_parallel(runs.size(), jobs, [&](size_t i) {
        const PlannedRun& run = runs[i];
        if (force || !up_to_date(run)) {
            nlohmann::json result = execute(run);
            result["input_key"] = run.key;
            write_file_atomically(run.output, result.dump(1) + "\n");
        }
        const size_t d = ++done;
        const double elapsed =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::lock_guard<std::mutex> lock(print);
        if (terminal) {
            std::cout << "\r[" << d << "/" << runs.size() << "] " << std::fixed
                      << std::setprecision(1) << elapsed << " s elapsed, ETA "
                      << elapsed / static_cast<double>(d) * static_cast<double>(runs.size() - d)
                      << " s   " << std::flush;
        }
    });
    if (terminal) std::cout << "\n";
}

}  // namespace

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
         {"no-studies", "", "skip the static studies (docs/studies.md)"}}};
    const ParsedArguments a = parse_arguments(spec, args);
    if (a.help) {
        std::cout << help_text(spec);
        return 0;
    }
    const std::string out = a.value("out").value_or("out");
    const int jobs = a.positive_int("suite", "jobs", kMaxJobs)
                         .value_or(std::max(1u, std::thread::hardware_concurrency()));
    const std::string glob = a.value("cases").value_or("*");
    const std::vector<std::string> catalog = catalog_cases();
    if (std::none_of(catalog.begin(), catalog.end(), [&](const std::string& name) {
            return fnmatch(glob.c_str(), name.c_str(), 0) == 0;
        })) {
        throw InputError("rotbeam suite: --cases: '" + glob +
                         "' matches no catalog case (see 'rotbeam list')");
    }
    const std::vector<PlannedRun> runs = plan_runs(glob, out, a.has("quick"));
    std::cout << "rotbeam suite: " << runs.size() << " runs on " << jobs << " threads → " << out
              << "\n";
    // A suite killed with SIGKILL in the middle of a write left a temporary (never a partial
    // result file): clear it so the resumed folder is the one an uninterrupted suite writes.
    if (fs::exists(out)) remove_stale_temporaries(out);
    run_all(runs, jobs, a.has("force"));
    // The published numbers of the cases run (Tables I–III), as `verify` computes them.
    std::vector<std::string> names;
    for (const PlannedRun& r : runs) {
        if (names.empty() || names.back() != r.case_name) names.push_back(r.case_name);
    }
    const PublishedReferences published = published_references(names);
    write_file_atomically((fs::path(out) / "published.md").string(), published.markdown);
    write_file_atomically((fs::path(out) / "rotation-study.json").string(),
                          param::rotation_study(721).dump(1) + "\n");
    // The static studies belong to the main job: on by default for the whole catalog, off
    // for a --cases selection unless --studies asks for them.
    const bool studies = !a.has("no-studies") && (a.has("studies") || !a.has("cases"));
    if (studies) run_suite_studies(StudyOptions{out, a.has("quick"), false}, jobs);
    std::vector<std::string> files;
    for (const PlannedRun& r : runs) files.push_back(r.output);
    write_report(out, files, study_names(), published.checks);
    std::cout << "report: " << (fs::path(out) / "index.md").string() << "\n";
    return 0;
}

}  // namespace rotbeam::cli
