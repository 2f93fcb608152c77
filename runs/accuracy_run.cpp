#include "runs/accuracy_run.hpp"

#include <map>
#include <tuple>
#include <vector>

#include "core/errors.hpp"
#include "estimates/accuracy_control.hpp"
#include "estimates/estimate.hpp"
#include "runs/mode_matching.hpp"

namespace rotbeam {

namespace {

// What tells two runs of one controlled case apart: the refinement changes only these.
using Key = std::tuple<std::vector<int>, int, int>;  // elements per member, order, sub-steps

Key key_of(const Model& model) {
    std::vector<int> elements;
    for (const Member& m : model.members) elements.push_back(m.elements);
    return {elements, model.discretization.order, model.analysis.statics.substeps};
}

std::vector<std::vector<double>> mode_stations(const nlohmann::json& modes) {
    std::vector<std::vector<double>> stations;
    for (const auto& m : modes) stations.push_back(m.value("stations", std::vector<double>()));
    return stations;
}

// Every run of the controlled case, companions included, by discretization: a refinement that
// lands on a companion's mesh (the p+1 order, the h/2 or h/4 mesh) takes its result instead of
// solving it again. Runs that threw (a model the formulation refuses) are not kept.
class RunCache {
  public:
    explicit RunCache(const RunRequest& request) : request_(request) {}

    nlohmann::json run(const Model& model, bool& reused) {
        const Key key = key_of(model);
        if (const auto it = runs_.find(key); it != runs_.end()) {
            reused = true;
            return it->second;
        }
        reused = false;
        nlohmann::json r = run_case(RunRequest{request_.case_path, model, request_.trace_newton,
                                               request_.time_limit_seconds});
        runs_[key] = r;
        return r;
    }

  private:
    const RunRequest& request_;
    std::map<Key, nlohmann::json> runs_;
};

}  // namespace

nlohmann::json run_to_accuracy(const RunRequest& request) {
    estimate::AccuracyBudget budget;
    if (request.time_limit_seconds > 0.0) budget.seconds = request.time_limit_seconds;
    RunCache cache(request);
    return estimate::control_accuracy(
        request.model, request.model.analysis.accuracy, budget, [&](const Model& model) {
            bool reused = false;
            nlohmann::json result = cache.run(model, reused);
            // The estimate as add_run_estimate makes it, its companions through the cache.
            estimate::add_estimate(
                model, result,
                [&](const Model& companion) {
                    bool unused = false;
                    return cache.run(companion, unused);
                },
                [](const nlohmann::json& modes, const nlohmann::json& companion) {
                    return match_modes(mode_stations(modes), mode_stations(companion), kMatchMac);
                });
            result["reused"] = reused;
            return result;
        });
}

}  // namespace rotbeam
