// Running one case with one combination (parameterization × formulation × options) and producing
// the result JSON of docs/architecture.md. Used by `run`, `verify` and `suite`.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "core/model.hpp"
#include "core/nodal_field.hpp"

namespace rotbeam {

struct RunRequest {
    std::string case_path;      // for the record
    Model model;                // with every override already applied
    bool trace_newton = false;  // print the Newton iterations to stderr
    // Wall-clock limit in seconds (core/time_limit.hpp), 0 = none: past it the run stops with
    // the status `time-limit`.
    double time_limit_seconds = 0.0;
    // Warm start of a static analysis (core/nodal_field.hpp): `start`, another discretization's
    // solved path of the same model, gives each load step it holds its initial state; `path`,
    // when set, receives this run's solved states (the formulations that provide them).
    const SolvedPath* start = nullptr;
    SolvedPath* path = nullptr;
};

// Runs the analysis. Never throws for numerical failure: the status says it (`converged`,
// `diverged`, `singular`, `error`, or `kinematics-unresolved` when the mixed kinematic check
// stops a solved run, core/kinematic_check.hpp; `unstable-equilibrium` when a solved static step
// is an unstable equilibrium, core/static_stability.hpp). Throws InputError only for input the
// formulation refuses (e.g. a rigid section in the displacement formulation).
nlohmann::json run_case(const RunRequest& request);

// Adds the result's error estimate (docs/error-estimates.md): companion runs of the same request;
// statics and modes by estimates/estimate.hpp (modes paired across meshes by shape), dynamics by
// estimates/history_estimate.hpp (which may set the status `inaccurate`). Warm start of the static
// companions (docs/error-estimates.md, "Warm start of the companions"): when request.path holds the
// run's solved path (run_case recorded it) the first companion starts from it, and each further
// companion from the last one that solved every load step (solved_every_step).
void add_run_estimate(const RunRequest& request, nlohmann::json& result);

// Whether `path`, recorded by the run of `model` that gave `result`, holds a solved state at every
// load step: the warm start another discretization of the same model takes.
bool solved_every_step(const nlohmann::json& result, const SolvedPath& path, const Model& model);

// The `estimate` of a run with the estimate switched off.
nlohmann::json estimate_off();

}  // namespace rotbeam
