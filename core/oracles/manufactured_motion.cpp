#include "core/oracles/manufactured_motion.hpp"

#include <cmath>

#include "core/oracles/manufactured_rod.hpp"
#include "core/so3.hpp"

namespace rotbeam::oracle {

namespace {

const Vec3 kE1 = Vec3::UnitX();
const Vec3 kE3 = Vec3::UnitZ();

// A field f(s, t) = g(t) F(s) and the derivatives the loads need: ∂s, ∂ss, ∂t, ∂tt.
struct Scalar {
    double v, s1, s2, t1, t2;
};
struct Vector {
    Vec3 v, s1, s2, t1, t2;
};

// The time functions λ(t), μ(t), the spin φ(t) and their first two derivatives.
struct TimeValues {
    double l, l1, l2, m, m1, m2, p, p1, p2;
};

TimeValues time_values(const ManufacturedMotion& mm, double t) {
    const double x = mm.omega1 * t + mm.phase1, y = mm.omega2 * t;
    const double w1 = mm.omega1, w2 = mm.omega2;
    return {std::sin(x),
            w1 * std::cos(x),
            -w1 * w1 * std::sin(x),
            std::cos(y),
            -w2 * std::sin(y),
            -w2 * w2 * std::cos(y),
            mm.spin0 + mm.spin_rate * t + 0.5 * mm.spin_acceleration * t * t,
            mm.spin_rate + mm.spin_acceleration * t,
            mm.spin_acceleration};
}

Scalar product(double g, double g1, double g2, double F, double F1, double F2) {
    return {g * F, g * F1, g * F2, g1 * F, g2 * F};
}

Vector product(double g, double g1, double g2, const Vec3& F, const Vec3& F1, const Vec3& F2) {
    return {g * F, g * F1, g * F2, g1 * F, g2 * F};
}

struct Fields {
    Scalar alpha, beta;
    Vector u;
};

Fields fields(const ManufacturedMotion& mm, double s, double t) {
    const double L = mm.length, x = s / L, pi = kPi;
    const TimeValues g = time_values(mm, t);
    const double sn = std::sin(pi * x), cs = std::cos(pi * x);
    Fields f;
    // α = φ(t) + λ(t) a cos(πs̄), β = μ(t) b sin²(πs̄).
    const Scalar twist = product(g.l, g.l1, g.l2, mm.twist * cs, -mm.twist * pi * sn / L,
                                 -mm.twist * pi * pi * cs / (L * L));
    f.alpha = {g.p + twist.v, twist.s1, twist.s2, g.p1 + twist.t1, g.p2 + twist.t2};
    f.beta = product(g.m, g.m1, g.m2, mm.b * sn * sn, mm.b * pi * std::sin(2 * pi * x) / L,
                     2.0 * mm.b * pi * pi * std::cos(2 * pi * x) / (L * L));
    // c₁ = cos(πs̄), c₂ = cos(2πs̄) and their s-derivatives (both vanish at the ends).
    const double s2 = std::sin(2 * pi * x), c2 = std::cos(2 * pi * x);
    const Eigen::Vector2d c(cs, c2);
    const Eigen::Vector2d c1 = Eigen::Vector2d(-pi * sn, -2 * pi * s2) / L;
    const Eigen::Vector2d cc = Eigen::Vector2d(-pi * pi * cs, -4 * pi * pi * c2) / (L * L);
    // w = L(0.05 c₁, 0.2 c₁, 0.1 c₂), v = L(0, 0.1 c₂, −0.15 c₁).
    auto w_of = [L](const Eigen::Vector2d& p) {
        return Vec3(L * 0.05 * p[0], L * 0.2 * p[0], L * 0.1 * p[1]);
    };
    auto v_of = [L](const Eigen::Vector2d& p) {
        return Vec3(0.0, L * 0.1 * p[1], L * -0.15 * p[0]);
    };
    const Vector uw = product(g.l, g.l1, g.l2, w_of(c), w_of(c1), w_of(cc));
    const Vector uv = product(g.m, g.m1, g.m2, v_of(c), v_of(c1), v_of(cc));
    f.u = {uw.v + uv.v, uw.s1 + uv.s1, uw.s2 + uv.s2, uw.t1 + uv.t1, uw.t2 + uv.t2};
    return f;
}

}  // namespace

ManufacturedMotion::State ManufacturedMotion::state(double s, double t) const {
    const Fields f = fields(*this, s, t);
    const Mat3 A = so3::exp_map(f.alpha.v * kE1);
    const Vec3 Ae3 = A * kE3;
    State out;
    out.u = f.u.v;
    out.u_dot = f.u.t1;
    out.u_ddot = f.u.t2;
    out.R = A * so3::exp_map(f.beta.v * kE3);
    // Ṙ Rᵀ = α̇ ẽ₁ + β̇ (Ae₃)~ (Ȧ = α̇ ẽ₁ A, Ḃ = β̇ ẽ₃ B).
    out.omega = f.alpha.t1 * kE1 + f.beta.t1 * Ae3;
    out.omega_dot = f.alpha.t2 * kE1 + f.beta.t2 * Ae3 + f.beta.t1 * f.alpha.t1 * kE1.cross(Ae3);
    return out;
}

Vec3 ManufacturedMotion::rotation_vector(double s, double t) const {
    const Fields f = fields(*this, s, t);
    const Vec3 psi0 = so3::log_map(state(s, t).R);
    const double angle = psi0.norm();
    if (angle < 1e-12) return psi0;
    const Vec3 n = psi0 / angle;
    const Vec3 guide = f.alpha.v * kE1 + f.beta.v * kE3;
    Vec3 best = psi0;
    for (int k = -3; k <= 3; ++k) {
        const Vec3 c = psi0 + 2.0 * kPi * k * n;
        if ((c - guide).norm() < (best - guide).norm()) best = c;
    }
    return best;
}

Vec6 ManufacturedMotion::strains(double s, double t) const {
    const Fields f = fields(*this, s, t);
    const Mat3 A = so3::exp_map(f.alpha.v * kE1);
    const Mat3 R = A * so3::exp_map(f.beta.v * kE3);
    const Vec3 k = f.alpha.s1 * kE1 + f.beta.s1 * (A * kE3);
    Vec6 strain;
    strain << R.transpose() * (kE1 + f.u.s1) - kE1, R.transpose() * k;
    return strain;
}

void ManufacturedMotion::loads(double s, double t, Vec3& force, Vec3& moment) const {
    const Fields f = fields(*this, s, t);
    const State st = state(s, t);
    const Mat3& R = st.R;
    const Mat3 Rt = R.transpose();
    const Vec3 Ae3 = so3::exp_map(f.alpha.v * kE1) * kE3;
    // Elastic part (as the static oracle, manufactured.cpp): k, k′ and, with x″ = u″, the
    // resultants and their derivatives (manufactured_rod.hpp).
    const Vec3 k = f.alpha.s1 * kE1 + f.beta.s1 * Ae3;
    const Vec3 k1 = f.alpha.s2 * kE1 + f.beta.s2 * Ae3 + f.beta.s1 * f.alpha.s1 * kE1.cross(Ae3);
    const Vec3 x1 = kE1 + f.u.s1;
    const SpatialResultants r = spatial_resultants(R, k, k1, x1, f.u.s2, stiffness);
    // Inertial part: [P; H] = M*[V; Ω], V = Rᵀu̇, Ω = Rᵀω; V̇ = Rᵀü − Ω × V, Ω̇ = Rᵀω̇ (the
    // Ω × Ω term vanishes); ṗ = ω × p + R Ṗ, ḣ = ω × h + R Ḣ.
    const Vec3 V = Rt * st.u_dot, W = Rt * st.omega;
    Vec6 vel, acc;
    vel << V, W;
    acc << Rt * st.u_ddot - W.cross(V), Rt * st.omega_dot;
    const Vec6 PH = mass * vel;
    const Vec6 PH1 = mass * acc;
    const Vec3 p = R * PH.head<3>();
    const Vec3 h = R * PH.tail<3>();
    const Vec3 p1 = st.omega.cross(p) + R * PH1.head<3>();
    const Vec3 h1 = st.omega.cross(h) + R * PH1.tail<3>();
    force = p1 - r.n1;
    moment = h1 + st.u_dot.cross(p) - r.m1 - x1.cross(r.n);
}

double ManufacturedMotion::max_angle(double t) const {
    double angle = 0.0;
    for (int i = 0; i <= 200; ++i) {
        angle = std::max(angle, rotation_vector(length * i / 200.0, t).norm());
    }
    return angle;
}

Mat6 manufactured_mass() {
    // m = 1, η* = (0.02, 0.05, −0.04), ρ* = m(|η*|² I − η*η*ᵀ) plus a full SPD part (the
    // section's own rotary inertia about the centre of mass), so M* is SPD (its Schur complement
    // ρ* − m η̃*η̃*ᵀ is the full SPD part).
    const double m = 1.0;
    const Vec3 eta(0.02, 0.05, -0.04);
    Mat3 rho_c;
    rho_c << 0.02, 0.002, -0.001, 0.002, 0.01, 0.0015, -0.001, 0.0015, 0.012;
    const Mat3 e = so3::skew(eta);
    Mat6 M;
    M << m * Mat3::Identity(), m * e.transpose(), m * e, rho_c + m * e * e.transpose();
    return M;
}

Model manufactured_motion_model(const ManufacturedMotion& motion, int elements_per_member,
                                double dt, double end_time) {
    Model model;
    model.name = "manufactured-motion";
    model.description =
        "Manufactured motion: rotation past 2π about an axis varying in space and time";
    const double L = motion.length;
    Section section;
    section.name = "manufactured";
    section.stiffness = motion.stiffness;
    section.compliance = motion.stiffness.inverse();
    section.mass = motion.mass;
    add_four_member_rod(model, motion.length, section, elements_per_member, [motion](double s0) {
        LoadField field;
        field.density_in_time = [motion, s0](double s, double t, Vec3& f, Vec3& m) {
            motion.loads(s0 + s, t, f, m);
        };
        return field;
    });
    // No constraint: the rod flies free (its ends carry no load, the fields vanish there).
    model.analysis.kind = AnalysisKind::dynamic;
    model.analysis.dynamics.time_step = dt;
    model.analysis.dynamics.end_time = end_time;
    // The loads are of order 10 (the stiffness over L², the inertia of λ̈ a): a fixed scale
    // keeps the Newton tolerances the same for every Δt and mesh.
    model.solver.force_scale = 10.0;
    model.solver.length_scale = L;
    return model;
}

}  // namespace rotbeam::oracle
