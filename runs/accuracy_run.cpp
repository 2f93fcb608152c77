#include "runs/accuracy_run.hpp"

#include <algorithm>
#include <map>
#include <memory>
#include <sstream>
#include <tuple>
#include <vector>

#include "core/errors.hpp"
#include "core/static_driver.hpp"
#include "estimates/accuracy_control.hpp"
#include "estimates/accuracy_scale.hpp"
#include "estimates/estimate.hpp"
#include "runs/mode_matching.hpp"

namespace rotbeam {

namespace {

// What tells two runs of one controlled case apart: the refinement changes only these
// (elements per member, order, sub-steps, the trapezoidal rule's refine).
using Key = std::tuple<std::vector<int>, int, int, int>;

Key key_of(const Model& model) {
    std::vector<int> elements;
    for (const Member& m : model.members) elements.push_back(m.elements);
    return {elements, model.discretization.order, model.analysis.statics.substeps,
            model.discretization.refine};
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

// Accuracy control of a dynamic run, in time only (docs/accuracy-control.md, Dynamics): the loader
// made analysis.time_tolerance = TOL/2, so the run takes adaptive steps for a global time error
// ≤ TOL/2; its estimate's Δt/2 companion (the run at TOL/8: tolerance/4) measures that error, and
// the result says whether it confirms it. The space error is estimated and reported, not
// controlled.
nlohmann::json run_dynamic_to_accuracy(const RunRequest& request) {
    const Model& model = request.model;
    const double tolerance = model.analysis.accuracy;
    const double target = 0.5 * tolerance;
    const double length = estimate::reference_length(model);
    nlohmann::json result = run_case(request);
    add_run_estimate(request, result);
    nlohmann::json acc = {
        {"tolerance", tolerance},
        {"target", target},
        {"strategy", "time only: adaptive steps with time_tolerance = TOL/2 on the case's mesh"},
        {"scales", {{"displacement", length}, {"rotation", 1.0}}},
        {"time_tolerance", model.analysis.dynamics.time_tolerance},
        {"solver_status", result.value("status", std::string("error"))}};
    // The worst time and space estimates over the named points' histories, in the scales above.
    double worst_time = -1.0, worst_space = -1.0;
    std::string worst_quantity;
    const nlohmann::json e = result.value("estimate", nlohmann::json::object());
    const nlohmann::json history = e.value("history", nlohmann::json::object());
    for (const auto& [point, quantities] : history.items()) {
        for (const auto& [quantity, h] : quantities.items()) {
            const double scale = quantity == "displacement" ? length : 1.0;
            const double t = h.value("max_time", 0.0) / scale;
            worst_space = std::max(worst_space, h.value("max_space", 0.0) / scale);
            if (t > worst_time) {
                worst_time = t;
                worst_quantity = point + " " + quantity;
            }
        }
    }
    std::string reason;
    if (!has_solution(acc["solver_status"].get<std::string>())) {
        reason = "the run did not finish: " + result.value("message", std::string());
    } else if (worst_time < 0.0) {
        reason = "the time estimate is missing: " + e.value("reason", std::string("no history"));
    } else if (worst_time > target) {
        std::ostringstream s;
        s.precision(3);
        s << "the dt/2 companion does not confirm the time tolerance: time error " << worst_time
          << " (" << worst_quantity << ") > " << target;
        reason = s.str();
    }
    if (worst_time >= 0.0) {
        acc["time_estimate"] = worst_time;
        acc["worst_quantity"] = worst_quantity;
        acc["space_estimate"] = worst_space;
        acc["confirmed"] = worst_time <= target;
    }
    acc["status"] = reason.empty() ? "reached" : "not-reached";
    if (!reason.empty()) {
        acc["reason"] = reason;
        if (has_solution(acc["solver_status"].get<std::string>())) {
            result["status"] = "accuracy-not-reached";
            result["message"] = "accuracy not reached: " + reason;
        }
    }
    result["accuracy"] = acc;
    return result;
}

}  // namespace

nlohmann::json run_to_accuracy(const RunRequest& request) {
    if (request.model.analysis.kind == AnalysisKind::dynamic) {
        return run_dynamic_to_accuracy(request);
    }
    estimate::AccuracyBudget budget;
    if (request.time_limit_seconds > 0.0) budget.seconds = request.time_limit_seconds;
    RunCache cache(request);
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
