#include "core/continuum/rod_ode.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include <algorithm>
#include <cmath>

#include "core/errors.hpp"
#include "core/so3.hpp"

namespace rotbeam::continuum {
namespace {

constexpr int kDim = 13;  // x (3), q (4), n (3), m (3)

int rhs_trampoline(double t, const double y[], double dydt[], void* params) {
    return static_cast<const RodIntegrator*>(params)->rhs(t, y, dydt);
}

Vec4 quaternion_of(const double y[]) { return Vec4(y[3], y[4], y[5], y[6]); }

}  // namespace

RodIntegrator::RodIntegrator(const RodGeometry& geometry, const Mat6& compliance,
                             double force_scale, double tolerance)
    : geometry_(geometry), compliance_(compliance), force_scale_(force_scale) {
    ROTBEAM_VERIFY(force_scale > 0.0 && tolerance > 0.0, "rod integrator needs positive scales");
    auto* system = new gsl_odeiv2_system{&rhs_trampoline, nullptr, kDim, this};
    system_ = system;
    // rk8pd: Prince–Dormand 8(9), adaptive; the absolute and relative tolerances act on the
    // scaled, O(1) state. The initial step is 1e-3 L; GSL adapts it.
    driver_ =
        gsl_odeiv2_driver_alloc_y_new(system, gsl_odeiv2_step_rk8pd, 1e-3, tolerance, tolerance);
    if (driver_ == nullptr) throw SolverError("continuum: cannot allocate the GSL ODE driver");
    gsl_odeiv2_driver_set_nmax(driver_, 1000000);
}

RodIntegrator::~RodIntegrator() {
    gsl_odeiv2_driver_free(driver_);
    delete static_cast<gsl_odeiv2_system*>(system_);
}

RodState RodIntegrator::unpack(double s, const double y[]) const {
    RodState state;
    state.s = s;
    const double L = geometry_.length();
    state.x = L * Vec3(y[0], y[1], y[2]);
    state.R = so3::quat_to_matrix(quaternion_of(y).normalized());
    state.n = force_scale_ * Vec3(y[7], y[8], y[9]);
    state.m = moment_scale() * Vec3(y[10], y[11], y[12]);
    return state;
}

int RodIntegrator::rhs(double t, const double y[], double dydt[]) const {
    for (int i = 0; i < kDim; ++i)
        if (!std::isfinite(y[i])) return GSL_EBADFUNC;
    const double L = geometry_.length();
    const double s = t * L;
    const RodState state = unpack(s, y);
    Vec6 resultant;
    resultant << state.R.transpose() * state.n, state.R.transpose() * state.m;
    const Vec6 strain = compliance_ * resultant;
    const Vec3 dx = state.R * (Vec3::UnitX() + strain.head<3>());
    const Vec3 omega = geometry_.curvature(s) + strain.tail<3>();
    Vec3 f = loads_->dead_force, mu = loads_->dead_moment;
    if (loads_->has_follower_distributed()) {
        const Mat3 R_rel = state.R * geometry_.frame(s).transpose();
        f += R_rel * loads_->follower_force;
        mu += R_rel * loads_->follower_moment;
    }
    const Vec3 dn = -f;
    const Vec3 dm = -dx.cross(state.n) - mu;
    // q' = ½ q ⊗ (0, Ω) with q = (w, v): (−v·Ω, wΩ + v × Ω) / 2; scaled by L for d/d(s/L).
    const Vec4 q = quaternion_of(y);
    const Vec3 v(q[1], q[2], q[3]);
    const Vec3 dv = 0.5 * L * (q[0] * omega + v.cross(omega));
    dydt[3] = -0.5 * L * v.dot(omega);
    for (int i = 0; i < 3; ++i) {
        dydt[i] = dx[i];
        dydt[4 + i] = dv[i];
        dydt[7 + i] = L * dn[i] / force_scale_;
        dydt[10 + i] = L * dm[i] / moment_scale();
    }
    return GSL_SUCCESS;
}

void RodIntegrator::apply_point_load(const RodPointLoad& load, double y[]) const {
    Vec3 force = load.force, moment = load.moment;
    if (load.follower) {
        const Mat3 R = so3::quat_to_matrix(quaternion_of(y).normalized());
        const Mat3 R_rel = R * geometry_.frame(load.s).transpose();
        force = R_rel * force;
        moment = R_rel * moment;
    }
    for (int i = 0; i < 3; ++i) {
        y[7 + i] -= force[i] / force_scale_;
        y[10 + i] -= moment[i] / moment_scale();
    }
}

bool RodIntegrator::shoot(const Vec6& z, const RodLoads& loads, Vec6& residual,
                          const std::vector<double>& stations, std::vector<RodState>* states) {
    loads_ = &loads;
    const double L = geometry_.length();
    double y[kDim];
    const Vec3 x0 = geometry_.position(0.0) / L;
    const Vec4 q0 = so3::quat_from_matrix(geometry_.frame(0.0));
    for (int i = 0; i < 3; ++i) {
        y[i] = x0[i];
        y[7 + i] = z[i];
        y[10 + i] = z[3 + i];
    }
    for (int i = 0; i < 4; ++i) y[3 + i] = q0[i];
    gsl_odeiv2_driver_reset(driver_);
    double t = 0.0;
    std::size_t next_load = 0, next_station = 0;
    while (true) {
        // The next event: a station, a point load or the free end.
        double target = L;
        if (next_station < stations.size()) target = std::min(target, stations[next_station]);
        if (next_load < loads.points.size()) target = std::min(target, loads.points[next_load].s);
        if (target > t * L) {
            if (gsl_odeiv2_driver_apply(driver_, &t, target / L, y) != GSL_SUCCESS) return false;
        }
        for (; next_station < stations.size() && stations[next_station] <= target; ++next_station)
            if (states != nullptr) states->push_back(unpack(stations[next_station], y));
        bool jumped = false;
        for (; next_load < loads.points.size() && loads.points[next_load].s <= target;
             ++next_load) {
            apply_point_load(loads.points[next_load], y);
            jumped = true;
        }
        if (jumped) gsl_odeiv2_driver_reset(driver_);
        if (target >= L) break;
    }
    for (int i = 0; i < 6; ++i) residual[i] = y[7 + i];
    return residual.allFinite();
}

}  // namespace rotbeam::continuum
