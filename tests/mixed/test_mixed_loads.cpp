// Physical checks of loads and connection points in the mixed statics: a uniformly loaded
// cantilever in the linear range against the Timoshenko deflection (Eqs. 51–54), a member split
// at a connection point equal to the unsplit member, and a follower tip moment equal to a dead one
// on the roll-up (the tip moment of a planar roll-up stays normal to the plane).
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <vector>

#include "core/so3.hpp"
#include "core/static_driver.hpp"
#include "formulations/mixed/mixed_statics.hpp"
#include "parameterizations/rodrigues.hpp"
#include "parameterizations/wiener_milenkovic.hpp"
#include "tests/core/tight_newton.hpp"
#include "tests/mixed/models.hpp"

using namespace rotbeam;

namespace {

NewtonSettings tight() { return test::tight_newton(); }

}  // namespace

BOOST_AUTO_TEST_SUITE(mixed_loads)

BOOST_AUTO_TEST_CASE(uniform_load_gives_timoshenko_tip_deflection_in_linear_range) {
    Model m = test::rollup_model(64);
    m.point_loads.clear();
    const double q = 1e-3;  // lbf/in: tip deflection ≈ 2e-6 L, deep in the linear range
    DistributedLoad load;
    load.member = 0;
    load.force = Vec3(0, 0, q);
    m.distributed_loads = {load};
    form::MixedStatics<param::WienerMilenkovic> problem(m);
    BOOST_TEST_REQUIRE(
        (run_static(problem, {1.0}, tight(), nullptr).status == SolveStatus::converged));
    const double L = test::kRollupLength, EI = test::kRollupEI;
    const double kGA = 5.0 / 6.0 * 30e6 / 2.6;
    const double exact = q * std::pow(L, 4) / (8 * EI) + q * L * L / (2 * kGA);
    const double w = problem.point_state(1).displacement[2];
    // Discretization error O((L/N)²) ≈ 2e-4 relative at 64 elements; geometric nonlinearity
    // O((w/L)²) ≈ 1e-11.
    BOOST_TEST(std::abs(w - exact) < 1e-3 * exact);
}

BOOST_AUTO_TEST_CASE(member_split_at_a_connection_point_equals_the_whole_member) {
    const Model whole = test::rollup_model(16);
    Model split = whole;
    split.points = {{"root", Vec3::Zero()}, {"tip", Vec3(12, 0, 0)}, {"joint", Vec3(4.5, 0, 0)}};
    split.members = {test::member("a", 0, 2, whole.members[0].sections[0].section, 6),
                     test::member("b", 2, 1, whole.members[0].sections[0].section, 10)};
    form::MixedStatics<param::WienerMilenkovic> one(whole);
    form::MixedStatics<param::WienerMilenkovic> two(split);
    BOOST_TEST_REQUIRE((run_static(one, {1.2}, tight(), nullptr).status == SolveStatus::converged));
    BOOST_TEST_REQUIRE((run_static(two, {1.2}, tight(), nullptr).status == SolveStatus::converged));
    // Same 16 equal elements, same equations: equal to the solver's tolerance.
    BOOST_TEST((one.point_state(1).displacement - two.point_state(1).displacement).norm() < 1e-9);
    BOOST_TEST(two.point_state(2).displacement.norm() > 1.0);  // the joint moved
}

BOOST_AUTO_TEST_CASE(follower_tip_moment_of_planar_rollup_equals_dead_moment) {
    Model follower = test::rollup_model(32);
    follower.point_loads[0].frame = LoadFrame::follower;
    form::MixedStatics<param::Rodrigues> dead_problem(test::rollup_model(32));
    form::MixedStatics<param::Rodrigues> follower_problem(follower);
    BOOST_TEST_REQUIRE(
        (run_static(dead_problem, {0.8}, tight(), nullptr).status == SolveStatus::converged));
    BOOST_TEST_REQUIRE(
        (run_static(follower_problem, {0.8}, tight(), nullptr).status == SolveStatus::converged));
    const Vec3 d =
        dead_problem.point_state(1).displacement - follower_problem.point_state(1).displacement;
    BOOST_TEST(d.norm() < 1e-9);
    BOOST_TEST(follower_problem.counters().follower_stiffness > 0);
    BOOST_TEST(dead_problem.counters().follower_stiffness == 0);
}

BOOST_AUTO_TEST_CASE(follower_tip_force_differs_from_dead_force_at_large_rotation) {
    // A transverse tip force that follows the tip bends the beam further round than a dead one
    // (the follower keeps its angle to the tip tangent); both converge and the two differ.
    Model dead = test::rollup_model(32);
    dead.point_loads[0].moment.setZero();
    dead.point_loads[0].force = Vec3(0, 0, 2.0 * test::kRollupEI / 144.0);
    Model follower = dead;
    follower.point_loads[0].frame = LoadFrame::follower;
    form::MixedStatics<param::WienerMilenkovic> a(dead), b(follower);
    BOOST_TEST_REQUIRE((run_static(a, {1.0}, tight(), nullptr).status == SolveStatus::converged));
    BOOST_TEST_REQUIRE((run_static(b, {1.0}, tight(), nullptr).status == SolveStatus::converged));
    BOOST_TEST(b.point_state(1).displacement[0] < a.point_state(1).displacement[0] - 0.5);
}

BOOST_AUTO_TEST_CASE(rigid_axial_and_shear_rows_give_euler_bernoulli_deflection) {
    // The mixed form never inverts the compliance: zero rows (inextensible, shear-rigid) are
    // admissible and give the Euler–Bernoulli tip deflection P L³ / (3 EI).
    Model m = test::rollup_model(64);
    Section& section = m.members[0].sections[0].section;
    section.compliance.topLeftCorner<3, 3>().setZero();
    section.stiffness.reset();
    m.point_loads[0].moment.setZero();
    const double P = 1e-2;  // deflection ≈ 2.8e-6 L: linear range
    m.point_loads[0].force = Vec3(0, 0, P);
    form::MixedStatics<param::WienerMilenkovic> problem(m);
    BOOST_TEST_REQUIRE(
        (run_static(problem, {1.0}, tight(), nullptr).status == SolveStatus::converged));
    const double L = test::kRollupLength;
    const double exact = P * L * L * L / (3.0 * test::kRollupEI);
    const Vec3 u = problem.point_state(1).displacement;
    // O((L/N)²) ≈ 2.4e-4 relative discretization error at 64 elements; no axial shortening from
    // shear or extension: u1 is the geometric O(w²/L) only.
    BOOST_TEST(std::abs(u[2] - exact) < 1e-3 * exact);
    BOOST_TEST(std::abs(u[0]) < 1e-3 * exact);
}

BOOST_AUTO_TEST_CASE(prescribed_root_motion_moves_the_unloaded_beam_rigidly) {
    Model m = test::rollup_model(8);
    m.point_loads.clear();
    m.constraints[0].kind = Constraint::Kind::prescribed;
    m.constraints[0].displacement = Vec3(0.3, -0.2, 0.5);
    m.constraints[0].rotation = Vec3(0.4, -1.1, 0.7);  // 1.36 rad, scaled by the load factor
    form::MixedStatics<param::Rodrigues> problem(m);
    BOOST_TEST_REQUIRE(
        (run_static(problem, {1.0}, tight(), nullptr).status == SolveStatus::converged));
    const Mat3 R = so3::exp_map(m.constraints[0].rotation);
    const Vec3 expected = m.constraints[0].displacement + (R - Mat3::Identity()) * Vec3(12, 0, 0);
    // A rigid motion is an exact solution of Eqs. 45–48 (F = M = 0, c constant): round-off only.
    BOOST_TEST((problem.point_state(1).displacement - expected).norm() < 1e-10);
    BOOST_TEST((problem.point_state(1).rotation - R).norm() < 1e-12);
}

BOOST_AUTO_TEST_CASE(section_resultants_of_rollup_are_the_applied_moment_everywhere) {
    form::MixedStatics<param::WienerMilenkovic> problem(test::rollup_model(16));
    BOOST_TEST_REQUIRE(
        (run_static(problem, {1.2}, tight(), nullptr).status == SolveStatus::converged));
    const Vec3 applied = 1.2 * test::rollup_model(16).point_loads[0].moment;
    const std::vector<form::MixedElementResultants> r = problem.resultants();
    BOOST_TEST(r.size() == 16u);
    for (const form::MixedElementResultants& e : r) {
        // Pure bending: zero force, the tip moment transmitted unchanged (inertial components).
        BOOST_TEST(e.force.norm() < 1e-9 * applied.norm() / test::kRollupLength);
        BOOST_TEST((e.moment - applied).norm() < 1e-9 * applied.norm());
    }
}

BOOST_AUTO_TEST_SUITE_END()
