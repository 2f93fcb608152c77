#include "core/continuum/continuum.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_multiroots.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <sstream>

#include "core/continuum/rod_geometry.hpp"
#include "core/continuum/rod_ode.hpp"
#include "core/errors.hpp"
#include "core/oracles/gsl_guard.hpp"
#include "core/so3.hpp"

namespace rotbeam {
namespace {

using continuum::RodGeometry;
using continuum::RodIntegrator;
using continuum::RodLoads;
using continuum::RodPointLoad;
using continuum::RodState;

// The parts of the model the shooting needs, checked once.
struct Setup {
    const Model* model = nullptr;
    std::unique_ptr<RodGeometry> geometry;
    Mat6 compliance = Mat6::Zero();
    double bending_stiffness = 0.0;
    std::vector<double> point_s;  // reference arc length of each named point
};

void require(bool condition, const std::string& what) {
    if (!condition) throw InputError("continuum solver: " + what);
}

double locate_point(const Setup& setup, int index) {
    const std::optional<double> s = setup.geometry->locate(setup.model->points[index].position);
    require(s.has_value(), "point '" + setup.model->points[index].name +
                               "' does not lie on the member's reference line");
    return *s;
}

Setup make_setup(const Model& model) {
    require(model.analysis.kind == AnalysisKind::static_, "only static analyses are supported");
    require(model.members.size() == 1, "exactly one member is supported");
    const Member& member = model.members.front();
    require(member.sections.size() == 1, "only one constant section is supported");
    require(model.constraints.size() == 1 &&
                model.constraints.front().kind == Constraint::Kind::clamped &&
                model.constraints.front().point == member.start_point,
            "exactly one constraint, a clamp at the member's start point, is supported");
    require(model.gravity.norm() == 0.0, "gravity is not supported");
    Setup setup;
    setup.model = &model;
    setup.geometry = std::make_unique<RodGeometry>(model, member);
    setup.compliance = member.sections.front().section.compliance;
    require(setup.compliance.allFinite(), "the compliance is not finite");
    const double c_bend = std::max(setup.compliance(4, 4), setup.compliance(5, 5));
    require(c_bend > 0.0, "the section has no bending compliance");
    setup.bending_stiffness = 1.0 / c_bend;
    for (int i = 0; i < static_cast<int>(model.points.size()); ++i)
        setup.point_s.push_back(locate_point(setup, i));
    for (const DistributedLoad& d : model.distributed_loads)
        require(d.member == 0, "a distributed load names an unknown member");
    return setup;
}

RodLoads loads_at(const Setup& setup, double factor) {
    const Model& model = *setup.model;
    RodLoads loads;
    for (const PointLoad& p : model.point_loads) {
        require(p.point >= 0 && p.point < static_cast<int>(model.points.size()),
                "a point load names an unknown point");
        const double s = setup.point_s[p.point];
        if (s <= 0.0) continue;  // at the clamp: carried by the reaction
        loads.points.push_back(
            {s, factor * p.force, factor * p.moment, p.frame == LoadFrame::follower});
    }
    std::stable_sort(loads.points.begin(), loads.points.end(),
                     [](const RodPointLoad& a, const RodPointLoad& b) { return a.s < b.s; });
    for (const DistributedLoad& d : model.distributed_loads) {
        if (d.frame == LoadFrame::follower) {
            loads.follower_force += factor * d.force;
            loads.follower_moment += factor * d.moment;
        } else {
            loads.dead_force += factor * d.force;
            loads.dead_moment += factor * d.moment;
        }
    }
    return loads;
}

// GSL multiroot callbacks: f is the shooting residual, df its central-difference Jacobian.
struct Shooting {
    RodIntegrator* rod;
    const RodLoads* loads;
    std::vector<double> no_stations;
};

Vec6 to_vec6(const gsl_vector* x) {
    Vec6 v;
    for (int i = 0; i < 6; ++i) v[i] = gsl_vector_get(x, i);
    return v;
}

int shooting_f(const gsl_vector* x, void* params, gsl_vector* f) {
    Shooting& s = *static_cast<Shooting*>(params);
    Vec6 r;
    if (!s.rod->shoot(to_vec6(x), *s.loads, r, s.no_stations, nullptr)) return GSL_EBADFUNC;
    for (int i = 0; i < 6; ++i) gsl_vector_set(f, i, r[i]);
    return GSL_SUCCESS;
}

// Step h = 1e-5 (unknowns are O(1) after scaling): truncation h² |r'''| ~ 1e-10 and integration
// noise ~ tolerance/h ~ 1e-8 relative; hybridsj needs no more to converge to the residual test.
int shooting_df(const gsl_vector* x, void* params, gsl_matrix* J) {
    Shooting& s = *static_cast<Shooting*>(params);
    const Vec6 z = to_vec6(x);
    for (int j = 0; j < 6; ++j) {
        const double h = 1e-5 * std::max(1.0, std::abs(z[j]));
        Vec6 zp = z, zm = z, rp, rm;
        zp[j] += h;
        zm[j] -= h;
        if (!s.rod->shoot(zp, *s.loads, rp, s.no_stations, nullptr) ||
            !s.rod->shoot(zm, *s.loads, rm, s.no_stations, nullptr))
            return GSL_EBADFUNC;
        for (int i = 0; i < 6; ++i) gsl_matrix_set(J, i, j, (rp[i] - rm[i]) / (2.0 * h));
    }
    return GSL_SUCCESS;
}

int shooting_fdf(const gsl_vector* x, void* params, gsl_vector* f, gsl_matrix* J) {
    const int status = shooting_f(x, params, f);
    return status != GSL_SUCCESS ? status : shooting_df(x, params, J);
}

struct SolveResult {
    bool converged = false;
    int iterations = 0;
    double residual = 0.0;
    Vec6 z = Vec6::Zero();
};

double max_abs(const gsl_vector* v) {
    double m = 0.0;
    for (std::size_t i = 0; i < v->size; ++i) m = std::max(m, std::abs(gsl_vector_get(v, i)));
    return m;
}

// The residual tolerance for these loads: options.residual_tolerance times the loads' size in
// the scaled units (at least 1e-3), so that loads much smaller than EI/L² are still resolved
// relatively (down to the ODE tolerance's absolute floor) and loads much larger than EI/L² are
// held to the same relative accuracy, which is what the integration can deliver.
double residual_tolerance(const RodIntegrator& rod, const RodLoads& loads,
                          const ContinuumOptions& options) {
    const double length = rod.moment_scale() / rod.force_scale();
    double size =
        (loads.dead_force.norm() + loads.follower_force.norm()) * length / rod.force_scale() +
        (loads.dead_moment.norm() + loads.follower_moment.norm()) * length / rod.moment_scale();
    for (const RodPointLoad& p : loads.points)
        size += p.force.norm() / rod.force_scale() + p.moment.norm() / rod.moment_scale();
    return options.residual_tolerance * std::max(size, 1e-3);
}

// Newton-type hybrid (Powell's dogleg with the Jacobian above) from the guess z.
SolveResult solve_shooting(RodIntegrator& rod, const RodLoads& loads, const Vec6& guess,
                           const ContinuumOptions& options) {
    Shooting shooting{&rod, &loads, {}};
    gsl_multiroot_function_fdf function{&shooting_f, &shooting_df, &shooting_fdf, 6, &shooting};
    std::unique_ptr<gsl_multiroot_fdfsolver, decltype(&gsl_multiroot_fdfsolver_free)> solver(
        gsl_multiroot_fdfsolver_alloc(gsl_multiroot_fdfsolver_hybridsj, 6),
        &gsl_multiroot_fdfsolver_free);
    std::unique_ptr<gsl_vector, decltype(&gsl_vector_free)> x0(gsl_vector_alloc(6),
                                                               &gsl_vector_free);
    for (int i = 0; i < 6; ++i) gsl_vector_set(x0.get(), i, guess[i]);
    SolveResult result;
    const double tolerance = residual_tolerance(rod, loads, options);
    if (gsl_multiroot_fdfsolver_set(solver.get(), &function, x0.get()) != GSL_SUCCESS)
        return result;
    for (int it = 0; it <= options.max_iterations; ++it) {
        result.residual = max_abs(solver->f);
        if (result.residual < tolerance) {
            result.converged = true;
            result.z = to_vec6(solver->x);
            return result;
        }
        if (it == options.max_iterations) break;
        if (gsl_multiroot_fdfsolver_iterate(solver.get()) != GSL_SUCCESS) break;
        ++result.iterations;
    }
    return result;
}

// The reported step's states: named points and centreline samples from one final shooting.
ContinuumStep record_step(const Setup& setup, RodIntegrator& rod, const RodLoads& loads,
                          const Vec6& z, const ContinuumOptions& options) {
    const RodGeometry& g = *setup.geometry;
    std::vector<double> samples;
    const int count = std::max(2, options.centreline_samples);
    for (int i = 0; i < count; ++i) samples.push_back(g.length() * i / (count - 1));
    std::vector<double> rotation_samples;
    const int rotation_count = std::max(2, options.rotation_samples);
    for (int i = 0; i < rotation_count; ++i) {
        rotation_samples.push_back(g.length() * i / (rotation_count - 1));
    }
    std::vector<double> stations = samples;
    stations.insert(stations.end(), setup.point_s.begin(), setup.point_s.end());
    stations.insert(stations.end(), rotation_samples.begin(), rotation_samples.end());
    std::sort(stations.begin(), stations.end());
    stations.erase(std::unique(stations.begin(), stations.end()), stations.end());
    std::vector<RodState> states;
    Vec6 residual;
    if (!rod.shoot(z, loads, residual, stations, &states) || states.size() != stations.size())
        throw SolverError("continuum: the recording integration failed");
    const auto state_at = [&](double s) -> const RodState& {
        return states[std::lower_bound(stations.begin(), stations.end(), s) - stations.begin()];
    };
    ContinuumStep step;
    step.residual = residual.cwiseAbs().maxCoeff();
    for (double s : setup.point_s) {
        const RodState& state = state_at(s);
        step.points.push_back({state.x - g.position(s), state.R * g.frame(s).transpose()});
    }
    step.root_force = states.front().n;
    step.root_moment = states.front().m;
    for (double s : samples) {
        step.centreline_s.push_back(s);
        step.centreline.push_back(state_at(s).x);
    }
    for (double s : rotation_samples) {
        step.rotations.push_back({0, true, state_at(s).R * g.frame(s).transpose()});
    }
    return step;
}

constexpr int kMonitoredSections = 8;  // equally spaced sections watched for the turn limit

// Continuation state between load increments: the last two converged roots for a secant guess.
// `rotations` are the sections' absolute rotations at `stations` in the last converged state.
struct Path {
    double lambda = 0.0;
    Vec6 z = Vec6::Zero();
    Vec6 z_previous = Vec6::Zero();
    double last_increment = 0.0;
    std::vector<double> stations;
    std::vector<Mat3> rotations;
};

// Largest rotation of any monitored section between the path's last state and the root z, with
// the new rotations in `rotations`. A shooting problem has other roots (rods with extra loops);
// an increment that turns a section by more than options.max_turn is where the root found may
// belong to another branch, so it is cut instead of accepted.
double largest_turn(RodIntegrator& rod, const RodLoads& loads, const Path& path, const Vec6& z,
                    std::vector<Mat3>& rotations) {
    std::vector<RodState> states;
    Vec6 residual;
    if (!rod.shoot(z, loads, residual, path.stations, &states)) return kPi;
    double turn = 0.0;
    rotations.clear();
    for (std::size_t i = 0; i < states.size(); ++i) {
        rotations.push_back(states[i].R);
        turn = std::max(turn, so3::rotation_angle(states[i].R * path.rotations[i].transpose()));
    }
    return turn;
}

// One increment to `next`: secant predictor, then (if that fails) the last root as the guess.
SolveResult advance(const Setup& setup, RodIntegrator& rod, const Path& path, double next,
                    const ContinuumOptions& options) {
    const RodLoads loads = loads_at(setup, next);
    if (path.last_increment != 0.0) {
        const Vec6 guess =
            path.z + (path.z - path.z_previous) * ((next - path.lambda) / path.last_increment);
        const SolveResult predicted = solve_shooting(rod, loads, guess, options);
        if (predicted.converged) return predicted;
    }
    return solve_shooting(rod, loads, path.z, options);
}

// Reaches `target` from path.lambda in `substeps` increments, bisecting failed increments and
// growing them back after successes. Returns false (with a message) when one increment needs
// more than options.max_step_cuts consecutive bisections.
bool reach(const Setup& setup, RodIntegrator& rod, Path& path, double target, int substeps,
           const ContinuumOptions& options, ContinuumStep& step, std::string& message) {
    const double nominal = (target - path.lambda) / substeps;
    double increment = nominal;
    int cuts = 0;
    while (path.lambda != target) {
        const bool last = std::abs(target - path.lambda) <= std::abs(increment) * (1.0 + 1e-12);
        const double next = last ? target : path.lambda + increment;
        const SolveResult result = advance(setup, rod, path, next, options);
        step.iterations += result.iterations;
        std::vector<Mat3> rotations;
        const bool accepted =
            result.converged &&
            largest_turn(rod, loads_at(setup, next), path, result.z, rotations) <= options.max_turn;
        if (!accepted) {
            if (++cuts > options.max_step_cuts) {
                std::ostringstream s;
                s << "shooting failed from load factor " << path.lambda << " to " << next
                  << " after " << options.max_step_cuts << " step cuts (residual "
                  << result.residual << (result.converged ? ", turn too large" : "") << ")";
                message = s.str();
                return false;
            }
            increment /= 2.0;
            continue;
        }
        path.z_previous = path.z;
        path.last_increment = next - path.lambda;
        path.z = result.z;
        path.rotations = rotations;
        path.lambda = next;
        ++step.substeps;
        cuts = 0;  // the limit is on consecutive bisections of one increment
        if (std::abs(2.0 * increment) <= std::abs(nominal)) increment *= 2.0;
    }
    return true;
}

ContinuumOutcome run(const Model& model, const ContinuumOptions& options) {
    ContinuumOutcome outcome;
    const Setup setup = make_setup(model);
    const double L = setup.geometry->length();
    RodIntegrator rod(*setup.geometry, setup.compliance, setup.bending_stiffness / (L * L),
                      options.ode_tolerance);
    std::vector<double> factors = model.analysis.statics.load_factors;
    if (factors.empty()) factors.push_back(1.0);
    const int substeps = std::max(1, model.analysis.statics.substeps);
    Path path;
    for (int i = 1; i <= kMonitoredSections; ++i) {
        path.stations.push_back(L * i / kMonitoredSections);
        path.rotations.push_back(setup.geometry->frame(path.stations.back()));
    }
    for (double target : factors) {
        ContinuumStep step;
        if (!reach(setup, rod, path, target, substeps, options, step, outcome.message)) {
            outcome.status = "diverged";
            return outcome;
        }
        const int iterations = step.iterations, taken = step.substeps;
        step = record_step(setup, rod, loads_at(setup, target), path.z, options);
        step.load_factor = target;
        step.iterations = iterations;
        step.substeps = taken;
        outcome.steps.push_back(std::move(step));
    }
    outcome.status = "converged";
    std::ostringstream s;
    s << "continuum reference: " << outcome.steps.size() << " load steps, free-end residual "
      << outcome.steps.back().residual << " (scaled)";
    outcome.message = s.str();
    return outcome;
}

}  // namespace

ContinuumOutcome solve_continuum(const Model& model, const ContinuumOptions& options) {
    const GslErrorHandlerOff guard;
    try {
        return run(model, options);
    } catch (const InputError& e) {
        return {"error", e.what(), {}};
    } catch (const SolverError& e) {
        return {"error", e.what(), {}};
    }
}

}  // namespace rotbeam
