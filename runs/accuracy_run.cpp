#include "runs/accuracy_run.hpp"

#include <algorithm>
#include <chrono>
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
// time companion of adaptive steps halves, and the fixed step, which a dt/2 or 2dt companion
// changes alone: estimates/dynamic_companions.cpp).
using Key = std::tuple<std::vector<int>, int, int, int, double, double, double, double, double>;

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
            d.output_interval,
            d.time_step};
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
//
// The budget's time is a limit on the whole control, not on each run: every run, companions
// included, gets the wall time the budget has left as its own limit (core/time_limit.hpp), so an
// attempt that would outlast the budget stops at it with the status `time-limit` (never cached:
// it has no numbers), and the control says so (estimates/accuracy_control.cpp).
class RunCache {
  public:
    RunCache(const RunRequest& request, double budget_seconds)
        : request_(request),
          deadline_(Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                       std::chrono::duration<double>(budget_seconds))) {}

    nlohmann::json run(const Model& model, bool& reused) {
        const Key key = key_of(model);
        if (const auto it = runs_.find(key); it != runs_.end()) {
            reused = true;
            return it->second;
        }
        reused = false;
        RunRequest request{request_.case_path, model, request_.trace_newton, time_left()};
        auto path = std::make_unique<SolvedPath>();
        request.start = warm_.get();
        request.path = path.get();
        nlohmann::json r = run_case(request);
        if (r.value("status", std::string()) == "time-limit") return r;
        if (solved_every_step(r, *path, model)) warm_ = std::move(path);
        runs_[key] = r;
        return r;
    }

  private:
    using Clock = std::chrono::steady_clock;
    // A run started with the budget spent still gets a limit (a limit ≤ 0 would mean none): it
    // stops at its first check.
    static constexpr double kSpentLimitSeconds = 1e-6;

    double time_left() const {
        const double left = std::chrono::duration<double>(deadline_ - Clock::now()).count();
        return std::max(left, kSpentLimitSeconds);
    }

    const RunRequest& request_;
    Clock::time_point deadline_;
    std::map<Key, nlohmann::json> runs_;
    std::unique_ptr<SolvedPath> warm_;  // the last run that solved every load step
};

}  // namespace

nlohmann::json run_to_accuracy(const RunRequest& request) {
    estimate::AccuracyBudget budget;
    if (request.time_limit_seconds > 0.0) budget.seconds = request.time_limit_seconds;
    RunCache cache(request, budget.seconds);
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
