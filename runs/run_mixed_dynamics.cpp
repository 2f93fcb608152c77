// Dynamic and modal analyses of the mixed formulation (analyses.hpp). This file holds the
// parameterization switch for them, as make_problem.cpp does for statics.
#include <algorithm>
#include <iostream>
#include <optional>
#include <sstream>
#include <type_traits>

#include "analyses.hpp"
#include "combinations/dispatch.hpp"
#include "core/beam_rotation.hpp"
#include "core/dae_driver.hpp"
#include "core/errors.hpp"
#include "core/kinematic_check.hpp"
#include "core/results.hpp"
#include "core/so3.hpp"
#include "core/static_driver.hpp"
#include "formulations/mixed/mixed_dynamics_of.hpp"
#include "formulations/mixed/mixed_modal.hpp"
#include "formulations/mixed/mixed_statics_of.hpp"
#include "frame_recorder.hpp"
#include "modal_checks.hpp"
#include "mode_matching.hpp"
#include "parameterizations/registry.hpp"
#include "parameterizations/wiener_milenkovic_continuous.hpp"
#include "solve_static.hpp"
#include "step_control_json.hpp"

namespace rotbeam {

namespace {

bool has_static_load(const Model& m) {
    return !m.point_loads.empty() || !m.distributed_loads.empty() ||
           m.gravity.squaredNorm() > 0.0 || m.rotating_frame.active();
}

nlohmann::json vec3(const Vec3& v) { return nlohmann::json::array({v[0], v[1], v[2]}); }

// Solves the static state of `model` at its load factors (default {1}) and records the steps
// (unless `record` is false). Returns false (status set) when the static solve fails or a step
// fails the kinematic check; `lambda` is the last load factor.
template <class P>
bool static_state(const Model& model, bool trace, nlohmann::json& result, VecX& state,
                  double& lambda, bool record = true) {
    form::MixedStaticsOf<P> statics(model);
    std::vector<double> loads = model.analysis.statics.load_factors;
    if (loads.empty()) loads = {1.0};
    const StaticRecording recording{.steps = record, .kinematic_check = true};
    const StaticSolve solve = solve_static(model, statics, loads, recording, trace, result);
    state = statics.state_vector();
    lambda = solve.outcome.last_converged_load_factor;
    if (solve.unresolved) {
        std::ostringstream m;
        m.precision(6);
        m << "static state: the discrete kinematics do not describe the beam at load factor "
          << solve.unresolved->load_factor << ": "
          << describe_kinematic_defect(model, solve.unresolved->defect);
        result["status"] = kKinematicsUnresolved;
        result["message"] = m.str();
        return false;
    }
    return static_state_usable(solve.outcome, result);
}

// The largest free-node component of a mode: dividing by it removes the phase.
template <class P>
std::complex<double> mode_peak(const form::MixedDynamicsOf<P>& dyn, const form::VecXc& shape) {
    std::complex<double> peak = 0.0;
    for (int n = 0; n < dyn.node_count(); ++n) {
        if (dyn.supported(n)) continue;
        for (int k = 0; k < 3 + P::kSize; ++k) {
            const std::complex<double> v = shape[dyn.node_column(n) + k];
            if (std::abs(v) > std::abs(peak)) peak = v;
        }
    }
    return peak;
}

// A mode's [u; θ] amplitude at node n: real part after dividing by the peak, θ the spatial
// rotation increment H_s(ĉ₀) δĉ (3 × 3, or 3 × 4 for the quaternion's q̂); zero at a support.
template <class P>
Vec6 node_mode(const form::MixedDynamicsOf<P>& dyn, const VecX& x0, const form::VecXc& shape,
               std::complex<double> peak, int n) {
    constexpr int K = P::kSize;
    Vec3 d = Vec3::Zero(), r = Vec3::Zero();
    if (!dyn.supported(n) && std::abs(peak) > 0.0) {
        const int c = dyn.node_column(n);
        param::Params<K> dq;
        for (int k = 0; k < 3; ++k) d[k] = (shape[c + k] / peak).real();
        for (int k = 0; k < K; ++k) dq[k] = (shape[c + 3 + k] / peak).real();
        r = P::spatial_tangent(x0.segment<K>(c + 3)) * dq;
    }
    return (Vec6() << d, r).finished();
}

// Named points' displacement and rotation amplitudes of one mode (node_mode), largest component 1.
template <class P>
nlohmann::json mode_json(const Model& model, const form::MixedDynamicsOf<P>& dyn, const VecX& x0,
                         const form::VecXc& shape, double frequency_hz, double growth_rate) {
    const std::complex<double> peak = mode_peak(dyn, shape);
    nlohmann::json points = nlohmann::json::object();
    for (size_t i = 0; i < model.points.size(); ++i) {
        const Vec6 a = node_mode(dyn, x0, shape, peak, static_cast<int>(i));
        points[model.points[i].name] = {{"displacement", vec3(Vec3(a.head<3>()))},
                                        {"rotation", vec3(Vec3(a.tail<3>()))}};
    }
    std::vector<NodeDisplacement> nodes;
    const form::MixedLayout& layout = dyn.layout();
    for (int n = 0; n < dyn.node_count(); ++n) {
        const Vec6 a = node_mode(dyn, x0, shape, peak, n);
        nodes.push_back({layout.nodes[static_cast<size_t>(n)].reference, Vec3(a.head<3>())});
    }
    return {{"frequency_hz", frequency_hz},
            {"growth_rate", growth_rate},
            {"points", points},
            {"stations", station_displacements(model, nodes)}};
}

// The frames of the state a mode is about and the mode's amplitude at every node, in their order
// (mixed_node_frames.hpp), when a recorder is installed (run --vtk).
template <class P>
void record_mode_frames(const form::MixedDynamicsOf<P>& dyn, const VecX& x0,
                        const form::VecXc& shape) {
    if (!frames_recorded()) return;
    const std::complex<double> peak = mode_peak(dyn, shape);
    std::vector<Vec6> amplitudes;
    for (const form::MixedFrameNode& n : dyn.frame_nodes()) {
        amplitudes.push_back(node_mode(dyn, x0, shape, peak, n.node));
    }
    record_snapshot({dyn.node_frames(x0, 0.0), dyn.section_resultants(x0), std::move(amplitudes),
                     std::nullopt, std::nullopt});
}

template <class P>
void modal(const Model& model, bool trace, nlohmann::json& result) {
    form::refuse_mixed_modal_damping(model);
    // The reference configuration (zero for three parameters, unit quaternions for four).
    VecX state = form::MixedStaticsOf<P>(model).state_vector();
    double lambda = 0.0;
    const bool loaded = model.analysis.modal.about_static_state && has_static_load(model);
    if (loaded) {
        if (!static_state<P>(model, trace, result, state, lambda)) return;
    }
    form::MixedDynamicsOf<P> dyn(form::frozen_loads(model, lambda), 1.0);
    result["dofs"] = dyn.size();
    const VecX x0 = dyn.from_static_state(state);
    VecX r;
    SparseMatrix A, B;
    dyn.evaluate(0.0, x0, VecX::Zero(dyn.size()), r, &A, &B);
    // About a spinning or a loaded state a growth is the question (a buckled column diverges, a
    // follower load flutters): each pair refined with its error estimate, real s > 0 (divergence)
    // kept (formulations/mixed/mixed_modal.hpp). At rest and unloaded the structure is conservative
    // and every s is imaginary.
    const bool refined = dyn.rotating() || loaded;
    const int count = model.analysis.modal.modes;
    const form::DaeModalSolution s =
        refined ? form::solve_dae_modal_refined(A, B, count) : form::solve_dae_modal(A, B, count);
    result["modes"] = nlohmann::json::array();
    std::vector<CheckedMode> checked;
    for (size_t i = 0; i < s.frequencies_hz.size(); ++i) {
        result["modes"].push_back(
            mode_json<P>(model, dyn, x0, s.shapes[i], s.frequencies_hz[i], s.growth_rates[i]));
        if (refined) {
            result["modes"].back()["refinement"] =
                refinement_json(s.arnoldi_s[i], s.refinement_steps[i]);
        }
        record_mode_frames(dyn, x0, s.shapes[i]);
        checked.push_back({s.frequencies_hz[i], s.growth_rates[i],
                           std::complex<double>(s.growth_rates[i], 2.0 * kPi * s.frequencies_hz[i]),
                           s.checks[i]});
    }
    result["modal"] = {
        {"solver", refined ? "shift-invert Arnoldi on (A + σB)⁻¹B, σ = 0, sparse LU; each pair "
                             "refined on A + sB"
                           : "shift-invert Arnoldi on (A + σB)⁻¹B, σ = 0, sparse LU"},
        {"arnoldi_vectors", s.arnoldi_vectors},
        {"mass_rule", std::string(choice_name(model.discretization.mixed.mass_rule)) +
                          " (element momenta P, H: consistent = the element "
                          "average of the section mass, midpoint = its mid-length "
                          "value, seed 002)"}};
    if (refined) {
        result["modal"]["refinement"] =
            "two-sided Rayleigh functional (the linearized DAE has no symmetry to keep a stable s "
            "on the imaginary axis: Re s within its error estimate)";
        result["modal"]["rotating_frame"] =
            "modes of the mixed dynamics linearized about the steady rotating state (at rest in "
            "the turning frame, momenta of the rigid rotation): centrifugal stiffening, spin "
            "softening and the Coriolis (gyroscopic) coupling included (docs/rotating-frame.md)";
    }
    result["counters"] = counters_json(dyn.counters());
    report_checked_modes(checked, result["steps"].empty() ? "undeformed" : "static", result);
    // A static state that stalled at round-off is carried into the modal status.
    if (result["status"] == "converged") {
        set_analysis_status(result, SolveStatus::converged, result["message"].get<std::string>());
    }
}

// Supported points also carry their reactions (the node unknowns, the frame's axes turned by Q
// to inertial ones): the root force and moment histories (seed 002 Fig. 11).
template <class Dyn>
void add_reactions(const Model& model, const Dyn& dyn, const VecX& xs, const Mat3& Q,
                   nlohmann::json& step) {
    for (size_t i = 0; i < model.points.size(); ++i) {
        const int n = static_cast<int>(i);
        if (!dyn.supported(n)) continue;
        nlohmann::json& p = step["points"][model.points[i].name];
        const Vec3 force = xs.segment<3>(dyn.node_column(n));
        const Vec3 moment = xs.segment<3>(dyn.node_column(n) + 3);
        // Without a frame the values as they are (an identity product would turn −0 into +0).
        p["reaction_force"] = vec3(dyn.rotating() ? Vec3(Q * force) : force);
        p["reaction_moment"] = vec3(dyn.rotating() ? Vec3(Q * moment) : moment);
    }
}

// The named points' states relative to a frame turned to inertial axes at frame rotation Q about
// the centre c: position c + Q (X + u − c), rotation Q R; the rotation angle is then the
// principal angle of Q R (as the displacement formulation reports it).
void to_inertial_axes(const Model& model, const Vec3& c, const Mat3& Q,
                      std::vector<PointState>& states, std::vector<Vec3>& continued) {
    for (size_t i = 0; i < states.size(); ++i) {
        const Vec3& X = model.points[i].position;
        states[i].displacement = c + Q * (X + states[i].displacement - c) - X;
        states[i].rotation = Q * states[i].rotation;
        continued[i] = so3::log_map(states[i].rotation);
    }
}

void track_norm_drift(const form::QuaternionNormDrift& now, form::QuaternionNormDrift& worst) {
    worst.nodes = std::max(worst.nodes, now.nodes);
    worst.elements = std::max(worst.elements, now.elements);
}

// The integrator named by analysis.integrator: `trapezoidal` (default; GEBT's fixed-step scheme),
// `ida` (SUNDIALS IDA, BDF of order ≤ 2, analysis.relative_tolerance and absolute_tolerance,
// 1e-6 by default, the latter × the state scales) or `radau-iia-3` (fixed or adaptive steps, order
// 5 on an index-1 system, core/dae_radau.hpp).
Integrator mixed_integrator(const DynamicSettings& d) {
    if (!comb::takes_integrator(Formulation::mixed, d.integrator)) {
        throw InputError("analysis.integrator: unknown integrator '" +
                         std::string(choice_name(d.integrator)) + "' for the mixed formulation (" +
                         comb::integrator_names(Formulation::mixed) + ")");
    }
    return comb::integrator_for(Formulation::mixed, d.integrator);
}

// The classical order of the fixed-step schemes (the result's max_order; IDA: its setting).
int scheme_order(Integrator integrator, const DaeSettings& s) {
    if (integrator == Integrator::ida) return s.max_order;
    return integrator == Integrator::radau_iia_3 ? 5 : 2;
}

DaeOutcome integrate(Integrator integrator, DaeSystem& dae, VecX& x, VecX& xdot,
                     const DaeSettings& s, const DaeOutput& output) {
    switch (integrator) {
        case Integrator::ida:
            return integrate_ida(dae, x, xdot, s, output);
        case Integrator::radau_iia_3:
            return integrate_radau_iia(dae, x, xdot, s, output);
        default:
            return integrate_trapezoidal(dae, x, xdot, s, output);
    }
}

template <class P>
void dynamic(const Model& model, bool trace, nlohmann::json& result) {
    const DynamicSettings& d = model.analysis.dynamics;
    if (!(d.time_step > 0.0) || !(d.end_time > d.time_step)) {
        throw InputError(
            "analysis: a dynamic analysis needs time_step > 0 and end_time > time_step");
    }
    const Integrator integrator = mixed_integrator(d);
    const bool ida = integrator == Integrator::ida;
    VecX state = form::MixedStaticsOf<P>(model).state_vector();
    if (d.initial_state == InitialState::static_equilibrium && has_static_load(model)) {
        double lambda = 0.0;
        Model at_start = model;
        at_start.analysis.statics.load_factors = {1.0};  // the loads at t = 0
        if (!static_state<P>(at_start, trace, result, state, lambda, false)) return;
    }
    // Loads are evaluated at max(t, 1e-6 Δt): their right limit at the start (mixed_dynamics.hpp).
    form::MixedDynamicsOf<P> dyn(model, d.end_time, 1e-6 * d.time_step);
    result["dofs"] = dyn.size();
    VecX x = dyn.from_static_state(state);
    if (d.initial_velocity.squaredNorm() > 0.0)
        dyn.set_translational_momenta(x, d.initial_velocity);
    VecX xdot = VecX::Zero(dyn.size());
    DaeSettings s;
    s.end_time = d.end_time;
    s.time_step = d.time_step;
    s.output_interval = d.output_interval;
    s.relative_tolerance = d.relative_tolerance;
    s.absolute_tolerance = d.absolute_tolerance;
    s.time_tolerance = d.time_tolerance;
    s.max_cuts = d.max_step_cuts;
    if (ida && d.time_tolerance > 0.0) {
        // IDA's local error test per step (not per unit step): its global error is proportional to
        // the tolerance, not bounded by it; the time companion checks it (tolerance/4).
        s.relative_tolerance = s.absolute_tolerance = d.time_tolerance;
    }
    s.newton = time_step_newton_settings(model.solver);
    if (trace) s.newton.trace = &std::cerr;
    std::vector<PointState> states(model.points.size());
    result["steps"] = nlohmann::json::array();
    form::QuaternionNormDrift drift;  // the quaternion's, over the output times
    // The first output time that fails the kinematic check (core/kinematic_check.hpp): the run
    // is reported up to the output before it, with the check's status.
    std::optional<std::string> unresolved;
    const DaeOutput output = [&](double t, const VecX& xs, const VecX&, int iterations) {
        if (unresolved) return;
        const std::vector<StaticProblem::RotationStation> stations = dyn.rotation_stations(xs, t);
        const std::optional<KinematicDefect> worst = worst_kinematic_defect(stations);
        if (worst && !within_kinematic_bound(*worst)) {
            std::ostringstream m;
            m << "the discrete kinematics do not describe the beam at t = " << t << " (output "
              << result["steps"].size() + 1 << "): " << describe_kinematic_defect(model, *worst)
              << "; the equations are solved, the answer is not trustworthy";
            unresolved = m.str();
            return;
        }
        for (size_t i = 0; i < model.points.size(); ++i) {
            states[i] = dyn.point_state(xs, t, static_cast<int>(i));
        }
        std::vector<Vec3> continued = rotation_vectors_along_beam(model, stations, states);
        // With a turning root: `points` in inertial axes, the same in the frame's axes (the
        // motion relative to it) under `rotating_frame` (docs/rotating-frame.md).
        const Mat3 Q = dyn.frame_rotation(t);
        nlohmann::json relative;
        if (dyn.rotating()) {
            relative = step_json(model, std::nullopt, t, iterations, states, continued);
            add_reactions(model, dyn, xs, Mat3::Identity(), relative);
            to_inertial_axes(model, dyn.frame_center(), Q, states, continued);
        }
        nlohmann::json step = step_json(model, std::nullopt, t, iterations, states, continued);
        add_reactions(model, dyn, xs, Q, step);
        if (dyn.rotating()) {
            const form::MixedEnergy e = dyn.energy(xs);
            step["energy"] = {{"kinetic", e.kinetic},
                              {"strain", e.strain},
                              {"angular_momentum", vec3(Q * e.angular_momentum)},
                              {"jacobi_integral",
                               e.total() - dyn.frame_angular_velocity().dot(e.angular_momentum)}};
            step["rotating_frame"] = {{"angle", t * dyn.frame_angular_velocity().norm()},
                                      {"points", relative["points"]}};
        }
        result["steps"].push_back(std::move(step));
        if (frames_recorded()) {
            std::optional<TurningFrame> turning;
            if (dyn.rotating()) turning = TurningFrame{Q, dyn.frame_center()};
            record_snapshot(
                {dyn.node_frames(xs, t), dyn.section_resultants(xs), {}, turning, std::nullopt});
        }
        if constexpr (P::kSize == 4) track_norm_drift(dyn.norm_drift(xs, t), drift);
    };
    const DaeOutcome out = integrate(integrator, dyn, x, xdot, s, output);
    result["dynamics"] = {{"integrator", choice_name(integrator)},
                          {"steps", out.steps},
                          {"newton_iterations", out.newton_iterations},
                          {"residual_evaluations", out.residual_evaluations},
                          {"jacobian_evaluations", out.jacobian_evaluations},
                          {"error_test_failures", out.error_test_failures},
                          {"nonlinear_failures", out.nonlinear_failures},
                          {"max_order", scheme_order(integrator, s)},
                          {"last_time", out.last_time}};
    if (ida) {
        result["dynamics"]["relative_tolerance"] = s.relative_tolerance;
        result["dynamics"]["absolute_tolerance"] = s.absolute_tolerance;
    } else {
        add_step_control_json(s.time_tolerance, out.control, result["dynamics"]);
    }
    if (integrator == Integrator::radau_iia_3) {
        result["dynamics"]["factorizations"] = out.factorizations;
    }
    result["counters"] = counters_json(dyn.counters());
    set_analysis_status(result, out.status, out.message);
    if (unresolved) {
        result["status"] = kKinematicsUnresolved;
        result["message"] = *unresolved;
        return;
    }
    if constexpr (P::kSize == 4) {
        result["quaternion_norm_drift"] = {{"nodes", drift.nodes}, {"elements", drift.elements}};
        std::ostringstream m;
        m << "; max ||q| - 1| over the output times: nodes " << drift.nodes
          << ", elements (midpoint averages, O(dL^2)) " << drift.elements;
        result["message"] = result["message"].get<std::string>() + m.str();
    }
}

// The parameterization switch of the mixed dynamics and modal analysis: f.template operator()<P>()
// (WM with the continuous map when the case asks for it).
template <class F>
void dispatch_mixed(const Model& model, F&& f) {
    comb::dispatch_parameterization_of<Formulation::mixed>(model.discretization, f);
}

}  // namespace

void run_mixed_dynamic(const Model& model, bool trace, nlohmann::json& result) {
    dispatch_mixed(model, [&]<class P>() { dynamic<P>(model, trace, result); });
}

void run_mixed_modal(const Model& model, bool trace, nlohmann::json& result) {
    dispatch_mixed(model, [&]<class P>() { modal<P>(model, trace, result); });
}

}  // namespace rotbeam
