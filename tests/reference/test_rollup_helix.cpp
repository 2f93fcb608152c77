// The exact roll-up and helix oracles: published values, limits and the defining ODEs.
#include <boost/test/unit_test.hpp>
#include <cmath>

#include "core/oracles/helix.hpp"
#include "core/oracles/rollup.hpp"
#include "core/so3.hpp"

using namespace rotbeam;
using namespace rotbeam::oracle;

namespace {

// Central differences with h = 1e-5 L: the truncation error h²/6 |x'''| = h² κ²/6 is ≤ 2e-9 for
// the curvatures used (κ ≤ 1.1/length unit, L ≤ 12) and the round-off ~1e-16 L/h = 1e-11, so
// 1e-8 tests x' = R e₁ (and R'Rᵀ = κñ, relative to κ) tightly.
constexpr double kFdTolerance = 1e-8;

}  // namespace

BOOST_AUTO_TEST_SUITE(rollup)

BOOST_AUTO_TEST_CASE(tip_matches_table_I_analytical_column_of_seed_002) {
    // Seed 002 Table I, analytical column (L = 12 in), printed to 4 decimals.
    const double lambdas[] = {0.4, 0.8, 1.0, 1.2, 1.6, 2.0};
    const double u1[] = {-2.9181, -9.1935, -12.0000, -13.8710, -14.2705, -12.0};
    const double u3[] = {6.5984, 8.6374, 7.6394, 5.7583, 1.6496, 0.0};
    for (int i = 0; i < 6; ++i) {
        const RollupState tip = rollup_tip(12.0, lambdas[i]);
        BOOST_TEST(std::abs(tip.displacement.x() - u1[i]) < 5.1e-5);
        BOOST_TEST(std::abs(tip.displacement.z() - u3[i]) < 5.1e-5);
        BOOST_TEST(tip.displacement.y() == 0.0);
    }
}

BOOST_AUTO_TEST_CASE(zero_load_is_the_reference_and_full_turns_close_the_circle) {
    const RollupState zero = rollup_tip(10.0, 0.0);
    BOOST_TEST(zero.displacement.norm() == 0.0);
    BOOST_TEST((zero.rotation - Mat3::Identity()).norm() == 0.0);
    for (double lambda : {2.0, 4.0}) {
        const RollupState tip = rollup_tip(10.0, lambda);
        BOOST_TEST((tip.displacement - Vec3(-10.0, 0.0, 0.0)).norm() < 1e-13);
        BOOST_TEST((tip.rotation - Mat3::Identity()).norm() < 1e-14);
        BOOST_TEST(std::abs(tip.angle - lambda * kPi) < 1e-14);
    }
}

BOOST_AUTO_TEST_CASE(small_load_series_branch_is_continuous_and_linear) {
    // Linear theory: u₃ = M L²/(2EI) = λπL/2, u₁ = O(λ²).
    const double L = 7.0, lambda = 1e-7;
    const RollupState tip = rollup_tip(L, lambda);
    BOOST_TEST(std::abs(tip.displacement.z() / (lambda * kPi * L / 2.0) - 1.0) < 1e-12);
    // Both sides of the series threshold (θ = 1e-2) agree to the series' truncation error.
    const double at = 1e-2 * L / kPi;
    const RollupState below = rollup_tip(L, at * (1.0 - 1e-12) / L);
    const RollupState above = rollup_tip(L, at * (1.0 + 1e-12) / L);
    BOOST_TEST((below.displacement - above.displacement).norm() < 1e-12 * L);
}

BOOST_AUTO_TEST_CASE(centreline_tangent_is_the_rotated_axis_at_lambda_2_7) {
    const double L = 12.0, lambda = 2.7, h = 1e-5 * L;
    for (double s : {0.1 * L, 0.45 * L, 0.9 * L}) {
        const Vec3 dx = (rollup_state(L, lambda, s + h).displacement -
                         rollup_state(L, lambda, s - h).displacement) /
                            (2.0 * h) +
                        Vec3::UnitX();
        const Vec3 t = rollup_state(L, lambda, s).rotation * Vec3::UnitX();
        BOOST_TEST((dx - t).norm() < kFdTolerance);
    }
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(helix)

BOOST_AUTO_TEST_CASE(centreline_tangent_and_spatial_curvature_solve_the_rod_equations) {
    // x' = R e₁ (no strain) and R' Rᵀ = κ ñ (constant spatial curvature), checked by central
    // differences at κL = 3.3π, a non-trivial state past two singular angles.
    const Vec3 n = Vec3(0.6, 0.0, 0.8);
    const double L = 10.0, kappa = 3.3 * kPi / L, h = 1e-5 * L;
    for (double s : {0.2 * L, 0.55 * L, 0.95 * L}) {
        const HelixState mid = helix_state(kappa, n, s);
        const HelixState plus = helix_state(kappa, n, s + h);
        const HelixState minus = helix_state(kappa, n, s - h);
        const Vec3 dx = (plus.displacement - minus.displacement) / (2.0 * h) + Vec3::UnitX();
        BOOST_TEST((dx - mid.rotation * Vec3::UnitX()).norm() < kFdTolerance);
        const Mat3 dR = (plus.rotation - minus.rotation) / (2.0 * h);
        const Mat3 k_spatial = dR * mid.rotation.transpose();
        BOOST_TEST((k_spatial - kappa * so3::skew(n)).norm() < kFdTolerance * kappa);
    }
}

BOOST_AUTO_TEST_CASE(full_turns_end_on_the_axis_projection) {
    // At κL = 2π m the tip lies at (n·e₁) L n: the helix closes one pitch per turn.
    const Vec3 n = Vec3(0.6, 0.0, 0.8);
    const double L = 10.0;
    for (int m : {1, 2}) {
        const HelixState tip = helix_state(2.0 * m * kPi / L, n, L);
        const Vec3 expected = 0.6 * L * n - L * Vec3::UnitX();
        BOOST_TEST((tip.displacement - expected).norm() < 1e-13 * L);
        BOOST_TEST((tip.rotation - Mat3::Identity()).norm() < 1e-14);
        BOOST_TEST(std::abs(tip.rotation_vector.norm() - 2.0 * m * kPi) < 1e-13);
    }
}

BOOST_AUTO_TEST_CASE(axis_normal_to_the_beam_reduces_to_the_rollup) {
    // n = −e_y is the roll-up with κ = λπ/L (docs/benchmarks.md §1 ⊂ §5).
    const double L = 12.0, lambda = 1.37;
    const HelixState h = helix_state(lambda * kPi / L, -Vec3::UnitY(), L);
    const RollupState r = rollup_tip(L, lambda);
    BOOST_TEST((h.displacement - r.displacement).norm() < 1e-13 * L);
    BOOST_TEST((h.rotation - r.rotation).norm() < 1e-14);
}

BOOST_AUTO_TEST_CASE(axis_along_the_beam_is_pure_twist) {
    const HelixState tip = helix_state(0.9, Vec3(2.0, 0.0, 0.0), 5.0);
    BOOST_TEST(tip.displacement.norm() < 1e-15);
    BOOST_TEST((tip.rotation - so3::exp_map(Vec3(4.5, 0.0, 0.0))).norm() < 1e-15);
    BOOST_TEST((helix_moment(0.9, 100.0, Vec3(2.0, 0.0, 0.0)) - Vec3(90.0, 0.0, 0.0)).norm() <
               1e-13);
}

BOOST_AUTO_TEST_SUITE_END()
