#include "solve_static.hpp"

#include <iostream>

#include "core/errors.hpp"
#include "core/kinsol_driver.hpp"
#include "frame_recorder.hpp"
#include "static_observers.hpp"

namespace rotbeam {

namespace {

// KINSOL (line search, scaling, KLU) in place of the in-house Newton, for additive systems.
NewtonOutcome kinsol_step_solver(NonlinearSystem& system, const NewtonSettings& settings) {
    KinsolSettings k;
    k.residual_tolerance = settings.residual_tolerance;
    k.increment_tolerance = settings.increment_tolerance;
    k.max_iterations = settings.max_iterations;
    k.line_search = settings.line_search;
    const KinsolOutcome o = solve_kinsol(system, k);
    NewtonOutcome out;
    out.converged = o.converged;
    out.criterion = o.criterion;
    out.error_bound = o.error_bound;
    out.round_off_floor = o.round_off_floor;
    out.iterations = static_cast<int>(o.iterations);
    out.scaled_residual = o.scaled_residual;
    out.singular = o.singular;
    out.failure = o.failure;
    return out;
}

// Thrown out of run_static's step callback when a reported step fails the kinematic check: the
// solve stops there, as it does when Newton fails.
struct KinematicsUnresolved {
    KinematicStop stop;
};

}  // namespace

StaticSolve solve_static(const Model& model, StaticProblem& problem,
                         const std::vector<double>& load_factors, const StaticRecording& recording,
                         bool trace, nlohmann::json& result, const SolvedPath* start) {
    NewtonSettings settings = newton_settings_from(model.solver, model.analysis.statics);
    if (trace) settings.trace = &std::cerr;
    StepSolver solver;
    if (model.solver.driver == Driver::kinsol) {
        if (!problem.additive()) {
            throw InputError(
                "solver.driver: kinsol needs an additive update (the mixed "
                "formulation); this combination composes rotations");
        }
        solver = kinsol_step_solver;
    }
    std::string not_assessed;
    if (recording.stability) {
        not_assessed = stability_not_assessed(model);
        settings.assess_stability = not_assessed.empty();
    }
    StaticSolve solve;
    std::size_t reported = 0;
    const auto on_step = [&](const StepRecord& step) {
        const std::size_t index = reported++;
        if (recording.kinematic_check) {
            if (const std::optional<KinematicDefect> defect =
                    observe_unresolved_kinematics(problem)) {
                throw KinematicsUnresolved{{index, step.load_factor, *defect}};
            }
        }
        if (recording.path) {
            if (std::optional<NodalField> field = problem.nodal_field()) {
                recording.path->load_factors.push_back(step.load_factor);
                recording.path->states.push_back(std::move(*field));
            }
        }
        if (!recording.steps) return;
        nlohmann::json entry = observe_points(model, problem, step);
        if (recording.convergence) {
            entry["convergence"] = observe_convergence(step);
            if (std::optional<nlohmann::json> line = observe_centerline(problem)) {
                entry["centerline"] = std::move(*line);
            }
        }
        if (recording.stability) entry["stability"] = observe_stability(step, not_assessed);
        result["steps"].push_back(std::move(entry));
        if (recording.frames) record_frames(problem);
    };
    StepGuess guess;
    if (start) {
        guess = [&](std::size_t step) {
            return step < start->states.size() && start->load_factors[step] == load_factors[step] &&
                   problem.start_from(start->states[step]);
        };
    }
    try {
        solve.outcome = run_static(problem, load_factors, settings, on_step, solver, guess);
    } catch (const KinematicsUnresolved& e) {
        solve.unresolved = e.stop;
    }
    return solve;
}

}  // namespace rotbeam
