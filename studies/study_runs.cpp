#include "study_runs.hpp"

#include "core/errors.hpp"
#include "runs/parallel.hpp"

namespace rotbeam::cli {

nlohmann::json execute_run(const StudyRun& run) {
    switch (run.kind) {
        case StudyRun::Kind::case_run:
            return run_spec(run.spec);
        case StudyRun::Kind::estimated_case_run:
            return run_spec(run.spec, true);
        case StudyRun::Kind::continuum_reference:
            return continuum_reference(run.spec.case_name, run.spec.overrides);
    }
    ROTBEAM_VERIFY(false, "unknown StudyRun kind");
    return {};
}

StudyResults results_by_key(const std::vector<StudyRun>& plan,
                            std::vector<nlohmann::json> results) {
    ROTBEAM_VERIFY(results.size() == plan.size(), "study: one result per planned run");
    StudyResults by_key;
    for (size_t i = 0; i < plan.size(); ++i) {
        const bool unique = by_key.emplace(plan[i].key, std::move(results[i])).second;
        ROTBEAM_VERIFY(unique, "study plan: key used twice: " + plan[i].key);
    }
    return by_key;
}

StudyResults execute_runs(const std::vector<StudyRun>& plan, int jobs) {
    std::vector<nlohmann::json> results(plan.size());
    for_each_parallel(plan.size(), jobs, [&](size_t i) { results[i] = execute_run(plan[i]); });
    return results_by_key(plan, std::move(results));
}

const nlohmann::json& result_of(const StudyResults& results, const std::string& key) {
    const auto it = results.find(key);
    ROTBEAM_VERIFY(it != results.end(), "study: no run was planned for " + key);
    return it->second;
}

std::string spec_key(const RunSpec& spec) {
    std::string key =
        spec.case_name + "|" + spec.combination.label() + "|" + std::to_string(spec.elements);
    for (const std::string& o : spec.overrides) key += "|" + o;
    return key;
}

void plan_case_run(std::vector<StudyRun>& plan, const RunSpec& spec) {
    const std::string key = spec_key(spec);
    for (const StudyRun& run : plan) {
        if (run.key == key) return;
    }
    plan.push_back({key, StudyRun::Kind::case_run, spec});
}

const nlohmann::json& result_for(const StudyResults& results, const RunSpec& spec) {
    return result_of(results, spec_key(spec));
}

nlohmann::json run_split_study(const SplitStudy& study, const StudyOptions& o, int jobs) {
    return study.combine(o, execute_runs(study.plan(o), jobs));
}

}  // namespace rotbeam::cli
