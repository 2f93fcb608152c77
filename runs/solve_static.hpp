// The one path by which a run solves a static state and records it: the static analysis of
// `rotbeam run`, the static state a modal analysis is computed about and the static start of a
// dynamic analysis all call solve_static. It follows the load factors with the static driver
// (core/static_driver.hpp, or KINSOL when solver.driver asks for it) and, after each reported
// step, runs the observers the caller asks for (static_observers.hpp) on the state.
#pragma once

#include <cstddef>
#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

#include "core/kinematic_check.hpp"
#include "core/model.hpp"
#include "core/nodal_field.hpp"
#include "core/static_driver.hpp"
#include "core/static_state.hpp"

namespace rotbeam {

// What is recorded after each reported step.
struct StaticRecording {
    // A `steps` entry in the result (observe_points) ...
    bool steps = true;
    // ... with its `convergence` block and `centerline` (a static analysis's result).
    bool convergence = false;
    // The kinematic check (core/kinematic_check.hpp) before the step is recorded: the first step
    // that fails it stops the solve (StaticSolve::unresolved).
    bool kinematic_check = false;
    // Its `stability` (core/static_stability.hpp), or why it is not assessed.
    bool stability = false;
    // A snapshot of the node frames for the ParaView output, when a recorder is installed
    // (frame_recorder.hpp).
    bool frames = false;
    // The state as a field along the members (core/nodal_field.hpp), appended to path->states
    // with its load factor, when set and the formulation provides it: the warm start of another
    // discretization's run.
    SolvedPath* path = nullptr;
};

// The reported step that failed the kinematic check.
struct KinematicStop {
    std::size_t step = 0;  // index among the reported steps
    double load_factor = 0.0;
    KinematicDefect defect;
};

struct StaticSolve {
    // The driver's outcome; not meaningful when `unresolved` is set (the solve stopped there).
    StaticOutcome outcome;
    std::optional<KinematicStop> unresolved;
};

// Solves `problem` (built from `model`) along `load_factors` with the model's solver settings
// (`trace`: one line per Newton iteration on stderr) and appends what `recording` asks for to
// result["steps"]. Throws InputError for solver.driver: kinsol with a non-additive update.
// `start`, when given, is another discretization's solved path of the same model: each step whose
// load factor it holds starts from its state there (StaticProblem::start_from; the driver's
// StepGuess), the others from the last converged state.
StaticSolve solve_static(const Model& model, StaticProblem& problem,
                         const std::vector<double>& load_factors, const StaticRecording& recording,
                         bool trace, nlohmann::json& result, const SolvedPath* start = nullptr);

}  // namespace rotbeam
