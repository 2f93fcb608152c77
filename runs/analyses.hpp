// The dynamic and modal analyses of each formulation, called by run_case. Each
// file that defines them holds that formulation's parameterization switch for its analyses (as
// make_problem.cpp does for statics), so nothing below dispatches on the parameterization.
//
// Each function fills the result JSON (docs/architecture.md) (run_case has written the header):
//   `dofs`, `status` (converged | stalled-at-round-off | diverged | singular | error; modal also
//   eigenpair-check-failed; mixed also kinematics-unresolved), `message`, `counters`;
//   dynamic: `steps`, one per output time, built with step_json(model, nullopt, t, iterations, …)
//            (run writes the CSV time history from them);
//   modal:   `modes` (model.analysis.modal.modes of them, lowest first; per mode: `s` [Re, Im]
//            of the oscillation e^{st}, `growth_rate`, `check` (modal_checks.hpp), `frequency_hz`
//            only when the check accepted the pair, `points`: each named point's displacement [3]
//            and rotation [3] amplitude, normalized to a largest component of 1, and `stations`
//            (mode_matching.hpp)), `frequencies_hz` (the accepted ones; all of them when the
//            status is `converged`, else the status is `eigenpair-check-failed`), and `steps`
//            holding the static state the modes are computed about (if loaded).
// Numerical failure is a status, never an exception; bad input throws InputError; a singular
// parameterization throws SingularityError (run_case turns it into status `singular`).
// `available: false` with status `error` says the analysis does not exist in the formulation.
#pragma once

#include <nlohmann/json.hpp>

#include "core/model.hpp"
#include "core/static_driver.hpp"

namespace rotbeam {

// runs/run_displacement_dynamics.cpp
void run_displacement_dynamic(const Model& model, bool trace, nlohmann::json& result);
void run_displacement_modal(const Model& model, bool trace, nlohmann::json& result);

// runs/run_mixed_dynamics.cpp
void run_mixed_dynamic(const Model& model, bool trace, nlohmann::json& result);
void run_mixed_modal(const Model& model, bool trace, nlohmann::json& result);

// The static state a dynamic or modal analysis starts from (runs/run_case.cpp): a failure
// sets the run's status and message ("static state: …") and returns false; a state stalled at
// round-off is kept (`static_state` in the result) and set_analysis_status carries it over.
bool static_state_usable(const StaticOutcome& out, nlohmann::json& result);
// The analysis's status and message, except that a converged analysis about a static state that
// stalled at round-off reports stalled-at-round-off, with the static state's message appended.
void set_analysis_status(nlohmann::json& result, SolveStatus status, const std::string& message);

// What a formulation without the analysis reports (not a solver failure: `verify` counts the
// references it would check as unavailable).
void report_unavailable(const Model& model, nlohmann::json& result);

}  // namespace rotbeam
