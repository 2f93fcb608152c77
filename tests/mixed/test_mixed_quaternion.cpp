// The mixed statics with four rotation unknowns (the quaternion; formulations/mixed/
// mixed_statics.hpp with MixedNumbering's redundant parameter): the unknown count and the norm
// conservation of the discrete Eq. 48 (the analytic Jacobian against central differences, one
// support and two supports with the scale ρ, is the generic harness's:
// tests/harness/test_jacobians.cpp; exactness of the reference configuration and no heap
// allocation after the first evaluation, with both supports, are every parameterization's:
// tests/mixed/test_mixed_jacobian.cpp).
#include <boost/test/unit_test.hpp>
#include <cmath>

#include "core/static_driver.hpp"
#include "formulations/mixed/mixed_statics.hpp"
#include "parameterizations/quaternion.hpp"
#include "parameterizations/rotation_vector.hpp"
#include "tests/mixed/deformed_model.hpp"
#include "tests/mixed/models.hpp"

using namespace rotbeam;
using Q = param::Quaternion;
using Statics = form::MixedStatics<Q>;

namespace {

// The joined beam of docs/benchmarks.md §3 as a static case: two members from clamped roots
// (0, ∓0.5, 0) to a common joint (1, 0, 0) m, the 0.1 × 0.05 m aluminium section, a follower force
// 1e5 N along e3 at the joint (a large deflection: 0.75 m at load factor 4).
Model joined_beam_model(int elements) {
    Model m;
    m.points = {{"root1", Vec3(0, -0.5, 0)}, {"root2", Vec3(0, 0.5, 0)}, {"joint", Vec3(1, 0, 0)}};
    const double E = 70e9, G = E / 2.7, A = 0.005, k = 5.0 / 6.0;
    const Vec6 stiffness = (Vec6() << E * A, k * G * A, k * G * A, G * 2.8625e-6,
                            E * 1.0416666666666667e-6, E * 4.166666666666667e-6)
                               .finished();
    m.members = {test::member("member1", 0, 2, test::diagonal_section(stiffness), elements),
                 test::member("member2", 1, 2, test::diagonal_section(stiffness), elements)};
    m.constraints = {Constraint{0, Constraint::Kind::clamped, Vec3::Zero(), Vec3::Zero(), {}},
                     Constraint{1, Constraint::Kind::clamped, Vec3::Zero(), Vec3::Zero(), {}}};
    PointLoad load;
    load.point = 2;
    load.force = Vec3(0, 0, 1e5);
    load.frame = LoadFrame::follower;
    m.point_loads = {load};
    return m;
}

template <class Problem>
Vec3 joined_beam_joint(Problem& problem) {
    NewtonSettings s;
    s.residual_tolerance = 1e-12;
    s.increment_tolerance = 1e-12;
    const StaticOutcome out = run_static(problem, {1.0, 2.0, 3.0, 4.0}, s, nullptr);
    BOOST_TEST_REQUIRE((out.status == SolveStatus::converged));
    return problem.point_state(2).displacement;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(mixed_quaternion_statics)

// Per element u, q, F, M = 13 unknowns, per free node û, q̂ = 7, per support 6 reactions (+ ρ
// after the first); rows 14 per element, 6 per node: square (mixed_layout.hpp).
BOOST_AUTO_TEST_CASE(unknown_count_is_square_for_one_and_two_supports) {
    for (const int n : {1, 16, 256}) {
        const Statics rollup(test::rollup_model(n));
        BOOST_TEST(rollup.size() == 13 * n + 7 * n + 6);  // N elements, N free nodes, one clamp
    }
    const Statics one(test::deformed_test_model());
    const int e = one.numbering().element_count;
    const int nodes = one.numbering().node_count();
    BOOST_TEST(e == 6);
    BOOST_TEST(one.size() == 13 * e + 7 * (nodes - 1) + 6);
    BOOST_TEST(one.size() == 14 * e + 6 * nodes);
    const Statics two(test::two_support_model());
    BOOST_TEST(two.size() == 13 * e + 7 * (nodes - 2) + 6 + 7);
    BOOST_TEST(two.size() == 14 * e + 6 * nodes);
}

// A closed loop (a member from the tip back to the root) leaves one redundant closure row.
BOOST_AUTO_TEST_CASE(closed_loop_is_refused_with_an_input_error) {
    Model m = test::deformed_test_model();
    m.members.push_back(test::member("back", 2, 0, m.members[0].sections[0].section, 2));
    BOOST_CHECK_THROW(Statics{m}, InputError);
}

// The discrete Eq. 48 is a Cayley transform from node to node: |q̂| stays 1 to round-off at every
// node, while the element's q_i = (q̂_a + q̂_b)/2 has |q_i| = cos(δ/4) for its relative rotation δ
// (λπ/N on the roll-up, up to the O(ΔL³) error of the Cayley angle 4 atan(δ/4) vs δ).
BOOST_AUTO_TEST_CASE(node_quaternions_keep_unit_norm_and_element_norms_are_the_midpoint_average) {
    const int n = 16;
    const double lambda = 1.0;
    Statics problem(test::rollup_model(n));
    NewtonSettings s;
    s.residual_tolerance = 1e-12;
    s.increment_tolerance = 1e-12;
    const StaticOutcome out = run_static(problem, {lambda}, s, nullptr);
    BOOST_TEST_REQUIRE((out.status == SolveStatus::converged));
    const form::QuaternionNormDrift d = problem.norm_drift();
    const double expected = 1.0 - std::cos(lambda * kPi / n / 4.0);
    BOOST_TEST_MESSAGE("roll-up λ = 1, N = 16: max ||q̂| − 1| = "
                       << d.nodes << " (nodes), max ||q_i| − 1| = " << d.elements
                       << " (elements; 1 − cos(δ/4) = " << expected << ")");
    BOOST_TEST(d.nodes < 1e-13);  // a few ε per element over 16 Cayley steps
    // The Cayley angle 4 atan(δ/4) differs from δ by δ²/48 relative (8e-4 here): 1 % is a margin.
    BOOST_TEST(std::abs(d.elements - expected) < 0.01 * expected);
    BOOST_TEST(out.message.find("nodes") != std::string::npos);  // the drift is in the message
}

// Two clamps: the second root's quaternion is ρ q_given. Along the continuation the path from the
// first root arrives at the second with unit norm and the same sign, so ρ = 1 to round-off, and
// the joint's displacement converges to the rotation vector's (same Eqs. 45–47, another discrete
// Eq. 48) at the element's order 2: their difference falls by ≈ 4 per halving of the mesh.
BOOST_AUTO_TEST_CASE(two_clamps_solve_with_unit_scale_and_second_order_agreement) {
    std::vector<double> differences;
    for (const int n : {8, 16, 32}) {
        Statics quaternion(joined_beam_model(n));
        form::MixedStatics<param::RotationVector> rotation_vector(joined_beam_model(n));
        const Vec3 uq = joined_beam_joint(quaternion);
        const Vec3 ur = joined_beam_joint(rotation_vector);
        const form::MixedNumbering& layout = quaternion.numbering();
        const double rho = quaternion.state_vector()[layout.node_column(1) + 6];
        BOOST_TEST_REQUIRE(layout.has_scale(1));
        BOOST_TEST(std::abs(rho - 1.0) < 1e-12);
        BOOST_TEST(quaternion.norm_drift().nodes < 1e-13);
        differences.push_back((uq - ur).norm());
        BOOST_TEST_MESSAGE("joined beam, " << n << " elements per member: joint " << uq.transpose()
                                           << ", |u_q − u_rv| = " << differences.back()
                                           << ", ρ − 1 = " << rho - 1.0);
    }
    for (std::size_t k = 1; k < differences.size(); ++k) {
        const double ratio = differences[k - 1] / differences[k];
        BOOST_TEST_MESSAGE("ratio " << ratio);
        BOOST_TEST(ratio > 3.5);  // order 2 (4), pre-asymptotic at 8 elements per member
        BOOST_TEST(ratio < 4.5);
    }
}

BOOST_AUTO_TEST_SUITE_END()
