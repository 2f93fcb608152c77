// Accuracy control (docs/accuracy-control.md): refine a static or modal run's discretization
// until every reported quantity's estimated error is at most half the asked tolerance, relative
// to its scale (estimates/accuracy_scale.hpp), or say plainly why it cannot be reached.
//
//   displacement formulation: raise the order p while the estimates decay spectrally (each order
//     divides the worst estimate by 1/ρ ≥ 2, and the order that reaches the target is predicted
//     from ρ), else split every element, the count predicted from the nodal h-rate 2p; with the
//     trapezoidal quadrature every such step also doubles refine (per order added), as the
//     estimate's p+1 companion does, and refine stays ≥ twice the order;
//   mixed formulation: split every element, the count predicted from the observed order;
//   either: a Newton failure at a load step doubles the sub-steps; a kinematic check that fails
//     splits the elements.
// It stops with `accuracy-not-reached` and the reason when the run is singular or fails in
// another way, when the estimates stagnate (a round-off floor above TOL/10), when the estimate is
// missing or not reliable after the budget, or at the budget (attempts, elements, order, time).
#pragma once

#include <functional>
#include <nlohmann/json.hpp>
#include <optional>

#include "core/model.hpp"

namespace rotbeam::estimate {

// analysis.accuracy / run --accuracy: 1e-12 ≤ TOL < 1. Below 1e-12 the target TOL/2 lies under
// the solves' own round-off (the Newton acceptance bounds the scaled algebraic error near 1e-12,
// docs/solver-convergence.md); 1 asks for nothing.
inline constexpr double kMinAccuracy = 1e-12;
inline constexpr double kMaxAccuracy = 1.0;  // exclusive

// The budget of one controlled run (docs/accuracy-control.md, "Budget").
struct AccuracyBudget {
    int attempts = 12;  // runs, each with its estimate
    // Elements per member of the run itself: the mixed h/4 companion then has 4 × this.
    int elements_per_member = 4096;
    // The run's order: its p+1 companion is one more, within the case format's 24. Past ~12 the
    // p-sequence of docs/studies.md is at round-off on two elements.
    int order = 16;
    // Trapezoidal quadrature: the run's refine; its p+1 companion doubles it, within the case
    // format's 1000.
    int refine = 500;
    int substeps_factor = 64;  // the case's sub-steps doubled at most 6 times
    // Dynamics: the adaptive steps' time tolerance divided by at most this in all.
    double time_tolerance_factor = 4096.0;
    double seconds = 600.0;  // total wall time; `run --time-limit` replaces it
};

// Runs a model and adds its estimate (the program's run_case and add_run_estimate). A result
// taken from an earlier run (a companion's) may say so with `reused: true` (removed here).
using EstimatedRun = std::function<nlohmann::json(const Model&)>;

// Refines `model` until its estimates meet tolerance / 2 or it says why not. Returns the last
// attempt's result with `accuracy` added (docs/accuracy-control.md, "Fields"); its status is the
// run's own when the target is met, else `accuracy-not-reached` with the reason as message.
//
// `start`, when given, is the first discretization tried instead of the case's (coarse_start);
// a run from it that does not solve or cannot be estimated moves once to the case's own
// discretization, said in that attempt's `next`, instead of stopping.
nlohmann::json control_accuracy(const Model& model, double tolerance, const AccuracyBudget& budget,
                                const EstimatedRun& run,
                                const std::optional<Model>& start = std::nullopt);

// The accuracy control of a dynamic run (docs/accuracy-control.md, "Dynamics"): the target
// tolerance / 2 split in halves between the mesh and the time step. Each attempt's estimate
// (space and time parts of every history, over its amplitude) decides what to refine: the mesh as
// for the statics (the displacement formulation's order while spectral, else its elements; the
// mixed formulation's elements) when the space part exceeds its half or is not reliable, and the
// adaptive steps' analysis.dynamics.time_tolerance (which the loader set to tolerance / 4) when the
// time part does. Starts from the case's own discretization. Stops as control_accuracy does, and
// also when the run itself stops (its status and message name the step and the time).
nlohmann::json control_dynamic_accuracy(const Model& model, double tolerance,
                                        const AccuracyBudget& budget, const EstimatedRun& run);

// The start of the displacement formulation's controlled run (docs/accuracy-control.md, "Cost"):
// one element per member at order max(the case's, 6), whatever the case's mesh. Below order 6
// the control raises p regardless (a coarse p-sequence is not yet spectral), so a lower start
// only adds attempts. With the trapezoidal quadrature refine is at least twice that order
// (docs/accuracy-control.md, "Trapezoidal quadrature").
// The mixed formulation starts from the case's mesh (returned unchanged).
Model coarse_start(const Model& model);

}  // namespace rotbeam::estimate
