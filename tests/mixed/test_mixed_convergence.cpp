// Accuracy of the mixed statics under mesh refinement: the roll-up against its exact solution
// (docs/benchmarks.md §1, observed order 2), the 45° bend (§2) converging to one answer, and the
// largest load λ*(N) the N-element equations can carry (§1: ≈ λc (1 − 1.1/N)).
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <iomanip>
#include <vector>

#include "core/static_driver.hpp"
#include "formulations/mixed/mixed_statics.hpp"
#include "parameterizations/rodrigues.hpp"
#include "parameterizations/wiener_milenkovic.hpp"
#include "tests/core/tight_newton.hpp"
#include "tests/mixed/models.hpp"

using namespace rotbeam;

namespace {

NewtonSettings tight_60_iterations() { return test::tight_newton(60); }

template <class P>
double rollup_error(int elements, double lambda) {
    form::MixedStatics<P> problem(test::rollup_model(elements));
    const StaticOutcome out = run_static(problem, {lambda}, tight_60_iterations(), nullptr);
    BOOST_TEST_REQUIRE((out.status == SolveStatus::converged));
    const Vec3 u = problem.point_state(1).displacement;
    return (u - test::rollup_exact_tip(lambda)).norm() / test::kRollupLength;
}

template <class P>
void check_rollup_order(double lambda) {
    std::vector<double> errors;
    for (int n = 16; n <= 1024; n *= 2) {
        errors.push_back(rollup_error<P>(n, lambda));
        const double order =
            errors.size() < 2 ? 0.0 : std::log2(errors[errors.size() - 2] / errors.back());
        BOOST_TEST_MESSAGE(P::kName << " λ = " << lambda << ", N = " << std::setw(4) << n
                                    << ": ‖Δu‖/L = " << std::scientific << std::setprecision(4)
                                    << errors.back() << std::defaultfloat << ", order " << order);
        // Second order from the first refinement on: Eqs. 47–48 are a midpoint rule of the
        // kinematic ODEs (local error O(ΔL³), global O(ΔL²)). The bounds leave ±0.05 for the
        // pre-asymptotic 16 → 32 step; round-off (≈ 1e-13 at N = 1024) is far below 7e-7.
        if (errors.size() >= 2) {
            BOOST_TEST(order > 1.95);
            BOOST_TEST(order < 2.05);
        }
    }
    BOOST_TEST(errors.back() < errors.front() / 3000.0);  // 64× finer mesh: 2⁻¹² ≈ 1/4096
}

// 45° bend: tip displacement at P = 300, 450, 600 (load steps of 50, as loads are applied in
// steps).
template <class P>
std::vector<Vec3> bend_tips(int elements, double shear_factor = 5.0 / 6.0, double J = 0.140577) {
    form::MixedStatics<P> problem(test::bend_model(elements, shear_factor, J));
    std::vector<double> loads;
    for (int k = 1; k <= 12; ++k) loads.push_back(50.0 * k);
    std::vector<Vec3> tips;
    const StaticOutcome out =
        run_static(problem, loads, tight_60_iterations(), [&](const StepRecord& step) {
            if (step.load_factor == 300.0 || step.load_factor == 450.0 ||
                step.load_factor == 600.0) {
                tips.push_back(problem.point_state(1).displacement);
            }
        });
    BOOST_TEST_REQUIRE((out.status == SolveStatus::converged));
    return tips;
}

// Largest load factor the N-element roll-up carries: continuation in steps δ from the last
// converged state; a failed Newton restores that state and halves δ, until δ < 1e-5 λc. (A plain
// bisection on [lo, hi] would take a failure far from the limit, where the basin of Newton's
// method shrinks, for the absence of a solution.)
template <class P>
double lambda_star(int elements, double lambda_c) {
    form::MixedStatics<P> problem(test::rollup_model(elements));
    NewtonSettings s = tight_60_iterations();
    s.residual_tolerance = 1e-10;
    s.increment_tolerance = 1e-10;
    s.max_iterations = 100;
    double lambda = 0.0;
    double step = 0.05 * lambda_c;
    problem.save_state(NonlinearSystem::kStepSlot);
    while (step > 1e-5 * lambda_c) {
        problem.set_load_factor(lambda + step);
        if (solve_newton(problem, s).converged) {
            lambda += step;
            problem.save_state(NonlinearSystem::kStepSlot);
        } else {
            step *= 0.5;
            problem.restore_state(NonlinearSystem::kStepSlot);
        }
    }
    return lambda;
}

// Independent reduction (no code shared with the formulation): with F = 0 and the moment about a
// fixed axis, Eqs. 48 reduce to the scalar recursion c_i = ĉ_i + a g(c_i), ĉ_{i+1} = c_i + a g(c_i)
// with a = h κ = λπ/(2N) and g = dc/dφ = 1 + k c² (Rodrigues k = 1/4, WM k = 1/16). The first
// step has a real root only while 1 − 4 k a (ĉ_i + a) ≥ 0: bisection on λ for the largest λ
// where every element's discriminant is non-negative.
bool reduction_solvable(double lambda, int n, double k) {
    const double a = lambda * kPi / (2.0 * n);
    double c_hat = 0.0;
    for (int i = 0; i < n; ++i) {
        const double disc = 1.0 - 4.0 * k * a * (c_hat + a);
        if (disc < 0.0) return false;
        const double c = (1.0 - std::sqrt(disc)) / (2.0 * k * a);  // the root continuous from 0
        c_hat = c + a * (1.0 + k * c * c);
    }
    return true;
}

double reduction_lambda_star(int n, double k, double lambda_c) {
    double lo = 0.0, hi = 1.5 * lambda_c;
    for (int it = 0; it < 60; ++it) {
        const double mid = 0.5 * (lo + hi);
        (reduction_solvable(mid, n, k) ? lo : hi) = mid;
    }
    return lo;
}

template <class P>
void check_lambda_star(double lambda_c, double lambda_16, double k) {
    for (int n = 16; n <= 64; n *= 2) {
        const double measured = lambda_star<P>(n, lambda_c);
        const double reduced = reduction_lambda_star(n, k, lambda_c);
        const double model = lambda_c * (1.0 - 1.1 / n);
        BOOST_TEST_MESSAGE(P::kName << ": λ*(" << n << ") = " << std::setprecision(7) << measured
                                    << ", reduction " << reduced << ", λc(1 − 1.1/N) = " << model);
        // Continuation resolves the fold to its last step δ = 1e-5 λc; near the fold Newton's
        // basin shrinks, so the last accepted load may sit a few steps short: 1e-4 λc.
        BOOST_TEST(measured <= reduced + 1e-9);
        BOOST_TEST(reduced - measured < 1e-4 * lambda_c);
        // The 1.1/N law is a fit (docs/benchmarks.md §1): the coefficient N(1 − λ*/λc) is 1.01 at
        // N = 16, 1.07 at 32, 1.10 at 64; λ*(16) is the value docs/benchmarks.md quotes.
        BOOST_TEST(std::abs(n * (1.0 - measured / lambda_c) - 1.1) < 0.1);
        if (n == 16) BOOST_TEST(std::abs(measured - lambda_16) < 0.5e-3);
    }
}

}  // namespace

BOOST_AUTO_TEST_SUITE(mixed_convergence)

BOOST_AUTO_TEST_CASE(wiener_milenkovic_rollup_converges_at_second_order) {
    check_rollup_order<param::WienerMilenkovic>(1.6);
}

BOOST_AUTO_TEST_CASE(rodrigues_rollup_converges_at_second_order) {
    check_rollup_order<param::Rodrigues>(0.8);
}

BOOST_AUTO_TEST_CASE(bend_45_degree_tip_converges_under_refinement) {
    std::vector<std::vector<Vec3>> tips;
    for (int n = 16; n <= 256; n *= 2) {
        tips.push_back(bend_tips<param::WienerMilenkovic>(n));
        const Vec3& u = tips.back()[2];
        BOOST_TEST_MESSAGE("bend N = " << n << ": tip at P = 600: " << std::setprecision(9)
                                       << u.transpose()
                                       << "; P = 300: " << tips.back()[0].transpose()
                                       << "; P = 450: " << tips.back()[1].transpose());
    }
    // Differences between successive meshes fall by ≈ 4 (second order). The published tip
    // (−23.5, −13.4, 53.4) is rounded to 0.1 and computed with section constants the paper does
    // not state; docs/benchmarks.md §2: the choice moves the in-plane components by about 1 %. With
    // GXBeam's constants (shear factor 1, J = 1/6) the converged tip is printed for comparison;
    // the gate is 2.5 % of |u| per component (u_y: 0.33 of 13.4 with this case's constants).
    for (std::size_t k = 2; k < tips.size(); ++k) {
        const double ratio =
            (tips[k - 2][2] - tips[k - 1][2]).norm() / (tips[k - 1][2] - tips[k][2]).norm();
        BOOST_TEST(ratio > 3.6);
        BOOST_TEST(ratio < 4.4);
    }
    const std::vector<Vec3> gx = bend_tips<param::WienerMilenkovic>(256, 1.0, 1.0 / 6.0);
    BOOST_TEST_MESSAGE("bend N = 256, GXBeam constants (k = 1, J = 1/6): " << gx[2].transpose());
    const Vec3 published(-23.5, -13.4, 53.4);
    for (int k = 0; k < 3; ++k) {
        BOOST_TEST(std::abs(tips.back()[2][k] - published[k]) < 0.025 * std::abs(published[k]));
        BOOST_TEST(std::abs(gx[2][k] - published[k]) < 0.025 * std::abs(published[k]));
    }
}

BOOST_AUTO_TEST_CASE(rodrigues_limit_load_follows_one_minus_1p1_over_n) {
    check_lambda_star<param::Rodrigues>(1.0, 0.937, 0.25);
}

BOOST_AUTO_TEST_CASE(wiener_milenkovic_limit_load_follows_one_minus_1p1_over_n) {
    check_lambda_star<param::WienerMilenkovic>(2.0, 1.874, 1.0 / 16.0);
}

BOOST_AUTO_TEST_SUITE_END()
