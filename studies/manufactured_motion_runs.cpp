#include "manufactured_motion_runs.hpp"

#include <chrono>
#include <cmath>
#include <sstream>
#include <type_traits>

#include "combinations/dispatch.hpp"
#include "core/dae_driver.hpp"
#include "core/errors.hpp"
#include "core/gauss_collocation.hpp"
#include "core/generalized_alpha.hpp"
#include "core/so3.hpp"
#include "core/static_driver.hpp"
#include "formulations/displacement/displacement_dynamics.hpp"
#include "formulations/mixed/mixed_dynamics_of.hpp"
#include "parameterizations/registry.hpp"
#include "parameterizations/wiener_milenkovic_continuous.hpp"
#include "studies/guarded_run.hpp"
#include "studies/semi_discrete_forcing.hpp"

namespace rotbeam::cli {

namespace {

const char* const kPoints[] = {"root", "q1", "mid", "q3", "tip"};

// Records the named points' state at output time t and their errors against the exact motion.
struct Recorder {
    const Model& model;
    const oracle::ManufacturedMotion& motion;
    MotionRunResult& result;
    template <class PointStateOf>
    void operator()(double t, PointStateOf&& point_state) {
        result.times.push_back(t);
        for (const char* name : kPoints) {
            const int p = model.point_index(name);
            const PointState h = point_state(p);
            const oracle::ManufacturedMotion::State x =
                motion.state(model.points[p].position.x(), t);
            result.u.push_back(h.displacement);
            result.R.push_back(h.rotation);
            result.error_u =
                std::max(result.error_u, (h.displacement - x.u).norm() / motion.length);
            result.error_R =
                std::max(result.error_R, so3::log_map(h.rotation.transpose() * x.R).norm());
        }
    }
};

// The nodal interpolant of the exact motion at t (y_h(t) of the displacement formulation): every
// node's u and R (parameters of its rotation vector: the relative interpolation reads the nodes
// through their rotations only) adopted as the step start, and, in the unknowns' numbering, v =
// [u̇; ω] and v˙ = [ü; ω̇] (spatial), the velocities set as the nodes'.
template <class P>
void set_displacement_trajectory(form::DisplacementDynamics<P>& d,
                                 const oracle::ManufacturedMotion& mm, double t, VecX& v,
                                 VecX& v_dot) {
    const form::Mesh& mesh = d.mesh();
    for (size_t i = 0; i < mesh.nodes.size(); ++i) {
        const oracle::ManufacturedMotion::State x = mm.state(mesh.nodes[i].x0.x(), t);
        d.statics().set_node_state(static_cast<int>(i), x.u,
                                   P::from_rotation_vector(so3::log_map(x.R)));
    }
    d.adopt_static_state();
    v = v_dot = VecX::Zero(d.size());
    for (size_t i = 0; i < mesh.nodes.size(); ++i) {
        const int dof = mesh.nodes[i].dof;
        if (dof < 0) continue;
        const oracle::ManufacturedMotion::State x = mm.state(mesh.nodes[i].x0.x(), t);
        v.segment<6>(dof) << x.u_dot, x.omega;
        v_dot.segment<6>(dof) << x.u_ddot, x.omega_dot;
        d.set_node_velocity(static_cast<int>(i), v.segment<6>(dof));
    }
}

// r_h(t): the residual of `shadow` (a second problem on the same mesh) at y_h(t).
template <class P>
void displacement_forcing(form::DisplacementDynamics<P>& shadow,
                          const oracle::ManufacturedMotion& mm, double t, VecX& r) {
    VecX v, v_dot;
    set_displacement_trajectory(shadow, mm, t, v, v_dot);
    shadow.set_stage(VecX::Zero(shadow.size()), v, v_dot, t, 0.0, 0.0);
    shadow.evaluate(r, nullptr);
}

// Errors against y_h accumulated over the outputs (semi-discrete runs): u over the length, the
// rotation angle, and the velocity-level and force unknowns as max differences and magnitudes
// (their ratio at the end, as relative_history_difference); the velocity-level unknowns come in
// blocks of six, [translational; rotational], whose halves are also measured apart.
struct TrajectoryError {
    struct Ratio {
        double diff = 0.0, size = 0.0;
        void add(const Eigen::Ref<const VecX>& x, const Eigen::Ref<const VecX>& y) {
            diff = std::max(diff, (x - y).cwiseAbs().maxCoeff());
            size = std::max(size, y.cwiseAbs().maxCoeff());
        }
        double value() const { return size > 0.0 ? diff / size : 0.0; }
    };
    double u = 0.0, R = 0.0;
    Ratio velocity, forces, translational, rotational;
    void add_velocity(const Vec6& x, const Vec6& y) {
        velocity.add(x, y);
        translational.add(x.head<3>(), y.head<3>());
        rotational.add(x.tail<3>(), y.tail<3>());
    }
    ComponentDifferences result() const {
        return {u, R, velocity.value(), forces.value(), translational.value(), rotational.value()};
    }
};

template <class P>
void displacement_run(const Model& model, const MotionRunSpec& spec, MotionRunResult& result) {
    form::DisplacementDynamics<P> d(model);
    const form::Mesh& mesh = d.mesh();
    VecX v0, v_dot0;
    set_displacement_trajectory(d, spec.motion, 0.0, v0, v_dot0);
    result.dofs = d.size();
    TimeIntegrationSettings ts;
    ts.time_step = spec.dt;
    ts.end_time = spec.end_time;
    ts.output_interval = model.analysis.dynamics.output_interval;
    ts.rho_infinity = spec.rho_infinity;
    ts.tolerance = spec.time_tolerance;
    ts.length_scale = spec.motion.length;
    Recorder record{model, spec.motion, result};
    const NewtonSettings newton = newton_settings_from(model.solver, model.analysis.statics);
    TrajectoryError exact;
    const auto on_output = [&](const TimeStepRecord& r) {
        record(r.time, [&](int p) { return d.point_state(p); });
        VecX v(d.size());
        int k = 0;
        for (size_t i = 0; i < mesh.nodes.size(); ++i) {
            if (mesh.nodes[i].dof < 0) continue;
            const int n = static_cast<int>(i);
            v.segment<6>(6 * k++) = d.node_velocity(n);
            if (!spec.semi_discrete) continue;
            const oracle::ManufacturedMotion::State x =
                spec.motion.state(mesh.nodes[i].x0.x(), r.time);
            exact.u = std::max(exact.u, (d.node_displacement(n) - x.u).norm() / spec.motion.length);
            exact.R = std::max(
                exact.R, so3::log_map(P::matrix(d.node_rotation(n)).transpose() * x.R).norm());
            exact.add_velocity(d.node_velocity(n), (Vec6() << x.u_dot, x.omega).finished());
        }
        result.velocity.push_back(v.head(6 * k));
    };
    const int stages = gauss_legendre_stages(spec.integrator);
    const auto integrate = [&](CollocationProblem& problem) {
        return stages > 0 ? run_gauss_collocation(problem, stages, ts, newton, on_output)
                          : run_generalized_alpha(problem, ts, newton, on_output);
    };
    DynamicOutcome out;
    if (spec.semi_discrete) {
        form::DisplacementDynamics<P> shadow(model);
        ForcingCache forcing(
            [&](double t, VecX& r) { displacement_forcing(shadow, spec.motion, t, r); });
        ForcedCollocation<form::DisplacementDynamics<P>> forced(d, forcing);
        out = integrate(forced);
        result.semi_discrete_error = exact.result();
    } else {
        out = integrate(d);
    }
    result.status = to_string(out.status);
    result.message = out.message;
    result.steps = out.steps;
    result.newton_iterations = out.newton_iterations;
}

// The exact state at t at the element mid-points (u, c, F, M, P, H and the rates) and the nodes
// (û, ĉ).
template <class Element, class Node>
void fill_mixed_state(const form::MixedLayout& layout, const oracle::ManufacturedMotion& mm,
                      double t, Element&& element, Node&& node) {
    for (int n = 0; n < static_cast<int>(layout.nodes.size()); ++n) {
        if (!layout.supported(n))
            node(n, mm.state(layout.nodes[static_cast<size_t>(n)].reference.x(), t));
    }
    for (int e = 0; e < layout.element_count(); ++e) {
        const form::MixedElement& el = layout.elements[static_cast<size_t>(e)];
        const double s =
            layout.nodes[static_cast<size_t>(el.start_node)].reference.x() + 0.5 * el.length;
        element(e, s);
    }
}

// The parameters of R(s, t) from the continuous branch of the rotation vector; with `chart`, in the
// chart nearest its parameters at `column` (P::rescale). A trajectory y_h(t) needs parameters
// continuous in t: the Euler angles of that rotation vector jump by 2π when a component leaves its
// principal range and the quaternion changes sign past 2π, and a fixed-step scheme cannot follow a
// jump of its differential unknowns (the semi-discrete runs failed there with any step).
template <class P>
param::Params<P::kSize> motion_parameters(const oracle::ManufacturedMotion& mm, double s, double t,
                                          const VecX* chart, int column) {
    const param::Params<P::kSize> c = P::from_rotation_vector(mm.rotation_vector(s, t));
    if (chart == nullptr) return c;
    return P::rescale(c, chart->segment<P::kSize>(column));
}

// The exact state at t: the differential unknowns (u, c, P, H) and their rates, and the algebraic
// ones (F, M; node û, ĉ) at their exact values, the rates of these zero (F does not see them).
// At t = 0 the start of the runs, for which the algebraic part is the drivers' starting guess
// (MixedNumbering: the free rod has no support, so no reactions or ρ; the quaternion's norm row
// holds no unknown); at every t the semi-discrete trajectory y_h(t), ẏ_h(t) of the mixed mesh.
template <class P, class Dyn>
void mixed_state(const Dyn& dyn, const oracle::ManufacturedMotion& mm, double t, VecX& x,
                 VecX& xdot, const VecX* chart = nullptr) {
    x = VecX::Zero(dyn.size());
    xdot = VecX::Zero(dyn.size());
    const form::MixedLayout* layout = &dyn.layout();
    auto node_column = [&](int n) { return dyn.node_column(n); };
    auto element_column = [&](int e) { return dyn.element_column(e); };
    const form::MixedNumbering& nb = dyn.numbering();
    const int ou = nb.u(), oc = nb.c(), oF = nb.F(), oP = nb.P();
    fill_mixed_state(
        *layout, mm, t,
        [&](int e, double s) {
            const oracle::ManufacturedMotion::State st = mm.state(s, t);
            const int o = element_column(e);
            const param::Params<P::kSize> c = motion_parameters<P>(mm, s, t, chart, o + oc);
            const Mat3 Rt = st.R.transpose();
            const Vec3 V = Rt * st.u_dot, W = Rt * st.omega;
            Vec6 vel, acc;
            vel << V, W;
            acc << Rt * st.u_ddot - W.cross(V), Rt * st.omega_dot;
            x.segment<3>(o + ou) = st.u;
            x.segment<P::kSize>(o + oc) = c;
            x.segment<6>(o + oF) = mm.stiffness * mm.strains(s, t);
            x.segment<6>(o + oP) = mm.mass * vel;
            xdot.segment<3>(o + ou) = st.u_dot;
            xdot.segment<P::kSize>(o + oc) = P::material_tangent_inverse(c) * W;  // Ω = H_m ċ
            xdot.segment<6>(o + oP) = mm.mass * acc;
        },
        [&](int n, const oracle::ManufacturedMotion::State& st) {
            const double s = layout->nodes[static_cast<size_t>(n)].reference.x();
            x.segment<3>(node_column(n)) = st.u;
            x.segment<P::kSize>(node_column(n) + 3) =
                motion_parameters<P>(mm, s, t, chart, node_column(n) + 3);
        });
}

// Errors of the state x against y (both mixed states at one time): u of the elements and nodes
// over the length, their rotations' angles, [P; H] and [F; M] of the elements.
template <class P, class Dyn>
void add_mixed_error(const Dyn& dyn, const VecX& x, const VecX& y, double length,
                     TrajectoryError& error) {
    const form::MixedNumbering& nb = dyn.numbering();
    const auto position = [&](int o) {
        error.u = std::max(error.u, (x.segment<3>(o) - y.segment<3>(o)).norm() / length);
        const Mat3 R = P::matrix(x.segment<P::kSize>(o + 3));
        const Mat3 Ry = P::matrix(y.segment<P::kSize>(o + 3));
        error.R = std::max(error.R, so3::log_map(R.transpose() * Ry).norm());
    };
    for (int n = 0; n < nb.node_count(); ++n) {
        if (!nb.supported(n)) position(nb.node_column(n));
    }
    for (int e = 0; e < nb.element_count; ++e) {
        const int o = nb.element_column(e);
        position(o + nb.u());
        error.add_velocity(x.segment<6>(o + nb.P()), y.segment<6>(o + nb.P()));
        error.forces.add(x.segment<6>(o + nb.F()), y.segment<6>(o + nb.F()));
    }
}

template <class P>
void mixed_run(const Model& model, const MotionRunSpec& spec, MotionRunResult& result) {
    form::MixedDynamicsOf<P> dyn(model, spec.end_time);
    VecX x, xdot;
    mixed_state<P>(dyn, spec.motion, 0.0, x, xdot);
    result.dofs = dyn.size();
    DaeSettings s;
    s.end_time = spec.end_time;
    s.time_step = spec.dt;
    s.output_interval = model.analysis.dynamics.output_interval;
    s.relative_tolerance = s.absolute_tolerance = spec.tolerance;
    s.time_tolerance = spec.time_tolerance;
    if (spec.newton_tolerance > 0.0) {
        s.newton.residual_tolerance = s.newton.increment_tolerance = spec.newton_tolerance;
    }
    Recorder record{model, spec.motion, result};
    const form::MixedNumbering& nb = dyn.numbering();
    TrajectoryError exact;
    const DaeOutput output = [&](double t, const VecX& xs, const VecX&, int) {
        record(t, [&](int p) { return dyn.point_state(xs, t, p); });
        if (spec.semi_discrete) {
            VecX y, ydot;
            mixed_state<P>(dyn, spec.motion, t, y, ydot);
            add_mixed_error<P>(dyn, xs, y, spec.motion.length, exact);
        }
        VecX momenta(6 * nb.element_count), forces(6 * nb.element_count);
        for (int e = 0; e < nb.element_count; ++e) {
            momenta.segment<6>(6 * e) = xs.segment<6>(nb.element_column(e) + nb.P());
            forces.segment<6>(6 * e) = xs.segment<6>(nb.element_column(e) + nb.F());
        }
        result.velocity.push_back(momenta);
        result.forces.push_back(forces);
    };
    const auto integrate = [&](DaeSystem& dae) {
        if (spec.integrator == Integrator::ida) return integrate_ida(dae, x, xdot, s, output);
        return spec.integrator == Integrator::radau_iia_3
                   ? integrate_radau_iia(dae, x, xdot, s, output)
                   : integrate_trapezoidal(dae, x, xdot, s, output);
    };
    DaeOutcome out;
    if (spec.semi_discrete) {
        // r_h(t) = F(t, y_h(t), ẏ_h(t)) of the same system (it holds no state). The parameters of
        // y_h follow their charts from the start: each evaluation takes the charts nearest the
        // last one's (the times of a run's evaluations are at most a step apart).
        VecX chart = x;
        ForcingCache forcing([&](double t, VecX& r) {
            VecX y, ydot;
            mixed_state<P>(dyn, spec.motion, t, y, ydot, &chart);
            chart = y;
            dyn.evaluate(t, y, ydot, r, nullptr, nullptr);
        });
        ForcedDae forced(dyn, forcing);
        out = integrate(forced);
        result.semi_discrete_error = exact.result();
    } else {
        out = integrate(dyn);
    }
    result.status = to_string(out.status);
    result.message = out.message;
    result.steps = out.steps;
    result.newton_iterations = out.newton_iterations;
}

// The parameterization switch of these runs.
void dispatch(const Model& model, const MotionRunSpec& spec, MotionRunResult& result) {
    comb::dispatch_formulation(spec.formulation, [&]<Formulation F>() {
        comb::dispatch_parameterization_of<F>(model.discretization, [&]<class P>() {
            if constexpr (F == Formulation::displacement) {
                displacement_run<P>(model, spec, result);
            } else {
                mixed_run<P>(model, spec, result);
            }
        });
    });
}

}  // namespace

std::string MotionRunSpec::label() const {
    std::ostringstream s;
    s << choice_name(formulation) << "/" << param::name_of(rotation);
    if (wm_map == WmMap::continuous) s << "-continuous";
    if (formulation == Formulation::displacement) {
        s << "/p" << order;
        if (gauss_legendre_stages(integrator) > 0) {
            s << "/gl" << gauss_legendre_stages(integrator);
        } else {
            s << "/ga" << rho_infinity;
        }
    } else {
        s << "/" << choice_name(comb::integrator_for(formulation, integrator));
    }
    if (time_tolerance > 0.0) s << "/adaptive";
    return s.str();
}

Model motion_run_model(const MotionRunSpec& spec) {
    Model m = oracle::manufactured_motion_model(spec.motion, spec.elements, spec.dt, spec.end_time);
    m.discretization.formulation = spec.formulation;
    m.discretization.rotation = spec.rotation;
    m.discretization.order = spec.order;
    m.discretization.mixed.wm_map = spec.wm_map;
    m.analysis.dynamics.integrator = spec.integrator;
    m.analysis.dynamics.rho_infinity = spec.rho_infinity;
    m.analysis.dynamics.relative_tolerance = m.analysis.dynamics.absolute_tolerance =
        spec.tolerance;
    m.analysis.dynamics.time_tolerance = spec.time_tolerance;
    m.analysis.dynamics.output_interval =
        spec.output_interval > 0.0 ? spec.output_interval : spec.end_time / kMotionOutputs;
    if (spec.newton_tolerance > 0.0) {
        m.solver.residual_tolerance = m.solver.increment_tolerance = spec.newton_tolerance;
    }
    return m;
}

oracle::ManufacturedMotion motion_within_reach(Formulation formulation,
                                               ParameterizationId rotation) {
    oracle::ManufacturedMotion m;
    if (rotation == param::id_of<param::Rodrigues>()) {
        m.spin0 = 0.0;
        m.spin_rate = 1.5;
    } else if (formulation == Formulation::mixed && rotation != param::id_of<param::Quaternion>()) {
        m.spin0 = 0.5 * kPi;
    }
    return m;
}

MotionRunResult run_manufactured_motion(const MotionRunSpec& spec) {
    const Model model = motion_run_model(spec);
    MotionRunResult result;
    run_guarded(result, [&] { dispatch(model, spec, result); });
    return result;
}

void run_difference(const MotionRunResult& a, const MotionRunResult& b, double length, double& du,
                    double& dR) {
    du = dR = 0.0;
    const size_t n = std::min(a.u.size(), b.u.size());
    for (size_t i = 0; i < n; ++i) {
        du = std::max(du, (a.u[i] - b.u[i]).norm() / length);
        dR = std::max(dR, so3::log_map(a.R[i].transpose() * b.R[i]).norm());
    }
}

namespace {

// The rows of a history's vectors that relative_history_difference compares: all, or in blocks
// of six [translational; rotational] one half.
enum class Rows { all, translational, rotational };

// Max over the common outputs of ‖a_k − b_k‖∞ over the max over the outputs of ‖b_k‖∞, on `rows`.
double relative_history_difference(const std::vector<VecX>& a, const std::vector<VecX>& b,
                                   Rows rows = Rows::all) {
    const size_t n = std::min(a.size(), b.size());
    double diff = 0.0, size = 0.0;
    for (size_t k = 0; k < n; ++k) {
        if (a[k].size() != b[k].size() || b[k].size() == 0) return 0.0;
        for (Eigen::Index i = 0; i < b[k].size(); ++i) {
            const bool rotational = i % 6 >= 3;
            if (rows != Rows::all && rotational != (rows == Rows::rotational)) continue;
            diff = std::max(diff, std::abs(a[k](i) - b[k](i)));
            size = std::max(size, std::abs(b[k](i)));
        }
    }
    return size > 0.0 ? diff / size : 0.0;
}

}  // namespace

namespace {

// ComponentDifferences' members in table order.
constexpr double ComponentDifferences::*kComponentMembers[kMotionComponents] = {
    &ComponentDifferences::u,
    &ComponentDifferences::R,
    &ComponentDifferences::velocity,
    &ComponentDifferences::forces,
    &ComponentDifferences::translational,
    &ComponentDifferences::rotational};

}  // namespace

double& component(ComponentDifferences& d, int k) { return d.*kComponentMembers[k]; }

double component(const ComponentDifferences& d, int k) { return d.*kComponentMembers[k]; }

const char* component_name(int k) {
    static const char* const names[kMotionComponents] = {"u", "R", "v", "F", "vt", "vr"};
    return names[k];
}

ComponentDifferences component_differences(const MotionRunResult& a, const MotionRunResult& b,
                                           double length) {
    ComponentDifferences d;
    run_difference(a, b, length, d.u, d.R);
    d.velocity = relative_history_difference(a.velocity, b.velocity);
    d.translational = relative_history_difference(a.velocity, b.velocity, Rows::translational);
    d.rotational = relative_history_difference(a.velocity, b.velocity, Rows::rotational);
    d.forces = relative_history_difference(a.forces, b.forces);
    return d;
}

}  // namespace rotbeam::cli
