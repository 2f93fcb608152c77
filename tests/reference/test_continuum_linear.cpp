// The continuum solver's own ingredients: the reference geometry it builds from the model, and
// its small-load limit against linear beam theory for shear-flexible and fully coupled sections.
#include <boost/test/unit_test.hpp>
#include <cmath>

#include "continuum_models.hpp"
#include "core/continuum/continuum.hpp"
#include "core/continuum/rod_geometry.hpp"
#include "core/oracles/timoshenko.hpp"
#include "core/so3.hpp"

using namespace rotbeam;

namespace {

// Linear Cosserat cantilever (straight along x, clamped at 0, tip force F and moment M): n = F,
// m(s) = M + (L − s) e1 × F, [γ; κ] = C [n; m], θ(s) = ∫₀ˢ κ, u(L) = ∫₀ᴸ (γ + θ × e1) ds.
// κ is linear in s, so θ is quadratic and Simpson's rule on [0, L] is exact for u(L).
Vec3 linear_tip_displacement(const Mat6& C, double L, const Vec3& F, const Vec3& M) {
    const auto strain = [&](double s) -> Vec6 {
        Vec6 resultant;
        resultant << F, M + (L - s) * Vec3::UnitX().cross(F);
        return C * resultant;
    };
    // θ(s) for linear κ: θ(s) = s (κ(0) + κ(s))/2 (trapezoid exact for a linear integrand).
    const auto theta = [&](double s) -> Vec3 {
        return 0.5 * s * (strain(0.0).tail<3>() + strain(s).tail<3>());
    };
    const auto integrand = [&](double s) -> Vec3 {
        return strain(s).head<3>() + theta(s).cross(Vec3::UnitX());
    };
    return L / 6.0 * (integrand(0.0) + 4.0 * integrand(L / 2.0) + integrand(L));
}

}  // namespace

BOOST_AUTO_TEST_SUITE(continuum_ingredients)

BOOST_AUTO_TEST_CASE(arc_geometry_with_twist_satisfies_its_frame_equations) {
    // x_r' = R^r e1 and R^r' = R^r (k^r)~ by central differences (h = 1e-5 L: truncation
    // h²|k|³ ~ 1e-12, round-off 1e-16/h ~ 1e-11 relative), on the 45° arc with 1.3 rad twist.
    Model model =
        test::cantilever(Vec3(100 * std::sin(kPi / 4), 100 * (1 - std::cos(kPi / 4)), 0),
                         Mat6::Identity(), Vec3::Zero(), Vec3::Zero(), LoadFrame::dead, {1.0});
    model.members[0].line.kind = LineKind::arc;
    model.members[0].line.center = Vec3(0, 100, 0);
    model.members[0].twist_start = 0.4;
    model.members[0].twist_end = 1.7;
    const continuum::RodGeometry g(model, model.members[0]);
    BOOST_TEST(std::abs(g.length() - 100 * kPi / 4) < 1e-12);
    const double h = 1e-5 * g.length();
    for (double s : {0.0 + h, 0.3 * g.length(), g.length() - h}) {
        const Vec3 dx = (g.position(s + h) - g.position(s - h)) / (2 * h);
        BOOST_TEST((dx - g.frame(s).col(0)).norm() < 1e-9);
        const Mat3 dR = (g.frame(s + h) - g.frame(s - h)) / (2 * h);
        BOOST_TEST((dR - g.frame(s) * so3::skew(g.curvature(s))).norm() < 1e-9);
    }
    BOOST_TEST((g.frame(0.0).col(0) - Vec3::UnitX()).norm() < 1e-15);
    BOOST_TEST(g.locate(model.points[1].position).value() == g.length());
    BOOST_TEST(!g.locate(Vec3(50, 50, 0)).has_value());
}

BOOST_AUTO_TEST_CASE(small_tip_force_gives_the_timoshenko_deflection) {
    // docs/benchmarks.md §7 section, L/h = 5 (shear matters: ~8 % of δ). At PL²/EI = 1e-7 the
    // geometric nonlinearity changes δ by O((PL²/EI)²) = 1e-14 relative.
    const double E = 2.1e11, G = E / 2.6, h = 0.2, L = 1.0, A = h * h, I = h * h * h * h / 12;
    const double kGA = 5.0 / 6.0 * G * A;
    const Mat6 C = test::diagonal_compliance(
        (Vec6() << E * A, kGA, kGA, G * 0.1406 * h * h * h * h, E * I, E * I).finished());
    const double P = 1e-7 * E * I / (L * L);
    const Model model =
        test::cantilever(Vec3(L, 0, 0), C, Vec3(0, 0, P), Vec3::Zero(), LoadFrame::dead, {1.0});
    const ContinuumOutcome outcome = solve_continuum(model);
    BOOST_TEST_REQUIRE(outcome.status == "converged", outcome.message);
    const double delta = oracle::timoshenko_tip_deflection({L, E * I, kGA, 1.0, 0.0}, P);
    BOOST_TEST(std::abs(outcome.steps[0].points[1].displacement.z() / delta - 1.0) < 1e-9);
}

BOOST_AUTO_TEST_CASE(small_loads_on_the_fully_coupled_mh104_section_match_linear_theory) {
    // MH-104 blade stiffness of docs/benchmarks.md §4 (all 36 entries non-zero), L = 60 m, loads
    // with PL²/EI ~ 5e-7: the deviation from the linear Cosserat solution is the geometric
    // nonlinearity, first order in the load — it halves when the loads are halved — and is
    // below 1e-6 relative.
    Mat6 K;
    K << 2.389e9, 1.524e6, 6.734e6, -3.382e7, -2.627e7, -4.736e8, 1.524e6, 4.334e8, -3.741e6,
        -2.935e5, 1.527e7, 3.835e5, 6.734e6, -3.741e6, 2.743e7, -4.592e5, -6.869e5, -4.742e6,
        -3.382e7, -2.935e5, -4.592e5, 2.167e7, -6.279e5, 1.430e6, -2.627e7, 1.527e7, -6.869e5,
        -6.279e5, 1.970e7, 1.209e7, -4.736e8, 3.835e5, -4.742e6, 1.430e6, 1.209e7, 4.406e8;
    const Mat6 C = K.inverse();
    const double L = 60.0;
    const Vec3 F(3.0e-3, -1.0e-3, 2.0e-3), M(1.0e-2, -2.0e-2, 1.5e-2);
    double deviation[2];
    for (int i = 0; i < 2; ++i) {
        const double scale = i == 0 ? 1.0 : 0.5;
        const Model model =
            test::cantilever(Vec3(L, 0, 0), C, scale * F, scale * M, LoadFrame::dead, {1.0});
        const ContinuumOutcome outcome = solve_continuum(model);
        BOOST_TEST_REQUIRE(outcome.status == "converged", outcome.message);
        const Vec3 linear = linear_tip_displacement(C, L, scale * F, scale * M);
        const Vec3 u = outcome.steps[0].points[1].displacement;
        deviation[i] = (u - linear).norm() / linear.norm();
        BOOST_TEST_MESSAGE("MH-104 load × " << scale << ": |u| = " << u.norm()
                                            << ", relative deviation from linear theory "
                                            << deviation[i]);
        BOOST_TEST(deviation[i] < 1e-6);
    }
    BOOST_TEST(std::abs(deviation[1] / deviation[0] - 0.5) < 0.05);
}

BOOST_AUTO_TEST_CASE(follower_tip_loads_equal_the_dead_loads_they_turn_into) {
    // A follower tip load F₀, M₀ at equilibrium acts as the dead load R_tip F₀, R_tip M₀
    // (core/model.hpp). Re-solving with those dead loads must give the same state: this checks
    // the follower path independently of any closed form (precessing-helix section, 3D loads).
    const Mat6 C =
        test::diagonal_compliance((Vec6() << 1e4, 1e4, 1e4, 50.0, 100.0, 200.0).finished());
    const Vec3 F0(0.0, 1.5, 2.0), M0(3.0, -4.0, 5.0);
    const Model follower =
        test::cantilever(Vec3(10, 0, 0), C, F0, M0, LoadFrame::follower, {0.5, 1.0});
    const ContinuumOutcome a = solve_continuum(follower);
    BOOST_TEST_REQUIRE(a.status == "converged", a.message);
    const PointState& tip = a.steps.back().points[1];
    BOOST_TEST(so3::rotation_angle(tip.rotation) > 1.0);  // a genuinely large rotation
    const Model dead = test::cantilever(Vec3(10, 0, 0), C, tip.rotation * F0, tip.rotation * M0,
                                        LoadFrame::dead, {0.5, 1.0});
    const ContinuumOutcome b = solve_continuum(dead);
    BOOST_TEST_REQUIRE(b.status == "converged", b.message);
    const PointState& tip_dead = b.steps.back().points[1];
    BOOST_TEST((tip.displacement - tip_dead.displacement).norm() < 1e-9 * 10.0);
    BOOST_TEST((tip.rotation - tip_dead.rotation).norm() < 1e-9);
}

BOOST_AUTO_TEST_CASE(small_uniform_distributed_load_gives_the_timoshenko_deflection) {
    // δ = qL⁴/(8EI) + qL²/(2κGA) for a uniform dead load q; at qL³/EI = 1e-7 the geometric
    // nonlinearity is O(1e-14) relative.
    const double L = 2.0, EI = 3.0, kGA = 40.0;
    const Mat6 C = test::diagonal_compliance((Vec6() << 1e3, kGA, kGA, 2.0, EI, EI).finished());
    Model model =
        test::cantilever(Vec3(L, 0, 0), C, Vec3::Zero(), Vec3::Zero(), LoadFrame::dead, {1.0});
    const double q = 1e-7 * EI / (L * L * L);
    DistributedLoad load;
    load.member = 0;
    load.force = Vec3(0, 0, q);
    model.distributed_loads.push_back(load);
    const ContinuumOutcome outcome = solve_continuum(model);
    BOOST_TEST_REQUIRE(outcome.status == "converged", outcome.message);
    const double delta = q * L * L * L * L / (8 * EI) + q * L * L / (2 * kGA);
    BOOST_TEST(std::abs(outcome.steps[0].points[1].displacement.z() / delta - 1.0) < 1e-9);
}

BOOST_AUTO_TEST_SUITE_END()
