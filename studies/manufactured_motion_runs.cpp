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

template <class P>
void displacement_run(const Model& model, const MotionRunSpec& spec, MotionRunResult& result) {
    form::DisplacementDynamics<P> d(model);
    const form::Mesh& mesh = d.mesh();
    for (size_t i = 0; i < mesh.nodes.size(); ++i) {
        const int n = static_cast<int>(i);
        const oracle::ManufacturedMotion::State x = spec.motion.state(mesh.nodes[i].x0.x(), 0.0);
        d.statics().set_node_state(n, x.u, P::from_rotation_vector(so3::log_map(x.R)));
    }
    d.adopt_static_state();
    for (size_t i = 0; i < mesh.nodes.size(); ++i) {
        if (mesh.nodes[i].dof < 0) continue;
        const oracle::ManufacturedMotion::State x = spec.motion.state(mesh.nodes[i].x0.x(), 0.0);
        d.set_node_velocity(static_cast<int>(i), (Vec6() << x.u_dot, x.omega).finished());
    }
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
    const auto on_output = [&](const TimeStepRecord& r) {
        record(r.time, [&](int p) { return d.point_state(p); });
        VecX v(d.size());
        int k = 0;
        for (size_t i = 0; i < mesh.nodes.size(); ++i) {
            if (mesh.nodes[i].dof < 0) continue;
            v.segment<6>(6 * k++) = d.node_velocity(static_cast<int>(i));
        }
        result.velocity.push_back(v.head(6 * k));
    };
    const int stages = gauss_legendre_stages(spec.integrator);
    const DynamicOutcome out = stages > 0 ? run_gauss_collocation(d, stages, ts, newton, on_output)
                                          : run_generalized_alpha(d, ts, newton, on_output);
    result.status = to_string(out.status);
    result.message = out.message;
    result.steps = out.steps;
    result.newton_iterations = out.newton_iterations;
}

// The exact state at the element mid-points (u, c, F, M, P, H and the rates) and the nodes (û, ĉ).
template <class Element, class Node>
void fill_mixed_state(const form::MixedLayout& layout, const oracle::ManufacturedMotion& mm,
                      Element&& element, Node&& node) {
    for (int n = 0; n < static_cast<int>(layout.nodes.size()); ++n) {
        if (!layout.supported(n))
            node(n, mm.state(layout.nodes[static_cast<size_t>(n)].reference.x(), 0.0));
    }
    for (int e = 0; e < layout.element_count(); ++e) {
        const form::MixedElement& el = layout.elements[static_cast<size_t>(e)];
        const double s =
            layout.nodes[static_cast<size_t>(el.start_node)].reference.x() + 0.5 * el.length;
        element(e, s);
    }
}

// The exact differential state (u, c, P, H; node û, ĉ) and a starting guess of everything else
// (MixedNumbering: the free rod has no support, so no reactions or ρ; the quaternion's norm row
// holds no unknown).
template <class P, class Dyn>
void mixed_initial_state(const Dyn& dyn, const oracle::ManufacturedMotion& mm, VecX& x,
                         VecX& xdot) {
    x = VecX::Zero(dyn.size());
    xdot = VecX::Zero(dyn.size());
    const form::MixedLayout* layout = &dyn.layout();
    auto node_column = [&](int n) { return dyn.node_column(n); };
    auto element_column = [&](int e) { return dyn.element_column(e); };
    const form::MixedNumbering& nb = dyn.numbering();
    const int ou = nb.u(), oc = nb.c(), oF = nb.F(), oP = nb.P();
    fill_mixed_state(
        *layout, mm,
        [&](int e, double s) {
            const oracle::ManufacturedMotion::State st = mm.state(s, 0.0);
            const auto c = P::from_rotation_vector(mm.rotation_vector(s, 0.0));
            const Mat3 Rt = st.R.transpose();
            const Vec3 V = Rt * st.u_dot, W = Rt * st.omega;
            Vec6 vel, acc;
            vel << V, W;
            acc << Rt * st.u_ddot - W.cross(V), Rt * st.omega_dot;
            const int o = element_column(e);
            x.segment<3>(o + ou) = st.u;
            x.segment<P::kSize>(o + oc) = c;
            x.segment<6>(o + oF) = mm.stiffness * mm.strains(s, 0.0);
            x.segment<6>(o + oP) = mm.mass * vel;
            xdot.segment<3>(o + ou) = st.u_dot;
            xdot.segment<P::kSize>(o + oc) = P::material_tangent_inverse(c) * W;  // Ω = H_m ċ
            xdot.segment<6>(o + oP) = mm.mass * acc;
        },
        [&](int n, const oracle::ManufacturedMotion::State& st) {
            const double s = layout->nodes[static_cast<size_t>(n)].reference.x();
            x.segment<3>(node_column(n)) = st.u;
            x.segment<P::kSize>(node_column(n) + 3) =
                P::from_rotation_vector(mm.rotation_vector(s, 0.0));
        });
}

template <class P>
void mixed_run(const Model& model, const MotionRunSpec& spec, MotionRunResult& result) {
    form::MixedDynamicsOf<P> dyn(model, spec.end_time);
    VecX x, xdot;
    mixed_initial_state<P>(dyn, spec.motion, x, xdot);
    result.dofs = dyn.size();
    DaeSettings s;
    s.end_time = spec.end_time;
    s.time_step = spec.dt;
    s.output_interval = model.analysis.dynamics.output_interval;
    s.relative_tolerance = s.absolute_tolerance = spec.tolerance;
    if (spec.newton_tolerance > 0.0) {
        s.newton.residual_tolerance = s.newton.increment_tolerance = spec.newton_tolerance;
    }
    Recorder record{model, spec.motion, result};
    const form::MixedNumbering& nb = dyn.numbering();
    const DaeOutput output = [&](double t, const VecX& xs, const VecX&, int) {
        record(t, [&](int p) { return dyn.point_state(xs, t, p); });
        VecX momenta(6 * nb.element_count), forces(6 * nb.element_count);
        for (int e = 0; e < nb.element_count; ++e) {
            momenta.segment<6>(6 * e) = xs.segment<6>(nb.element_column(e) + nb.P());
            forces.segment<6>(6 * e) = xs.segment<6>(nb.element_column(e) + nb.F());
        }
        result.velocity.push_back(momenta);
        result.forces.push_back(forces);
    };
    const bool ida = spec.integrator == Integrator::ida;
    const DaeOutcome out = ida ? integrate_ida(dyn, x, xdot, s, output)
                           : spec.integrator == Integrator::radau_iia_3
                               ? integrate_radau_iia(dyn, x, xdot, s, output)
                               : integrate_trapezoidal(dyn, x, xdot, s, output);
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
    m.analysis.dynamics.output_interval = spec.end_time / kMotionOutputs;
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

// Max over the common outputs of ‖a_k − b_k‖∞ over the max over the outputs of ‖b_k‖∞.
double relative_history_difference(const std::vector<VecX>& a, const std::vector<VecX>& b) {
    const size_t n = std::min(a.size(), b.size());
    double diff = 0.0, size = 0.0;
    for (size_t k = 0; k < n; ++k) {
        if (a[k].size() != b[k].size() || b[k].size() == 0) return 0.0;
        diff = std::max(diff, (a[k] - b[k]).cwiseAbs().maxCoeff());
        size = std::max(size, b[k].cwiseAbs().maxCoeff());
    }
    return size > 0.0 ? diff / size : 0.0;
}

}  // namespace

ComponentDifferences component_differences(const MotionRunResult& a, const MotionRunResult& b,
                                           double length) {
    ComponentDifferences d;
    run_difference(a, b, length, d.u, d.R);
    d.velocity = relative_history_difference(a.velocity, b.velocity);
    d.forces = relative_history_difference(a.forces, b.forces);
    return d;
}

}  // namespace rotbeam::cli
