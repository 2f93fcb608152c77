#include "distribution/study_registry.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <filesystem>
#include <iostream>
#include <mutex>
#include <numeric>
#include <thread>

#include "benches/study_speed.hpp"
#include "core/errors.hpp"
#include "distribution/study_cost.hpp"
#include "distribution/study_help.hpp"
#include "runs/parallel.hpp"
#include "runs/progress.hpp"
#include "studies/studies.hpp"

namespace rotbeam::cli {

const std::vector<std::pair<std::string, StudyFunction>>& static_studies() {
    static const std::vector<std::pair<std::string, StudyFunction>> table = {
        {"convergence", study_convergence},
        {"singularity", study_singularity},
        {"extremes", study_extremes},
        {"manufactured-time", study_manufactured_time},
        {"free-vibration-time", study_free_vibration_time},
        {"effectivity", study_effectivity},
        {"speed-accuracy", study_speed_accuracy},
        {"joined-beam-modal", study_joined_beam_modal},
        {"joined-beam-dynamics", study_joined_beam_dynamics},
        {"joined-beam-agreement", study_joined_beam_agreement},
    };
    return table;
}

namespace {

// One line per registered study for `rotbeam study --help` (docs/studies.md has each in full).
struct StudySummary {
    const char* name;
    const char* summary;
};
constexpr StudySummary kStudySummaries[] = {
    {"convergence",
     "h- and p-refinement of every combination on the roll-up, the 45° bend and the precessing "
     "helix: observed orders against the exact solution or the continuum reference"},
    {"singularity",
     "every combination and interpolation on the roll-up to λ = 4 and the helices to κL = 4π: "
     "the largest rotation reached and how each run stops"},
    {"extremes",
     "slenderness 10 … 1e5 (shear locking) and loads down to 1e-10 of the benchmark's against "
     "the linear Timoshenko oracle; Newton at the extremes"},
    {"manufactured-time",
     "observed orders in time of every integrator, and in space, against the manufactured "
     "motion"},
    {"free-vibration-time",
     "the time integrators on the undamped free vibration: observed orders per component and "
     "the energy drift"},
    {"effectivity",
     "estimated / true error of every estimate over refinement sequences, every combination, "
     "on the roll-up (to λ = 2, and to 4), the manufactured rod, the 45° bend, the helix, the "
     "precessing helix, the tip-loaded cantilever and the joined beam's frequencies; the band "
     "[0.5, 2] where asymptotic, and the estimator failures with their causes"},
    {"speed-accuracy",
     "per combination the cheapest discretization of each bench target, its time against its "
     "error, and the Pareto front"},
    {"joined-beam-modal", "frequency convergence of the joined beam, every combination"},
    {"joined-beam-dynamics",
     "the joined beam's 0–2 s response, dead and follower load: error against CPU time across "
     "Δt and IDA tolerances (run by name, not by the suite)"},
    {"joined-beam-agreement",
     "the mixed and displacement formulations' 0–2 s joined-beam responses at converged Δt and "
     "mesh agree (run by name, not by the suite)"},
};

}  // namespace

std::string study_help_text() {
    std::string text =
        "Studies, written to --out (study-NAME.md, .json, figures; docs/studies.md). `rotations`: "
        "sweep the rotation angle from 0 to 4π about a generic axis for every parameterization: "
        "parameter norm, σ_min(H), ‖H⁺‖, round-trip and finite-difference errors, and where each "
        "is defined (to --json).";
    for (const std::string& name : study_names()) {
        const auto* s = std::find_if(std::begin(kStudySummaries), std::end(kStudySummaries),
                                     [&](const StudySummary& e) { return name == e.name; });
        ROTBEAM_VERIFY(s != std::end(kStudySummaries), "study_help_text: no summary of " + name);
        text += " `" + name + "`: " + s->summary + ".";
    }
    return text + " `all`: every one of them.";
}

std::vector<std::string> study_names() {
    std::vector<std::string> names;
    for (const auto& entry : static_studies()) names.push_back(entry.first);
    return names;
}

void run_study_whole(const std::string& name, const StudyOptions& o) {
    const auto entry = std::find_if(static_studies().begin(), static_studies().end(),
                                    [&](const auto& e) { return e.first == name; });
    ROTBEAM_VERIFY(entry != static_studies().end(), "run_study_whole: unknown study " + name);
    std::filesystem::create_directories(o.out_dir);
    const auto start = std::chrono::steady_clock::now();
    entry->second(o);
    std::cout << "study " << name << ": "
              << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()
              << " s → " << (std::filesystem::path(o.out_dir) / ("study-" + name + ".md")).string()
              << "\n";
}

std::string study_name_list() {
    std::string names = "rotations";
    for (const std::string& name : study_names()) names += ", " + name;
    return names + ", all";
}

void check_study_name(const std::string& name) {
    bool found = name == "all";
    for (const auto& entry : static_studies()) found = found || entry.first == name;
    if (!found) {
        throw InputError("rotbeam study: unknown study '" + name +
                         "' (available: " + study_name_list() + ")");
    }
}

namespace {

// The options of `rotbeam study` that only some studies take, and which: "rotations" (the
// rotation study alone), "registered" (every study of the registry, and all) or the name of one
// study of the registry (it, and all, which runs it).
struct StudyOptionScope {
    const char* option;
    const char* studies;
};
constexpr StudyOptionScope kStudyOptionScopes[] = {
    {"json", "rotations"},
    {"samples", "rotations"},
    {"out", "registered"},
    {"quick", "registered"},
    {"reduced-follower", "joined-beam-dynamics"},
    {"jobs", "registered"},
};

}  // namespace

void check_study_option(const std::string& name, const std::string& option) {
    for (const StudyOptionScope& scope : kStudyOptionScopes) {
        if (option != scope.option) continue;
        const std::string studies = scope.studies;
        const bool rotations = name == "rotations";
        const bool applies = studies == "rotations"    ? rotations
                             : studies == "registered" ? !rotations
                                                       : name == studies || name == "all";
        if (!applies) {
            throw InputError("rotbeam study: --" + option + " does not apply to study '" + name +
                             "' (only to " +
                             (studies == "rotations"    ? std::string("rotations")
                              : studies == "registered" ? std::string("every study but rotations")
                                                        : studies + " and all") +
                             ")");
        }
    }
}

void run_named_study(const std::string& name, const StudyOptions& o) {
    check_study_name(name);
    std::filesystem::create_directories(o.out_dir);  // only for a valid study: no stray output
    std::vector<std::string> chosen;
    for (const auto& entry : static_studies()) {
        if (name == "all" || name == entry.first) chosen.push_back(entry.first);
    }
    ProgressOptions options = progress_options_for_stderr();
    options.workers = 1;
    Progress progress("rotbeam study", chosen.size(), std::cerr, options);
    double cost = 0.0;
    for (const std::string& study : chosen) cost += whole_study_seconds(study, o.quick);
    progress.set_total_cost(cost);
    for (const std::string& study : chosen) {
        progress.started(study, whole_study_seconds(study, o.quick));
        run_study_whole(study, o);
        progress.finished(study);
    }
}

// Studies whose timings decide their results: run alone, after the others.
bool timed_study(const std::string& name) { return name == "speed-accuracy"; }

// Not run by the suite: the joined beam's 0–2 s sweep costs ~20 CPU-minutes (its references
// alone ~10), the formulations' agreement at converged Δt and mesh ~40; `rotbeam study NAME --out
// DIR` into the suite's folder puts its section into the report (report.cpp reads every
// registered study's file it finds).
bool standalone_study(const std::string& name) {
    return name == "joined-beam-dynamics" || name == "joined-beam-agreement";
}

std::string reference_group(const std::string& name) {
    return name == "joined-beam-dynamics" || name == "joined-beam-agreement" ? "joined-beam" : "";
}

const std::vector<std::pair<std::string, SplitStudy>>& split_studies() {
    static const std::vector<std::pair<std::string, SplitStudy>> table = {
        {"convergence", convergence_study()},
        {"singularity", singularity_study()},
        {"extremes", extremes_study()},
        {"effectivity", effectivity_study()},
    };
    return table;
}

void run_suite_studies(const StudyOptions& o, int jobs) {
    std::filesystem::create_directories(o.out_dir);
    // The suite's accuracy studies: the split ones as their runs, the others whole.
    std::vector<std::string> whole;
    std::vector<std::pair<std::string, SplitStudy>> split;
    for (const auto& entry : static_studies()) {
        if (timed_study(entry.first) || standalone_study(entry.first)) continue;
        const auto s = std::find_if(split_studies().begin(), split_studies().end(),
                                    [&](const auto& e) { return e.first == entry.first; });
        if (s != split_studies().end()) {
            split.push_back(*s);
        } else {
            whole.push_back(entry.first);
        }
    }
    // One worker pool: the whole studies first (each is long), then every run of every split
    // study; then each split study combines its runs' results.
    std::vector<std::vector<StudyRun>> plans;
    std::vector<std::pair<size_t, size_t>> items;  // (plan, run) of each pooled run
    for (const auto& [name, study] : split) {
        plans.push_back(study.plan(o));
        for (size_t r = 0; r < plans.back().size(); ++r) items.emplace_back(plans.size() - 1, r);
    }
    std::vector<std::vector<nlohmann::json>> results(plans.size());
    for (size_t p = 0; p < plans.size(); ++p) results[p].resize(plans[p].size());
    std::vector<std::string> timed;
    for (const auto& entry : static_studies()) {
        if (timed_study(entry.first)) timed.push_back(entry.first);
    }
    // Progress over every step: the pooled runs and whole studies, the combines, the timed ones,
    // each weighed by its expected time (priced first: the line starts with its total).
    std::vector<double> pooled_cost;
    for (const std::string& name : whole) pooled_cost.push_back(whole_study_seconds(name, o.quick));
    for (const auto& [p, r] : items) pooled_cost.push_back(study_run_seconds(plans[p][r]));
    double alone_cost = static_cast<double>(split.size()) * combine_step_seconds();
    for (const std::string& name : timed) alone_cost += whole_study_seconds(name, o.quick);
    ProgressOptions options = progress_options_for_stderr();
    options.workers = jobs;
    Progress progress("rotbeam suite: studies",
                      whole.size() + items.size() + split.size() + timed.size(), std::cerr,
                      options);
    progress.set_total_cost(std::accumulate(pooled_cost.begin(), pooled_cost.end(), 0.0),
                            alone_cost);
    // A whole study in the pool has one thread, as each of its neighbours.
    StudyOptions pooled = o;
    pooled.jobs = 1;
    for_each_parallel(whole.size() + items.size(), jobs, [&](size_t i) {
        if (i < whole.size()) {
            progress.started("study " + whole[i], pooled_cost[i]);
            run_study_whole(whole[i], pooled);
            progress.finished("study " + whole[i]);
        } else {
            const auto [p, r] = items[i - whole.size()];
            const std::string label = split[p].first + " " + plans[p][r].key;
            progress.started(label, pooled_cost[i]);
            results[p][r] = execute_run(plans[p][r]);
            progress.finished(label);
        }
    });
    for (size_t p = 0; p < split.size(); ++p) {
        const auto start = std::chrono::steady_clock::now();
        progress.started("combining " + split[p].first, combine_step_seconds(), true);
        split[p].second.combine(o, results_by_key(plans[p], std::move(results[p])));
        progress.finished("combining " + split[p].first);
        std::cout
            << "study " << split[p].first << " (" << plans[p].size()
            << " runs in the pool), combined in "
            << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()
            << " s → "
            << (std::filesystem::path(o.out_dir) / ("study-" + split[p].first + ".md")).string()
            << "\n";
    }
    // Run alone, a timed study may take every thread for its untimed work (its references).
    StudyOptions alone = o;
    alone.jobs = jobs;
    for (const std::string& name : timed) {
        progress.started("study " + name, whole_study_seconds(name, o.quick), true);
        run_study_whole(name, alone);
        progress.finished("study " + name);
    }
}

}  // namespace rotbeam::cli
