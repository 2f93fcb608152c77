#include "runs/accuracy_run.hpp"

#include <map>
#include <memory>
#include <tuple>
#include <vector>

#include "core/errors.hpp"
#include "core/static_driver.hpp"
#include "estimates/accuracy_control.hpp"
#include "estimates/estimate.hpp"
#include "estimates/history_estimate.hpp"
#include "runs/mode_matching.hpp"

namespace rotbeam {

namespace {

// What tells two runs of one controlled case apart: the refinement and the companions change only
// these (elements per member, order, sub-steps, the trapezoidal rule's refine; in a dynamic
// analysis the adaptive steps' tolerance, IDA's tolerances and the output interval, which the
// time companion of adaptive steps halves: estimates/dynamic_companions.cpp).
using Key = std::tuple<std::vector<int>, int, int, int, double, double, double, double>;

Key key_of(const Model& model) {
    std::vector<int> elements;
    for (const Member& m : model.members) elements.push_back(m.elements);
    const DynamicSettings& d = model.analysis.dynamics;
    return {elements,
            model.discretization.order,
            model.analysis.statics.substeps,
            model.discretization.refine,
            d.time_tolerance,
            d.relative_tolerance,
            d.absolute_tolerance,
            d.output_interval};
}

std::vector<std::vector<double>> mode_stations(const nlohmann::json& modes) {
    std::vector<std::vector<double>> stations;
    for (const auto& m : modes) stations.push_back(m.value("stations", std::vector<double>()));
    return stations;
}

// Every run of the controlled case, companions included, by discretization: a refinement that
// lands on a companion's mesh (the p+1 order, the h/2 or h/4 mesh) takes its result instead of
// solving it again. Runs that threw (a model the formulation refuses) are not kept.
//
// Warm start (docs/accuracy-control.md, "Warm start"): each new static run starts every load step
// from the state of the last run that solved all of its steps, at the same load factor, evaluated
// on the new discretization (RunRequest::start). The first run starts from the undeformed beam.
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
        RunRequest request{request_.case_path, model, request_.trace_newton,
                           request_.time_limit_seconds};
        auto path = std::make_unique<SolvedPath>();
        request.start = warm_.get();
        request.path = path.get();
        nlohmann::json r = run_case(request);
        if (solved_every_step(r, *path, model)) warm_ = std::move(path);
        runs_[key] = r;
        return r;
    }

  private:
    const RunRequest& request_;
    std::map<Key, nlohmann::json> runs_;
    std::unique_ptr<SolvedPath> warm_;  // the last run that solved every load step
};

}  // namespace

nlohmann::json run_to_accuracy(const RunRequest& request) {
    estimate::AccuracyBudget budget;
    if (request.time_limit_seconds > 0.0) budget.seconds = request.time_limit_seconds;
    RunCache cache(request);
    if (request.model.analysis.kind == AnalysisKind::dynamic) {
        // The estimate as add_run_estimate makes it, its companions through the cache: the p+1
        // (or h/2) companion is the next attempt when only the mesh is refined, by one step. The
        // time companion is never an attempt: its outputs come twice as often.
        return estimate::control_dynamic_accuracy(
            request.model, request.model.analysis.accuracy, budget, [&](const Model& model) {
                bool reused = false;
                nlohmann::json result = cache.run(model, reused);
                estimate::add_dynamic_estimate(model, result, [&](const Model& companion) {
                    bool unused = false;
                    return cache.run(companion, unused);
                });
                result["reused"] = reused;
                return result;
            });
    }
    return estimate::control_accuracy(
        request.model, request.model.analysis.accuracy, budget,
        [&](const Model& model) {
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
        },
        estimate::coarse_start(request.model));
}

}  // namespace rotbeam
