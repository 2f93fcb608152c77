// Mixed statics' reach on the roll-up of docs/benchmarks.md §1 to λ = 4 (tip rotation 4π) at 256
// elements, for every parameterization and option: the rotation vector (dexp⁻¹ in place
// of Q⁻¹ in Eq. 48) with its second-order convergence, plain and continuous WM, Rodrigues and the
// quaternion (four-component Eq. 48); where and why a continuation stops.
#include <algorithm>
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <iomanip>
#include <vector>

#include "core/so3.hpp"
#include "core/static_driver.hpp"
#include "formulations/mixed/mixed_statics_of.hpp"
#include "parameterizations/quaternion.hpp"
#include "parameterizations/rodrigues.hpp"
#include "parameterizations/rotation_vector.hpp"
#include "parameterizations/wiener_milenkovic.hpp"
#include "parameterizations/wiener_milenkovic_continuous.hpp"
#include "tests/core/tight_newton.hpp"
#include "tests/mixed/models.hpp"

using namespace rotbeam;

namespace {

NewtonSettings reach_settings() { return test::tight_newton(60, 8); }

double tip_error(const StaticProblem& problem, double lambda) {
    const Vec3 u = problem.point_state(1).displacement;
    return (u - test::rollup_exact_tip(lambda)).norm() / test::kRollupLength;
}

struct Reach {
    StaticOutcome outcome;
    double worst_error = 0.0;           // largest ‖Δu_tip‖/L over the converged load steps
    double worst_rotation_error = 0.0;  // largest ‖R_tip − exp(−λπ ẽ2)‖ (Frobenius)
};

// Load steps of 0.1 from 0.1 to `lambda_end`; the driver cuts a failing step up to 8 times.
template <class P>
Reach rollup_reach(int elements, double lambda_end) {
    form::MixedStaticsOf<P> problem(test::rollup_model(elements));
    std::vector<double> loads;
    for (int k = 1; k <= static_cast<int>(std::lround(10.0 * lambda_end)); ++k) {
        loads.push_back(0.1 * k);
    }
    Reach r;
    r.outcome = run_static(problem, loads, reach_settings(), [&](const StepRecord& step) {
        r.worst_error = std::max(r.worst_error, tip_error(problem, step.load_factor));
        const Mat3 exact = so3::exp_map(Vec3(0.0, -kPi * step.load_factor, 0.0));
        r.worst_rotation_error =
            std::max(r.worst_rotation_error, (problem.point_state(1).rotation - exact).norm());
    });
    BOOST_TEST_MESSAGE(P::kName << ", N = " << elements << ": " << r.outcome.status
                                << ", last λ = " << r.outcome.last_converged_load_factor
                                << ", worst ‖Δu‖/L = " << r.worst_error << ", worst ‖ΔR‖ = "
                                << r.worst_rotation_error << "; " << r.outcome.message);
    return r;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(mixed_rotation_vector_reach)

BOOST_AUTO_TEST_CASE(rotation_vector_rollup_converges_with_order_two) {
    // λ = 1.6: the tip turns 1.6π, below the tangent's singular angle 2π.
    std::vector<double> errors;
    for (int n = 16; n <= 512; n *= 2) {
        form::MixedStatics<param::RotationVector> problem(test::rollup_model(n));
        const StaticOutcome out = run_static(problem, {1.6}, reach_settings(), nullptr);
        BOOST_TEST_REQUIRE((out.status == SolveStatus::converged));
        errors.push_back(tip_error(problem, 1.6));
        const double order =
            errors.size() < 2 ? 0.0 : std::log2(errors[errors.size() - 2] / errors.back());
        BOOST_TEST_MESSAGE("rotation-vector λ = 1.6, N = "
                           << std::setw(4) << n << ": ‖Δu‖/L = " << std::scientific
                           << std::setprecision(4) << errors.back() << std::defaultfloat
                           << ", order " << order);
        // Eq. 47 is a midpoint rule of u′ = R e − e1 (global error O(ΔL²)); Eq. 48 is exact here
        // (dexp⁻¹ κ = κ for κ along ψ). ±0.05 covers the pre-asymptotic first refinement.
        if (errors.size() >= 2) {
            BOOST_TEST(order > 1.95);
            BOOST_TEST(order < 2.05);
        }
    }
}

// In the plane of the roll-up ψ and κ stay parallel, where dexp⁻¹ κ = κ (Eq. V4: ψ̃ κ = 0), so
// Eq. 48 stays regular through φ = 2π: only the transverse blocks of ∂(dexp⁻¹ w)/∂ψ grow like
// cot(φ/2), and they decouple. The element mid-rotations λπ(i + ½)/N with λ = 0.1k never land
// within the guard of 2π (k(2i + 1) = 10240 has no solution with 2i + 1 odd > 1 and k ≤ 40), so
// every step converges and the continuation passes 2π and reaches 4π.
BOOST_AUTO_TEST_CASE(rotation_vector_rollup_reaches_lambda_four_within_1e_4) {
    const Reach r = rollup_reach<param::RotationVector>(256, 4.0);
    BOOST_TEST_REQUIRE((r.outcome.status == SolveStatus::converged));
    BOOST_TEST(r.outcome.last_converged_load_factor == 4.0, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(r.outcome.steps.size() == 40u);
    // 256 elements: the midpoint-rule error ≈ 3.8e-6 at λ = 1.6 grows ∝ λ² at most.
    BOOST_TEST(r.worst_error <= 1e-4);
    BOOST_TEST(r.worst_error > 1e-7);  // the measurement is not vacuous (an O(ΔL²) error remains)
}

// Plain WM stops at its fold below λ = 2 (docs: λ*(256) ≈ 1.990); with GXBeam's continuous map
// the unknowns pass |θ| = 4 (φ = π) and 8 (φ = 2π) and the continuation is measured to λ = 4.
BOOST_AUTO_TEST_CASE(plain_wm_stops_before_lambda_two_and_continuous_wm_reaches_lambda_four) {
    const Reach plain = rollup_reach<param::WienerMilenkovic>(256, 4.0);
    BOOST_TEST((plain.outcome.status == SolveStatus::diverged ||
                plain.outcome.status == SolveStatus::singular));
    BOOST_TEST(plain.outcome.last_converged_load_factor < 2.0);
    BOOST_TEST(plain.worst_error <= 1e-4);
    const Reach continuous = rollup_reach<param::WienerMilenkovicContinuous>(256, 4.0);
    BOOST_TEST_REQUIRE((continuous.outcome.status == SolveStatus::converged));
    BOOST_TEST(continuous.outcome.steps.size() == 40u);
    BOOST_TEST(continuous.worst_error <= 1e-4);
}

// Rodrigues has no chart past φ = π: the roll-up's fold λ*(256) ≈ 0.995 (docs) stops it before
// λ = 1 with a truthful status, every converged step within 1e-4 of the exact arc.
BOOST_AUTO_TEST_CASE(rodrigues_stops_before_lambda_one) {
    const Reach r = rollup_reach<param::Rodrigues>(256, 4.0);
    BOOST_TEST(
        (r.outcome.status == SolveStatus::diverged || r.outcome.status == SolveStatus::singular));
    BOOST_TEST(r.outcome.last_converged_load_factor < 1.0);
    BOOST_TEST(r.outcome.last_converged_load_factor > 0.9);
    BOOST_TEST(r.worst_error <= 1e-4);
}

// The quaternion at λ = 1.6 (below plain WM's fold, so the errors compare): Eq. 47's midpoint rule
// and the Cayley angle of Eq. 48 (δ − δ³/48 per element) both err by O(ΔL²) globally.
BOOST_AUTO_TEST_CASE(quaternion_rollup_converges_with_order_two) {
    std::vector<double> errors;
    for (int n = 16; n <= 512; n *= 2) {
        form::MixedStaticsOf<param::Quaternion> problem(test::rollup_model(n));
        const StaticOutcome out = run_static(problem, {1.6}, reach_settings(), nullptr);
        BOOST_TEST_REQUIRE((out.status == SolveStatus::converged));
        errors.push_back(tip_error(problem, 1.6));
        const double order =
            errors.size() < 2 ? 0.0 : std::log2(errors[errors.size() - 2] / errors.back());
        BOOST_TEST_MESSAGE("quaternion λ = 1.6, N = " << std::setw(4) << n << ": ‖Δu‖/L = "
                                                      << std::scientific << std::setprecision(4)
                                                      << errors.back() << std::defaultfloat
                                                      << ", order " << order << ", iterations "
                                                      << out.steps.back().newton_iterations);
        if (errors.size() >= 2) {  // ±0.05 covers the pre-asymptotic first refinement
            BOOST_TEST(order > 1.95);
            BOOST_TEST(order < 2.05);
        }
    }
}

// The quaternion (four-component Eq. 48, a Cayley transform from node to node) has neither a
// singular angle nor a fold: it passes λ = 2 (tip rotation 2π, where plain WM stops) and reaches
// λ = 4. The error is the midpoint rule's O(ΔL²) (≈ 3.3e-3 at N = 16, λ = 1.6, like WM's), ≈ 1e-5
// at 256 elements, growing with λ.
BOOST_AUTO_TEST_CASE(quaternion_rollup_reaches_lambda_four_within_1e_4) {
    const Reach r = rollup_reach<param::Quaternion>(256, 4.0);
    BOOST_TEST_REQUIRE((r.outcome.status == SolveStatus::converged));
    BOOST_TEST(r.outcome.last_converged_load_factor == 4.0, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(r.outcome.steps.size() == 40u);
    BOOST_TEST(r.worst_error <= 1e-4);
    BOOST_TEST(r.worst_error > 1e-7);  // an O(ΔL²) error remains: the measurement is not vacuous
    // The tip rotation: with M constant, κ = M/EI is exact and each element turns its end node by
    // the Cayley angle 4 atan(δ/4) = δ − δ³/48 + O(δ⁵), δ = λπ/N, so the tip lags the exact arc's
    // exp(−λπ ẽ2) by (λπ)³/(48N²) (largest at λ = 4) and ‖ΔR‖_F = √2 · that. Matching it to 1 %
    // (the next term is O(δ²) ≈ 2e-3 relative) checks that Eq. 48 is exactly this transform.
    const double lag = std::pow(4.0 * kPi, 3) / (48.0 * 256.0 * 256.0);
    BOOST_TEST(r.worst_rotation_error / (std::sqrt(2.0) * lag) == 1.0,
               boost::test_tools::tolerance(0.01));
}

BOOST_AUTO_TEST_SUITE_END()
