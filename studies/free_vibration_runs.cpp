#include "free_vibration_runs.hpp"

#include <chrono>
#include <cmath>
#include <sstream>

#include "cases/loader/case_loader.hpp"
#include "combinations/dispatch.hpp"
#include "core/dae_driver.hpp"
#include "core/errors.hpp"
#include "core/gauss_collocation.hpp"
#include "core/generalized_alpha.hpp"
#include "core/so3.hpp"
#include "core/static_driver.hpp"
#include "formulations/displacement/displacement_dynamics.hpp"
#include "formulations/mixed/mixed_dynamics_of.hpp"
#include "formulations/mixed/mixed_statics_of.hpp"
#include "parameterizations/registry.hpp"
#include "runs/catalog.hpp"
#include "studies/guarded_run.hpp"

namespace rotbeam::cli {

namespace {

// The mesh node nearest to a point of the reference line.
int nearest_node(const form::Mesh& mesh, const Vec3& x) {
    int best = 0;
    for (size_t i = 0; i < mesh.nodes.size(); ++i) {
        if ((mesh.nodes[i].x0 - x).norm() < (mesh.nodes[static_cast<size_t>(best)].x0 - x).norm())
            best = static_cast<int>(i);
    }
    return best;
}

template <class P>
void free_vibration_displacement(const Model& model, const FreeVibrationSpec& spec,
                                 FreeVibrationRun& run) {
    form::DisplacementDynamics<P> d(model);
    NewtonSettings newton = newton_settings_from(model.solver, model.analysis.statics);
    newton.contraction_stop = spec.contraction_stop;
    d.statics().set_time(0.0);
    const StaticOutcome start = run_static(d.statics(), {1.0}, newton, {});
    if (!has_solution(start.status)) {
        run.status = to_string(start.status);
        run.message = "static state: " + start.message;
        return;
    }
    d.adopt_static_state();
    const int tip = model.point_index("tip");
    const int tip_node = nearest_node(d.mesh(), model.points[static_cast<size_t>(tip)].position);
    const int root_node = nearest_node(
        d.mesh(), model.points[static_cast<size_t>(model.point_index("root"))].position);
    TimeIntegrationSettings ts;
    ts.time_step = spec.dt;
    ts.end_time = spec.end_time;
    ts.output_interval = spec.output_interval;
    ts.rho_infinity = spec.rho_infinity;
    const auto on_output = [&](const TimeStepRecord& r) {
        const PointState s = d.point_state(tip);
        const Vec6& v = d.node_velocity(tip_node);
        const Vec6 reaction = d.reaction(root_node);
        run.times.push_back(r.time);
        run.energy.push_back(d.energy().total());
        run.values.push_back({s.displacement.z(), so3::log_map(s.rotation).y(), v[2], v[4],
                              reaction[2], reaction[4]});
    };
    const int stages = gauss_legendre_stages(spec.integrator);
    const DynamicOutcome out = stages > 0 ? run_gauss_collocation(d, stages, ts, newton, on_output)
                                          : run_generalized_alpha(d, ts, newton, on_output);
    run.status = to_string(out.status);
    run.message = out.message;
    run.steps = out.steps;
    run.iterations = out.newton_iterations;
}

template <class P>
void free_vibration_mixed(const Model& model, const FreeVibrationSpec& spec,
                          FreeVibrationRun& run) {
    form::MixedStaticsOf<P> statics(model);
    NewtonSettings newton = newton_settings_from(model.solver, model.analysis.statics);
    const StaticOutcome start = run_static(statics, {1.0}, newton, {});
    if (!has_solution(start.status)) {
        run.status = to_string(start.status);
        run.message = "static state: " + start.message;
        return;
    }
    // Loads at max(t, 1e-6 Δt): the release's right limit at the start (mixed_dynamics.hpp).
    form::MixedDynamicsOf<P> dyn(model, spec.end_time, 1e-6 * spec.dt);
    VecX x = dyn.from_static_state(statics.state_vector());
    VecX xdot = VecX::Zero(dyn.size());
    DaeSettings s;
    s.end_time = spec.end_time;
    s.time_step = spec.dt;
    s.output_interval = spec.output_interval;
    s.newton.residual_tolerance = s.newton.increment_tolerance = spec.newton_tolerance;
    s.newton.contraction_stop = spec.contraction_stop;
    const int tip = model.point_index("tip");
    const form::MixedNumbering& nb = dyn.numbering();
    const int last = nb.element_column(nb.element_count - 1);
    const int root = dyn.node_column(0);
    const DaeOutput output = [&](double t, const VecX& xs, const VecX&, int) {
        const PointState p = dyn.point_state(xs, t, tip);
        run.times.push_back(t);
        run.energy.push_back(dyn.energy(xs).total());
        run.values.push_back({p.displacement.z(), so3::log_map(p.rotation).y(),
                              xs[last + nb.P() + 2], xs[last + nb.P() + 4], xs[root + 2],
                              xs[root + 4]});
    };
    const DaeOutcome out = spec.integrator == Integrator::radau_iia_3
                               ? integrate_radau_iia(dyn, x, xdot, s, output)
                               : integrate_trapezoidal(dyn, x, xdot, s, output);
    run.status = to_string(out.status);
    run.message = out.message;
    run.steps = out.steps;
    run.iterations = out.newton_iterations;
}

}  // namespace

const char* group_name(FreeVibrationGroup g) {
    switch (g) {
        case FreeVibrationGroup::position:
            return "u";
        case FreeVibrationGroup::rotation:
            return "rotation";
        case FreeVibrationGroup::velocity:
            return "velocity";
        case FreeVibrationGroup::force:
            return "force";
    }
    return "?";
}

bool FreeVibrationRun::ok() const { return has_solution(status); }

std::string FreeVibrationSpec::label() const {
    std::ostringstream s;
    s << choice_name(formulation) << "/" << param::name_of(rotation);
    if (wm_map == WmMap::continuous) s << "-continuous";
    s << "/";
    const int stages = gauss_legendre_stages(integrator);
    if (stages > 0) {
        s << "gl" << stages;
    } else if (integrator == Integrator::generalized_alpha) {
        s << "ga" << rho_infinity;
    } else {
        s << choice_name(integrator);
    }
    return s.str();
}

Model free_vibration_model(const FreeVibrationSpec& spec) {
    Model m = load_case(resolve_case_path("free-vibration"));
    m.members[0].elements = spec.elements;
    m.discretization.formulation = spec.formulation;
    m.discretization.rotation = spec.rotation;
    m.discretization.order = spec.order;
    m.discretization.mixed.wm_map = spec.wm_map;
    m.analysis.dynamics.integrator = spec.integrator;
    m.analysis.dynamics.rho_infinity = spec.rho_infinity;
    m.analysis.dynamics.time_step = spec.dt;
    m.analysis.dynamics.end_time = spec.end_time;
    m.analysis.dynamics.output_interval = spec.output_interval;
    m.solver.residual_tolerance = m.solver.increment_tolerance = spec.newton_tolerance;
    return m;
}

FreeVibrationRun run_free_vibration(const FreeVibrationSpec& spec) {
    const Model model = free_vibration_model(spec);
    FreeVibrationRun run;
    run_guarded(run, [&] {
        comb::dispatch_formulation(spec.formulation, [&]<Formulation F>() {
            comb::dispatch_parameterization_of<F>(model.discretization, [&]<class P>() {
                if constexpr (F == Formulation::displacement) {
                    free_vibration_displacement<P>(model, spec, run);
                } else {
                    free_vibration_mixed<P>(model, spec, run);
                }
            });
        });
    });
    return run;
}

double group_difference(const FreeVibrationRun& a, const FreeVibrationRun& b,
                        FreeVibrationGroup g) {
    // Columns of each group in the recorded values.
    size_t from = 0, count = 1;
    switch (g) {
        case FreeVibrationGroup::position:
            from = 0;
            break;
        case FreeVibrationGroup::rotation:
            from = 1;
            break;
        case FreeVibrationGroup::velocity:
            from = 2;
            count = 2;
            break;
        case FreeVibrationGroup::force:
            from = 4;
            count = 2;
            break;
    }
    const size_t n = std::min(a.values.size(), b.values.size());
    double diff = 0.0, size = 0.0;
    for (size_t k = 0; k < n; ++k) {
        for (size_t i = from; i < from + count; ++i) {
            diff = std::max(diff, std::abs(a.values[k][i] - b.values[k][i]));
            size = std::max(size, std::abs(b.values[k][i]));
        }
    }
    return size > 0.0 ? diff / size : 0.0;
}

namespace {

// Upward zero crossings of the tip's u_z: the number of first-mode periods in the run.
double first_mode_periods(const FreeVibrationRun& r) {
    std::vector<double> crossings;
    for (size_t k = 1; k < r.values.size(); ++k) {
        const double a = r.values[k - 1][0], b = r.values[k][0];
        if (a < 0.0 && b >= 0.0) {
            crossings.push_back(r.times[k - 1] + (r.times[k] - r.times[k - 1]) * a / (a - b));
        }
    }
    if (crossings.size() < 2) return 0.0;
    const double period =
        (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
    return (r.times.back() - r.times.front()) / period;
}

}  // namespace

EnergyDrift energy_drift(const FreeVibrationRun& run) {
    EnergyDrift d;
    if (run.energy.size() < 2) return d;
    d.periods = first_mode_periods(run);
    if (d.periods <= 0.0) return d;
    const double E0 = run.energy.front();
    for (double e : run.energy) d.max_deviation = std::max(d.max_deviation, std::abs(e - E0) / E0);
    const size_t window = static_cast<size_t>(
        std::max(1.0, std::round(10.0 * static_cast<double>(run.energy.size() - 1) / d.periods)));
    const double per_time = d.periods / (run.times.back() - run.times.front());
    for (size_t k = 0; k + window <= run.energy.size(); k += window) {
        double m = 0.0;
        for (size_t i = k; i < k + window; ++i) m += (run.energy[i] - E0) / E0;
        d.window_means.push_back(m / static_cast<double>(window));
        d.window_periods.push_back(per_time * (run.times[k + window / 2] - run.times.front()));
    }
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    const double n = static_cast<double>(d.window_means.size());
    for (size_t k = 0; k < d.window_means.size(); ++k) {
        sx += d.window_periods[k];
        sy += d.window_means[k];
        sxx += d.window_periods[k] * d.window_periods[k];
        sxy += d.window_periods[k] * d.window_means[k];
    }
    if (n > 1) d.drift_per_1000_periods = 1000.0 * (n * sxy - sx * sy) / (n * sxx - sx * sx);
    return d;
}

}  // namespace rotbeam::cli
