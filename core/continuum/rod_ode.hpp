// The static Cosserat rod ODE in compliance form and its integration from the clamped root.
//
// State along the reference arc length s: centreline x, absolute rotation R = R(q) (material →
// inertial, unit quaternion q, scalar first), internal force n and moment m in inertial
// components (the action of the part beyond s on the part before it). With the compliance C
// (6×6, material axes, rows may be zero = rigid) and the material reference curvature k^r:
//   [γ; κ] = C [Rᵀn; Rᵀm],                 (strains [ε11, 2ε12, 2ε13] and curvature change)
//   x' = R (e1 + γ),   R' = R (k^r + κ)~   ⇔  q' = ½ q ⊗ (0, k^r + κ),
//   n' + f = 0,        m' + x' × n + μ = 0,  (f, μ distributed force/moment per unit s)
// the strong form of seed 000 Eq. 9 / seed 002 Eq. 17 without inertia. Point loads (F, M) at s_i
// are jumps n(s_i⁺) = n(s_i⁻) − F, m(s_i⁺) = m(s_i⁻) − M; a follower load is R R^r(s_i)ᵀ F₀.
// Everything is integrated in scaled variables (s/L, x/L, q, n/F_s, m/(F_s L)) with
// F_s = EI/L², so one absolute/relative tolerance fits every component.
#pragma once

#include <vector>

#include "core/continuum/rod_geometry.hpp"
#include "core/types.hpp"

struct gsl_odeiv2_driver_struct;

namespace rotbeam::continuum {

struct RodPointLoad {
    double s = 0.0;  // > 0 (a load at the clamped root goes into the reaction)
    Vec3 force = Vec3::Zero();
    Vec3 moment = Vec3::Zero();
    bool follower = false;
};

// Loads at one load factor (already multiplied by it).
struct RodLoads {
    std::vector<RodPointLoad> points;                                    // sorted by s
    Vec3 dead_force = Vec3::Zero(), dead_moment = Vec3::Zero();          // per unit length
    Vec3 follower_force = Vec3::Zero(), follower_moment = Vec3::Zero();  // f₀, μ₀ per length
    bool has_follower_distributed() const {
        return follower_force.squaredNorm() + follower_moment.squaredNorm() > 0.0;
    }
};

struct RodState {
    double s = 0.0;
    Vec3 x = Vec3::Zero();
    Mat3 R = Mat3::Identity();
    Vec3 n = Vec3::Zero();
    Vec3 m = Vec3::Zero();
};

class RodIntegrator {
  public:
    RodIntegrator(const RodGeometry& geometry, const Mat6& compliance, double force_scale,
                  double tolerance);
    ~RodIntegrator();
    RodIntegrator(const RodIntegrator&) = delete;
    RodIntegrator& operator=(const RodIntegrator&) = delete;

    double force_scale() const { return force_scale_; }
    double moment_scale() const { return force_scale_ * geometry_.length(); }

    // Integrates from the clamped root with the scaled root unknowns z = [n(0)/F_s; m(0)/M_s] and
    // returns the scaled free-end residual [n(L⁺)/F_s; m(L⁺)/M_s] (zero at a solution). States
    // at `stations` (sorted, in [0, L]) are appended to `states` when it is non-null. Returns
    // false when the integrator fails (non-finite state, step-size underflow).
    bool shoot(const Vec6& z, const RodLoads& loads, Vec6& residual,
               const std::vector<double>& stations, std::vector<RodState>* states);

    // The right-hand side in scaled variables (public for the GSL trampoline).
    int rhs(double t, const double y[], double dydt[]) const;

  private:
    RodState unpack(double s, const double y[]) const;
    void apply_point_load(const RodPointLoad& load, double y[]) const;

    const RodGeometry& geometry_;
    Mat6 compliance_;
    double force_scale_;
    const RodLoads* loads_ = nullptr;
    gsl_odeiv2_driver_struct* driver_ = nullptr;
    void* system_ = nullptr;  // gsl_odeiv2_system, owned
};

}  // namespace rotbeam::continuum
