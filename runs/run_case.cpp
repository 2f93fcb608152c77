#include "run_case.hpp"

#include <chrono>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>

#include "analyses.hpp"
#include "combinations/registry.hpp"
#include "core/dae_driver.hpp"
#include "core/errors.hpp"
#include "core/kinematic_check.hpp"
#include "core/non_finite.hpp"
#include "core/results.hpp"
#include "core/static_driver.hpp"
#include "core/static_stability.hpp"
#include "core/time_limit.hpp"
#include "core/version.hpp"
#include "estimates/estimate.hpp"
#include "estimates/history_estimate.hpp"
#include "make_problem.hpp"
#include "mode_matching.hpp"
#include "solve_static.hpp"
#include "static_observers.hpp"

namespace rotbeam {

namespace {

const char* quadrature_name(Quadrature q) {
    switch (q) {
        case Quadrature::automatic:
            return "automatic";
        case Quadrature::reduced:
            return "reduced";
        case Quadrature::full:
            return "full";
        case Quadrature::gll:
            return "gll";
        case Quadrature::trapezoidal:
            return "trapezoidal";
    }
    return "automatic";
}

nlohmann::json result_header(const RunRequest& request) {
    const Model& m = request.model;
    const Discretization& d = m.discretization;
    const NewtonSettings newton = step_newton_settings(m);
    int elements = 0;
    nlohmann::json per_member = nlohmann::json::object();
    for (const Member& member : m.members) {
        elements += member.elements;
        per_member[member.name] = member.elements;
    }
    return {{"case", m.name},
            {"case_file", request.case_path},
            {"rotation", param::name_of(d.rotation)},
            {"formulation", choice_name(d.formulation)},
            {"elements", elements},
            {"elements_per_member", per_member},
            {"order", d.order},
            {"dofs", 0},
            {"status", "error"},
            {"message", ""},
            {"wall_seconds", 0.0},
            {"version", kGitDescribe},
            {"schema_version", kSchemaVersion},
            {"options",
             {{"interpolation", choice_name(d.displacement.interpolation)},
              {"update", choice_name(d.displacement.update)},
              {"rescale", d.displacement.rescale},
              {"wm_map", choice_name(d.mixed.wm_map)},
              {"quadrature", quadrature_name(d.quadrature)},
              {"quadrature_points", d.quadrature_points},
              {"mass_rule", choice_name(d.mass_rule())},
              {"driver", choice_name(m.solver.driver)},
              {"residual_tolerance", newton.residual_tolerance},
              {"increment_tolerance", newton.increment_tolerance},
              {"assemble_all_terms", m.solver.assemble_all_terms}}},
            {"steps", nlohmann::json::array()}};
}

// The kinematic check's stop of a static analysis: the message names the step, the load factor,
// the element and the angles.
std::string kinematics_message(const Model& model, const KinematicStop& stop) {
    std::ostringstream s;
    s.precision(6);
    s << "the discrete kinematics do not describe the beam at load step " << stop.step + 1
      << " (load factor " << stop.load_factor
      << "): " << describe_kinematic_defect(model, stop.defect)
      << "; the equations are solved, the answer is not trustworthy (refine the mesh or use a "
         "parameterization whose elements resolve the rotation)";
    return s.str();
}

// The first reported step whose equilibrium is unstable: the run's status says so (the answer is
// an equilibrium no loaded beam would stay in), followed by the solver's message.
void report_unstable_equilibrium(const StaticOutcome& outcome, nlohmann::json& result) {
    for (std::size_t i = 0; i < outcome.steps.size(); ++i) {
        const StepRecord& step = outcome.steps[i];
        if (step.stability.assessment != StaticStability::Assessment::unstable) continue;
        std::ostringstream s;
        s.precision(6);
        s << "the equilibrium at load step " << i + 1 << " (load factor " << step.load_factor
          << ") is unstable: ";
        if (const std::optional<KineticSummary>& k = step.stability.kinetic) {
            s << "its linearized free motion has " << k->divergent << " divergent and "
              << k->fluttering << " fluttering mode(s), growth rate up to " << k->growth_rate
              << " 1/time (error " << k->growth_rate_error << ")";
        } else {
            s << "its tangent has " << step.stability.negative
              << " negative eigenvalue(s), directions in which the energy decreases";
        }
        s << "; " << result["status"].get<std::string>() << ": "
          << result["message"].get<std::string>();
        result["status"] = kUnstableEquilibrium;
        result["message"] = s.str();
        return;
    }
}

void run_static_case(const RunRequest& request, nlohmann::json& result) {
    const Model& model = request.model;
    std::unique_ptr<StaticProblem> problem = make_static_problem(model);
    result["dofs"] = problem->size();
    const StaticRecording recording{.steps = true,
                                    .convergence = true,
                                    .kinematic_check = true,
                                    .stability = true,
                                    .frames = true,
                                    .path = request.path};
    const StaticSolve solve = solve_static(model, *problem, model.analysis.statics.load_factors,
                                           recording, request.trace_newton, result, request.start);
    result["counters"] = counters_json(problem->counters());
    if (solve.unresolved) {
        result["status"] = kKinematicsUnresolved;
        result["message"] = kinematics_message(model, *solve.unresolved);
        return;
    }
    const StaticOutcome& outcome = solve.outcome;
    result["status"] = to_string(outcome.status);
    result["message"] = outcome.message;
    if (has_solution(outcome.status)) report_unstable_equilibrium(outcome, result);
    if (outcome.steps.empty()) return;
    if (std::optional<nlohmann::json> sections =
            observe_sections(model, *problem, outcome.last_converged_load_factor)) {
        result["section_resultants"] = std::move(*sections);
    }
}

}  // namespace

namespace {

// Every mode's `stations`, for pairing modes across meshes by shape.
std::vector<std::vector<double>> mode_stations(const nlohmann::json& modes) {
    std::vector<std::vector<double>> stations;
    for (const auto& m : modes) stations.push_back(m.value("stations", std::vector<double>()));
    return stations;
}

}  // namespace

bool solved_every_step(const nlohmann::json& result, const SolvedPath& path, const Model& model) {
    return has_solution(result.value("status", std::string())) && !path.states.empty() &&
           path.states.size() == model.analysis.statics.load_factors.size();
}

void add_run_estimate(const RunRequest& request, nlohmann::json& result) {
    // The companions run in the plan's order (p+1, then p+2): each starts from the last solved
    // path of the chain. Formulations that record no path (mixed) and analyses that take no start
    // (modal, dynamic) run as without it.
    const SolvedPath* start =
        request.path && solved_every_step(result, *request.path, request.model) ? request.path
                                                                                : nullptr;
    std::unique_ptr<SolvedPath> warm;
    const estimate::CompanionRun companion_run = [&](const Model& companion) {
        auto path = std::make_unique<SolvedPath>();
        RunRequest r{request.case_path, companion, false, request.time_limit_seconds};
        r.start = start;
        r.path = path.get();
        nlohmann::json out = run_case(r);
        if (solved_every_step(out, *path, companion)) {
            warm = std::move(path);
            start = warm.get();
        }
        return out;
    };
    if (request.model.analysis.kind == AnalysisKind::dynamic) {
        estimate::add_dynamic_estimate(request.model, result, companion_run);
        return;
    }
    estimate::add_estimate(request.model, result, companion_run,
                           [](const nlohmann::json& modes, const nlohmann::json& companion) {
                               return match_modes(mode_stations(modes), mode_stations(companion),
                                                  kMatchMac);
                           });
}

nlohmann::json estimate_off() { return estimate::estimate_off(); }

bool static_state_usable(const StaticOutcome& out, nlohmann::json& result) {
    if (out.status == SolveStatus::stalled_at_round_off) {
        result["static_state"] = {{"status", to_string(out.status)}, {"message", out.message}};
    }
    if (has_solution(out.status)) return true;
    result["status"] = to_string(out.status);
    result["message"] = "static state: " + out.message;
    return false;
}

void set_analysis_status(nlohmann::json& result, SolveStatus status, const std::string& message) {
    result["status"] = to_string(status);
    result["message"] = message;
    if (status == SolveStatus::converged && result.contains("static_state")) {
        result["status"] = result["static_state"]["status"];
        result["message"] =
            message + "; static state: " + result["static_state"]["message"].get<std::string>();
    }
}

void report_unavailable(const Model& model, nlohmann::json& result) {
    result["available"] = false;
    result["status"] = "error";
    result["message"] =
        std::string(model.analysis.kind == AnalysisKind::dynamic ? "dynamic" : "modal") +
        " analysis is not available yet in the " +
        std::string(choice_name(model.discretization.formulation)) + " formulation";
}

nlohmann::json run_case(const RunRequest& request) {
    const Model& model = request.model;
    nlohmann::json result = result_header(request);
    const auto start = std::chrono::steady_clock::now();
    try {
        const ScopedTimeLimit limit(request.time_limit_seconds);
        switch (model.analysis.kind) {
            case AnalysisKind::static_:
                run_static_case(request, result);
                break;
            case AnalysisKind::dynamic:
                if (!comb::traits(model.discretization.formulation).dynamics) {
                    report_unavailable(model, result);
                    break;
                }
                switch (model.discretization.formulation) {
                    case Formulation::displacement:
                        run_displacement_dynamic(model, request.trace_newton, result);
                        break;
                    case Formulation::mixed:
                        run_mixed_dynamic(model, request.trace_newton, result);
                        break;
                }
                break;
            case AnalysisKind::modal:
                if (!comb::traits(model.discretization.formulation).modal) {
                    report_unavailable(model, result);
                    break;
                }
                switch (model.discretization.formulation) {
                    case Formulation::displacement:
                        run_displacement_modal(model, request.trace_newton, result);
                        break;
                    case Formulation::mixed:
                        run_mixed_modal(model, request.trace_newton, result);
                        break;
                }
                break;
        }
    } catch (const SingularityError& e) {
        result["status"] = "singular";
        result["message"] = e.what();
    } catch (const SolverError& e) {
        result["status"] = "error";
        result["message"] = e.what();
    } catch (const TimeLimitReached& e) {
        // Stopped on purpose: what was computed is not an answer, so nothing of it is kept.
        result["status"] = "time-limit";
        result["message"] = e.what();
        result["steps"] = nlohmann::json::array();
    } catch (const InputError& e) {
        // A model the formulation refuses (a rigid section in the displacement formulation): the
        // one-line message names the case file like every other input error.
        const std::string m = e.what();
        if (request.case_path.empty() || m.rfind(request.case_path, 0) == 0) throw;
        throw InputError(request.case_path + ": (model): " + m);
    }
    result["wall_seconds"] =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (const std::string where = first_non_finite(result); !where.empty()) {
        // A result never prints NaN: drop the numbers, say what happened and where it showed.
        result["status"] = "error";
        result["message"] = "non-finite values in the solution, first at " + where + " (" +
                            result["message"].get<std::string>() + ")";
        result["steps"] = nlohmann::json::array();
    }
    return result;
}

}  // namespace rotbeam
