// Dynamic and modal analyses of the displacement formulation (analyses.hpp). This file
// holds the parameterization switch for them, as make_problem.cpp does for statics.
#include <cmath>
#include <iostream>

#include "analyses.hpp"
#include "combinations/registry.hpp"
#include "core/beam_rotation.hpp"
#include "core/errors.hpp"
#include "core/gauss_collocation.hpp"
#include "core/generalized_alpha.hpp"
#include "core/results.hpp"
#include "core/so3.hpp"
#include "core/static_driver.hpp"
#include "estimates/accuracy_scale.hpp"
#include "formulations/displacement/displacement_dynamics.hpp"
#include "formulations/displacement/displacement_modal.hpp"
#include "formulations/displacement/displacement_statics.hpp"
#include "formulations/displacement/gyroscopic_modal.hpp"
#include "formulations/mixed/mixed_modal.hpp"
#include "frame_recorder.hpp"
#include "modal_checks.hpp"
#include "mode_matching.hpp"
#include "parameterizations/registry.hpp"
#include "solve_static.hpp"
#include "step_control_json.hpp"

namespace rotbeam {

namespace {

bool has_static_load(const Model& m) {
    return !m.point_loads.empty() || !m.distributed_loads.empty() ||
           m.gravity.squaredNorm() > 0.0 || m.rotating_frame.active();
}

nlohmann::json vec3(const Eigen::Ref<const VecX>& v) {
    return nlohmann::json::array({v[0], v[1], v[2]});
}

// Named points' displacement and rotation amplitudes of one mode, largest component 1.
nlohmann::json mode_json(const Model& model, const form::Mesh& mesh, const VecX& shape,
                         double frequency_hz) {
    const double peak = shape.cwiseAbs().maxCoeff();
    const VecX v = peak > 0.0 ? VecX(shape / peak) : shape;
    nlohmann::json points = nlohmann::json::object();
    for (size_t i = 0; i < model.points.size(); ++i) {
        const int node = mesh.point_node[i];
        const int dof = node < 0 ? -1 : mesh.nodes[static_cast<size_t>(node)].dof;
        const VecX zero = VecX::Zero(6);
        const Eigen::Ref<const VecX> s =
            dof < 0 ? Eigen::Ref<const VecX>(zero) : Eigen::Ref<const VecX>(v.segment(dof, 6));
        points[model.points[i].name] = {{"displacement", vec3(s.head(3))},
                                        {"rotation", vec3(s.tail(3))}};
    }
    return {{"frequency_hz", frequency_hz}, {"growth_rate", 0.0}, {"points", points}};
}

// A mode's [u; θ] amplitude at every node, in the order of node_frames(), normalized like the
// named points' (largest component 1); zero at a support.
std::vector<Vec6> node_amplitudes(const form::Mesh& mesh, const VecX& shape) {
    const double peak = shape.cwiseAbs().maxCoeff();
    const VecX v = peak > 0.0 ? VecX(shape / peak) : shape;
    std::vector<Vec6> out;
    int member = -1;
    for (const form::MeshElement& e : mesh.elements) {
        for (size_t j = e.member != member ? 0 : 1; j < e.nodes.size(); ++j) {
            const int dof = mesh.nodes[static_cast<size_t>(e.nodes[j])].dof;
            out.push_back(dof < 0 ? Vec6(Vec6::Zero()) : Vec6(v.segment<6>(dof)));
        }
        member = e.member;
    }
    return out;
}

// Modes of M ẍ + G ẋ + K x = 0 about a state at rest in the turning frame: the first-order
// pencil's shift-invert Arnoldi, each pair refined on the quadratic problem and checked there
// (formulations/displacement/gyroscopic_modal.hpp); each mode's shape is its displacement
// eigenvector, phase removed (largest component real), real part. `add_mode(shape, mode)`.
template <class AddMode>
void gyroscopic_modes(const SparseMatrix& K, const SparseMatrix& G, const SparseMatrix& M,
                      int count, bool conservative_loads, const AddMode& add_mode,
                      nlohmann::json& result) {
    const form::GyroscopicModes s =
        form::solve_gyroscopic_modes(K, G, M, count, conservative_loads);
    for (const form::GyroscopicMode& m : s.modes) {
        VecXc x = m.shape;
        Eigen::Index peak = 0;
        x.cwiseAbs().maxCoeff(&peak);
        if (std::abs(x[peak]) > 0.0) x *= std::abs(x[peak]) / x[peak];
        const double frequency_hz = m.s.imag() / (2.0 * kPi);
        add_mode(VecX(x.real()), {frequency_hz, m.s.real(), m.s, m.check});
        nlohmann::json& j = result["modes"].back();
        j["growth_rate"] = m.s.real();
        const std::complex<double> omega2 = -m.s * m.s;
        j["omega_squared"] = {omega2.real(), omega2.imag()};
        j["refinement"] = refinement_json(m.arnoldi_s, m.refinement_steps);
    }
    result["modal"] = {
        {"solver",
         "first-order form of (s²M + sG + K)φ = 0, shift-invert Arnoldi on "
         "(A + σB)⁻¹B, σ = 0, sparse LU; each pair refined on the quadratic problem"},
        {"arnoldi_vectors", s.arnoldi_vectors},
        {"refinement", s.conservative ? "conservative (M, K symmetric, G skew): one-sided "
                                        "Rayleigh functional, a stable s on the imaginary axis"
                                      : "two-sided Rayleigh functional"},
        {"rotating_frame",
         "modes about the steady rotating state: centrifugal stiffening and spin softening in K, "
         "the Coriolis (gyroscopic) coupling in G (docs/rotating-frame.md)"}};
    if (s.discretization_asymmetry > 0.0) {
        result["modal"]["stiffness_asymmetry"] = s.discretization_asymmetry;
        result["modal"]["asymmetry"] =
            "the loads are conservative: K's skew part is the weak form's discretization error, "
            "its first-order growth or decay rate is in each mode's error estimate "
            "(docs/rotating-frame.md)";
    }
}

template <class P>
void modal(const Model& model, bool trace, nlohmann::json& result) {
    form::DisplacementStatics<P> problem(model);
    result["dofs"] = problem.size();
    double lambda = 0.0;  // the load factor of the state (none: the undeformed state at λ = 0)
    if (model.analysis.modal.about_static_state && has_static_load(model)) {
        std::vector<double> loads = model.analysis.statics.load_factors;
        if (loads.empty()) loads = {1.0};
        const StaticSolve solve =
            solve_static(model, problem, loads, StaticRecording{}, trace, result);
        if (!static_state_usable(solve.outcome, result)) return;
        lambda = loads.back();
    }
    VecX r;
    SparseMatrix K;
    problem.evaluate(r, &K);
    const form::Mesh mass_mesh = form::build_mass_mesh(model);
    const SparseMatrix M = form::assemble_mass_matrix(
        model, mass_mesh, [&](int node) { return P::matrix(problem.node_rotation(node)); });
    result["modes"] = nlohmann::json::array();
    std::vector<CheckedMode> checked;
    // One mode into `modes` (points, stations, frames) and `checked`.
    const auto add_mode = [&](const VecX& shape, const CheckedMode& mode) {
        result["modes"].push_back(mode_json(model, problem.mesh(), shape, mode.frequency_hz));
        std::vector<NodeDisplacement> nodes;
        for (const form::MeshNode& n : problem.mesh().nodes) {
            nodes.push_back({n.x0, n.dof < 0 ? Vec3::Zero() : Vec3(shape.segment<3>(n.dof))});
        }
        result["modes"].back()["stations"] = station_displacements(model, nodes);
        if (frames_recorded()) record_frames(problem, node_amplitudes(problem.mesh(), shape));
        checked.push_back(mode);
    };
    // The frame's Ω² is scaled by the load factor of the state, as in the statics.
    if (model.rotating_frame.active() && lambda != 0.0) {
        if (lambda < 0.0) {
            throw InputError(
                "analysis.load_factors: a modal analysis in a rotating frame needs a "
                "positive last load factor (it scales Ω²)");
        }
        const Vec3 omega = std::sqrt(lambda) * model.rotating_frame.angular_velocity;
        const SparseMatrix G = form::gyroscopic_matrix(M, omega);
        gyroscopic_modes(K, G, M, model.analysis.modal.modes,
                         problem.non_conservative_load_reason().empty(), add_mode, result);
        result["modal"]["mass_rule"] = choice_name(model.discretization.displacement.mass_rule);
    } else {
        const form::ModalSolution s = form::solve_modal(K, M, model.analysis.modal.modes);
        for (size_t i = 0; i < s.pairs.size(); ++i) {
            const form::ModalPair& p = s.pairs[i];
            add_mode(s.shapes[i],
                     {p.frequency_hz, p.growth_rate,
                      std::complex<double>(p.growth_rate, 2.0 * kPi * p.frequency_hz), p.check});
            result["modes"].back()["omega_squared"] = {p.omega2.real(), p.omega2.imag()};
        }
        result["modal"] = {{"solver", s.symmetric ? "symmetric (K symmetric to round-off)" : "QZ"},
                           {"stiffness_asymmetry", s.asymmetry},
                           {"mass_rule", choice_name(model.discretization.displacement.mass_rule)}};
    }
    result["counters"] = counters_json(problem.counters());
    report_checked_modes(checked, result["steps"].empty() ? "undeformed" : "static", result);
    // The sections' damping acts in the dynamics only: these are the undamped structure's modes
    // (its decay rates are not in growth_rate), said in the result instead of left unsaid.
    if (model.has_damping()) {
        result["modal"]["damping"] = "left out: the modes are the undamped structure's";
        result["message"] = result["message"].get<std::string>() +
                            "; the sections' damping is left out (undamped modes)";
    }
    // A static state that stalled at round-off is carried into the modal status.
    if (result["status"] == "converged") {
        set_analysis_status(result, SolveStatus::converged, result["message"].get<std::string>());
    }
}

// Reactions of the constrained named points: the force and moment the support exerts on the beam
// (the residual rows the support's node would have), inertial axes.
// With a rotating frame, Q turns them from the frame's axes to inertial axes.
template <class P>
nlohmann::json reactions_json(const Model& model, form::DisplacementDynamics<P>& problem,
                              const Mat3& Q) {
    nlohmann::json out = nlohmann::json::object();
    for (const Constraint& c : model.constraints) {
        const int node = problem.mesh().point_node[static_cast<size_t>(c.point)];
        if (node < 0) continue;
        const Vec6 r = problem.reaction(node);
        out[model.points[static_cast<size_t>(c.point)].name] = {{"force", vec3(Q * r.head<3>())},
                                                                {"moment", vec3(Q * r.tail<3>())}};
    }
    return out;
}

// The named points' states of a run in a rotating frame turned to inertial axes at frame rotation
// Q (docs/rotating-frame.md): position c + Q (X + u − c), rotation Q R. The rotation angle is then
// the principal angle of Q R (the continuation along the beam is that of the frame's axes).
template <class P>
void to_inertial_axes(const Model& model, const form::DisplacementDynamics<P>& problem,
                      const Mat3& Q, std::vector<PointState>& states,
                      std::vector<Vec3>& continued) {
    const Vec3& c = problem.frame_center();
    for (size_t i = 0; i < states.size(); ++i) {
        const Vec3& X = model.points[i].position;
        states[i].displacement = c + Q * (X + states[i].displacement - c) - X;
        states[i].rotation = Q * states[i].rotation;
        continued[i] = so3::log_map(states[i].rotation);
    }
}

// Lie-group generalized-α (core/generalized_alpha.hpp) or Gauss–Legendre collocation
// (core/gauss_collocation.hpp) from rest or from the static state of the loads at t = 0
// (`initial_state: static`, a release).
template <class P>
void dynamic(const Model& model, bool trace, nlohmann::json& result) {
    const DynamicSettings& d = model.analysis.dynamics;
    if (!comb::takes_integrator(Formulation::displacement, d.integrator)) {
        throw InputError("analysis.integrator: the displacement formulation integrates with " +
                         comb::integrator_names(Formulation::displacement) + ", not '" +
                         std::string(choice_name(d.integrator)) + "'");
    }
    form::DisplacementDynamics<P> problem(model);
    result["dofs"] = problem.size();
    if (d.initial_state == InitialState::static_equilibrium) {
        problem.statics().set_time(0.0);
        const StaticSolve solve = solve_static(model, problem.static_problem(), {1.0},
                                               StaticRecording{.steps = false}, trace, result);
        if (!static_state_usable(solve.outcome, result)) return;
        problem.adopt_static_state();
    }
    NewtonSettings settings = newton_settings_from(model.solver, model.analysis.statics);
    if (trace) settings.trace = &std::cerr;
    problem.set_velocity(d.initial_velocity, Vec3::Zero());
    std::vector<PointState> states(model.points.size());
    TimeIntegrationSettings ts;
    ts.time_step = d.time_step;
    ts.end_time = d.end_time;
    ts.output_interval = d.output_interval;
    ts.rho_infinity = d.rho_infinity;
    ts.tolerance = d.time_tolerance;
    ts.length_scale = estimate::reference_length(model);
    ts.max_cuts = d.max_step_cuts;
    const auto on_output = [&](const TimeStepRecord& s) {
        for (size_t i = 0; i < model.points.size(); ++i) {
            states[i] = problem.point_state(static_cast<int>(i));
        }
        std::vector<Vec3> continued =
            rotation_vectors_along_beam(model, problem.statics().rotation_stations(), states);
        // With turning supports: `points` and `reactions` in inertial axes, the same in the
        // frame's axes (the motion relative to it) under `rotating_frame`.
        nlohmann::json relative;
        const Mat3 Q = problem.frame_rotation(s.time);
        if (problem.rotating()) {
            relative =
                step_json(model, std::nullopt, s.time, s.newton_iterations, states, continued);
            relative["reactions"] = reactions_json(model, problem, Mat3::Identity());
            to_inertial_axes(model, problem, Q, states, continued);
        }
        nlohmann::json step =
            step_json(model, std::nullopt, s.time, s.newton_iterations, states, continued);
        step["reactions"] = reactions_json(model, problem, Q);
        const form::BeamEnergy e = problem.energy();
        step["energy"] = {{"kinetic", e.kinetic}, {"strain", e.strain}};
        if (problem.rotating()) {
            step["energy"]["angular_momentum"] = vec3(Q * e.angular_momentum);
            step["energy"]["jacobi_integral"] =
                e.total() - problem.frame_angular_velocity().dot(e.angular_momentum);
            step["rotating_frame"] = {{"angle", s.time * problem.frame_angular_velocity().norm()},
                                      {"points", relative["points"]},
                                      {"reactions", relative["reactions"]}};
        }
        result["steps"].push_back(std::move(step));
        if (frames_recorded()) {
            std::optional<TurningFrame> turning;
            if (problem.rotating()) turning = TurningFrame{Q, problem.frame_center()};
            record_frames(problem.statics(), {}, turning);
        }
    };
    const int stages =
        gauss_legendre_stages(comb::integrator_for(Formulation::displacement, d.integrator));
    const DynamicOutcome out = stages > 0
                                   ? run_gauss_collocation(problem, stages, ts, settings, on_output)
                                   : run_generalized_alpha(problem, ts, settings, on_output);
    set_analysis_status(result, out.status, out.message);
    if (stages > 0) {
        result["integrator"] = {{"scheme", "Lie-group Gauss-Legendre collocation (RKMK)"},
                                {"stages", stages},
                                {"order", 2 * stages},
                                {"time_step", d.time_step},
                                {"steps", out.steps},
                                {"newton_iterations", out.newton_iterations}};
        add_step_control_json(ts.tolerance, out.control, result["integrator"]);
    } else {
        result["integrator"] = {{"scheme", "Lie-group generalized-alpha"},
                                {"rho_infinity", d.rho_infinity},
                                {"time_step", d.time_step},
                                {"steps", out.steps},
                                {"newton_iterations", out.newton_iterations}};
        add_step_control_json(ts.tolerance, out.control, result["integrator"]);
    }
    result["counters"] = counters_json(problem.counters());
}

}  // namespace

void run_displacement_dynamic(const Model& model, bool trace, nlohmann::json& result) {
    param::dispatch_parameterization(model.discretization.rotation,
                                     [&]<class P>() { dynamic<P>(model, trace, result); });
}

void run_displacement_modal(const Model& model, bool trace, nlohmann::json& result) {
    param::dispatch_parameterization(model.discretization.rotation,
                                     [&]<class P>() { modal<P>(model, trace, result); });
}

}  // namespace rotbeam
