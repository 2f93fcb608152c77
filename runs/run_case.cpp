#include "run_case.hpp"

#include <chrono>
#include <iostream>
#include <optional>
#include <sstream>

#include "analyses.hpp"
#include "combinations/registry.hpp"
#include "core/beam_rotation.hpp"
#include "core/errors.hpp"
#include "core/kinematic_check.hpp"
#include "core/kinsol_driver.hpp"
#include "core/results.hpp"
#include "core/static_driver.hpp"
#include "core/time_limit.hpp"
#include "core/version.hpp"
#include "estimates/estimate.hpp"
#include "estimates/history_estimate.hpp"
#include "make_problem.hpp"
#include "mode_matching.hpp"

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
    }
    return "automatic";
}

nlohmann::json result_header(const RunRequest& request) {
    const Model& m = request.model;
    const Discretization& d = m.discretization;
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
            {"options",
             {{"interpolation", choice_name(d.interpolation)},
              {"update", choice_name(d.update)},
              {"rescale", d.rescale},
              {"wm_map", choice_name(d.wm_map)},
              {"quadrature", quadrature_name(d.quadrature)},
              {"quadrature_points", d.quadrature_points},
              {"mass_rule", d.mass_rule},
              {"driver", choice_name(m.solver.driver)},
              {"residual_tolerance", m.solver.residual_tolerance},
              {"increment_tolerance", m.solver.increment_tolerance},
              {"assemble_all_terms", m.solver.assemble_all_terms}}},
            {"steps", nlohmann::json::array()}};
}

// The deformed centre line of a reported step, for shape plots (kept to small meshes: the result
// file stays small for the studies' refined runs).
void add_centerline(const StaticProblem& problem, nlohmann::json& step) {
    constexpr size_t kMaxPoints = 2000;
    const std::vector<StaticProblem::CenterlinePoint> line = problem.centerline();
    if (line.empty() || line.size() > kMaxPoints) return;
    nlohmann::json points = nlohmann::json::array();
    for (const StaticProblem::CenterlinePoint& p : line) {
        points.push_back({p.member, p.position[0], p.position[1], p.position[2]});
    }
    step["centerline"] = points;  // [member, x, y, z] per node
}

// Section resultants of the last converged state, per member, ordered by arc length.
nlohmann::json sections_json(const Model& model, double load_factor,
                             const std::vector<SectionResultants>& sections) {
    auto vec = [](const Vec3& v) { return nlohmann::json::array({v[0], v[1], v[2]}); };
    nlohmann::json stations = nlohmann::json::array();
    for (const SectionResultants& r : sections) {
        stations.push_back({{"member", model.members[static_cast<size_t>(r.member)].name},
                            {"s", r.s},
                            {"force", vec(r.force)},
                            {"moment", vec(r.moment)},
                            {"force_material", vec(r.force_material)},
                            {"moment_material", vec(r.moment_material)}});
    }
    return {{"load_factor", load_factor}, {"stations", stations}};
}

// How the reported state of a load step was accepted (core/convergence.hpp): the criterion, the
// scaled residual, the bound on the scaled algebraic error, and the expected round-off floor when
// the last solve computed it (it does when the final correction was computed).
nlohmann::json convergence_json(const StepRecord& step) {
    nlohmann::json c = {{"criterion", to_string(step.criterion)},
                        {"scaled_residual", step.scaled_residual},
                        {"error_bound", step.error_bound}};
    if (step.round_off_floor > 0.0) c["round_off_floor"] = step.round_off_floor;
    return c;
}

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

// Thrown out of run_static's step callback when a reported step fails the kinematic check
// (core/kinematic_check.hpp): the run stops there, as it does when Newton fails.
struct KinematicsUnresolved {
    std::string message;
};

// The kinematic check of a reported step: throws KinematicsUnresolved naming the step, the load
// factor, the element and the angles.
void check_kinematics(const Model& model, const StaticProblem& problem, std::size_t step,
                      double load_factor) {
    const std::optional<KinematicDefect> worst =
        worst_kinematic_defect(problem.rotation_stations());
    if (!worst || within_kinematic_bound(*worst)) return;
    std::ostringstream s;
    s.precision(6);
    s << "the discrete kinematics do not describe the beam at load step " << step + 1
      << " (load factor " << load_factor << "): " << describe_kinematic_defect(model, *worst)
      << "; the equations are solved, the answer is not trustworthy (refine the mesh or use a "
         "parameterization whose elements resolve the rotation)";
    throw KinematicsUnresolved{s.str()};
}

void run_static_case(const Model& model, bool trace, nlohmann::json& result) {
    std::unique_ptr<StaticProblem> problem = make_static_problem(model);
    result["dofs"] = problem->size();
    std::vector<PointState> states(model.points.size());
    NewtonSettings settings = newton_settings_from(model.solver, model.analysis.statics);
    if (trace) settings.trace = &std::cerr;
    StepSolver solver;
    if (model.solver.driver == Driver::kinsol) {
        if (!problem->additive()) {
            throw InputError(
                "solver.driver: kinsol needs an additive update (the mixed "
                "formulation); this combination composes rotations");
        }
        solver = kinsol_step_solver;
    }
    std::optional<StaticOutcome> solved;
    try {
        solved = run_static(
            *problem, model.analysis.statics.load_factors, settings,
            [&](const StepRecord& step) {
                check_kinematics(model, *problem, result["steps"].size(), step.load_factor);
                for (size_t i = 0; i < model.points.size(); ++i) {
                    states[i] = problem->point_state(static_cast<int>(i));
                }
                const std::vector<Vec3> continued =
                    rotation_vectors_along_beam(model, problem->rotation_stations(), states);
                result["steps"].push_back(step_json(model, step.load_factor, std::nullopt,
                                                    step.newton_iterations, states, continued));
                result["steps"].back()["convergence"] = convergence_json(step);
                add_centerline(*problem, result["steps"].back());
            },
            solver);
    } catch (const KinematicsUnresolved& e) {
        result["status"] = kKinematicsUnresolved;
        result["message"] = e.message;
        result["counters"] = counters_json(problem->counters());
        return;
    }
    const StaticOutcome& outcome = *solved;
    result["status"] = to_string(outcome.status);
    result["message"] = outcome.message;
    result["counters"] = counters_json(problem->counters());
    if (!outcome.steps.empty()) {
        const std::vector<SectionResultants> sections = problem->section_resultants();
        if (!sections.empty()) {
            result["section_resultants"] =
                sections_json(model, outcome.last_converged_load_factor, sections);
        }
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

void add_run_estimate(const RunRequest& request, nlohmann::json& result) {
    const estimate::CompanionRun companion_run = [&](const Model& companion) {
        return run_case(
            RunRequest{request.case_path, companion, false, request.time_limit_seconds});
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
                run_static_case(model, request.trace_newton, result);
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
    if (!all_finite(result)) {
        // A result never prints NaN: drop the numbers, say what happened.
        result["status"] = "error";
        result["message"] =
            "non-finite values in the solution (" + result["message"].get<std::string>() + ")";
        result["steps"] = nlohmann::json::array();
    }
    return result;
}

}  // namespace rotbeam
