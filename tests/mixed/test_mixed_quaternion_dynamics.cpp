// The mixed dynamics with the quaternion (formulations/mixed/mixed_dynamics.hpp): the
// unknown count (one support, and a second, prescribed and moving support with the scale ρ),
// consistent initial conditions from a non-equilibrium start by the Newton on the
// initial-condition chart (IDA starts from it), and the norm kept by the Cayley relations along a
// fixed-step run (∂F/∂X and ∂F/∂Ẋ against central differences, and the radial rate entering
// nowhere, are the generic harness's: tests/harness/test_jacobians.cpp; no allocation after the
// first evaluation, with both supports, and the follower-load counters are every
// parameterization's: tests/mixed/test_mixed_dynamics_jacobian.cpp).
#include <boost/test/unit_test.hpp>
#include <cmath>

#include "core/dae_driver.hpp"
#include "formulations/mixed/mixed_dynamics.hpp"
#include "formulations/mixed/mixed_statics.hpp"
#include "parameterizations/quaternion.hpp"
#include "tests/mixed/dynamic_models.hpp"
#include "tests/mixed/initial_conditions.hpp"

using namespace rotbeam;
using Q = param::Quaternion;
using Dynamics = form::MixedDynamics<Q>;

BOOST_AUTO_TEST_SUITE(mixed_quaternion_dynamics)

// 19 unknowns and 20 rows per element, 7 unknowns and 6 rows per free node, 6 at the first
// support and 7 (ρ) at every further one: square on a tree (docs/mixed-dynamics.md).
BOOST_AUTO_TEST_CASE(unknown_count_is_square_on_a_tree) {
    for (const Model& m : {test::dynamic_test_model(), test::two_support_dynamic_model()}) {
        const Dynamics dyn(m, 1.0);
        int free = 0, supports = 0;
        for (int n = 0; n < dyn.node_count(); ++n) (dyn.supported(n) ? supports : free) += 1;
        const int columns = 19 * dyn.element_count() + 7 * free + 6 + 7 * (supports - 1);
        const int rows = 20 * dyn.element_count() + 6 * dyn.node_count();
        BOOST_TEST(dyn.size() == columns);
        BOOST_TEST(dyn.size() == rows);
        BOOST_TEST(dyn.pattern().rows() == dyn.size());
    }
}

// At rest (Ẋ = 0, P = H = 0) the momentum rows vanish and the node and kinematic rows are the
// statics' at the same state: a static equilibrium is a dynamic one.
BOOST_AUTO_TEST_CASE(at_rest_the_residual_is_the_static_one) {
    const Model model = test::dynamic_test_model();
    form::MixedStatics<Q> statics(model);
    Dynamics dyn(model, 1.0);
    VecX xs(statics.size());
    for (int i = 0; i < statics.size(); ++i) xs[i] = 0.5 * std::sin(0.37 * i + 0.2);
    statics.set_state_vector(xs);
    statics.set_load_factor(1.0);
    VecX rs, rd;
    statics.evaluate(rs, nullptr);
    // The statics take the load time functions at t = 0 (times the load factor); the dynamics at t.
    dyn.evaluate(0.0, dyn.from_static_state(xs), VecX::Zero(dyn.size()), rd, nullptr, nullptr);
    const int node_rows = 6 * dyn.node_count();
    BOOST_TEST((rd.head(node_rows) - rs.head(node_rows)).cwiseAbs().maxCoeff() < 1e-12);
    for (int e = 0; e < dyn.element_count(); ++e) {
        const int r = dyn.element_row(e);
        BOOST_TEST((rd.segment<14>(r) - rs.segment<14>(statics.numbering().element_row(e)))
                       .cwiseAbs()
                       .maxCoeff() < 1e-12);
        BOOST_TEST(rd.segment<6>(r + dyn.numbering().fP()).cwiseAbs().maxCoeff() == 0.0);
    }
}

// A start far from consistency (reference configuration, rigid initial velocity, loads on at
// t₀ = 0.4): the shared Newton on the initial-condition chart (the largest component of each
// element q algebraic) makes it consistent and IDA starts from that state; the rotations and their
// norms are kept, and the rates come back tangent to the sphere.
BOOST_AUTO_TEST_CASE(ida_starts_a_non_equilibrium_start_consistent) {
    const Model model = test::dynamic_test_model();
    Dynamics dyn(model, 1.0);
    VecX x0 = dyn.from_static_state(form::MixedStatics<Q>(model).state_vector());
    dyn.set_translational_momenta(x0, Vec3(0.3, -0.2, 0.5));
    const VecX xd0 = VecX::Zero(dyn.size());
    const double t0 = 0.4;
    const test::TwoInitialConditions ic = test::consistent_twice(dyn, t0, x0, xd0);
    BOOST_TEST(ic.r0 > 0.1);
    double kept = 0.0, tangent = 0.0;
    for (int e = 0; e < dyn.element_count(); ++e) {
        const int col = dyn.element_column(e) + dyn.numbering().c();
        const VecX& x = ic.x_ic;
        kept = std::max(kept, (x.segment<4>(col) - x0.segment<4>(col)).cwiseAbs().maxCoeff());
        tangent = std::max(tangent, std::abs(x.segment<4>(col).dot(ic.xd_ic.segment<4>(col))));
    }
    BOOST_TEST_MESSAGE("quaternion: scaled residual before "
                       << ic.r0 << ", at IDA's start " << ic.r_ic << "; IDA vs Newton: X " << ic.dx
                       << ", Ẋ " << ic.dxd);
    BOOST_TEST(ic.r_ic < 1e-8);
    BOOST_TEST(ic.dx < 1e-8);
    BOOST_TEST(ic.dxd < 1e-8);
    BOOST_TEST(kept < 1e-12);  // the element rotations (a consistent norm) are kept
    BOOST_TEST(tangent < 1e-12);
    BOOST_TEST(ic.xd_newton.cwiseAbs().maxCoeff() > 0.1);
}

// Along a fixed-step run from a non-equilibrium start (rigid velocity, sine loads), rotating the
// structure by more than a radian, the nodes' |q̂| stays 1 to the Newton tolerance (the Cayley
// relations propagate the support's unit quaternion at every instant: nothing accumulates over
// the steps; each kinematic row is met to 1e-10, so |q̂| − 1 is bounded by ~1e-10 per element of
// the path from the support, 6e-10 for the 6 elements here) and the elements' |q_i| is the designed
// midpoint average cos(δ/4) of its end nodes: equal to |q̂_a + q̂_b|/2 to the same tolerance.
BOOST_AUTO_TEST_CASE(fixed_step_run_keeps_the_node_norms_at_round_off) {
    Model model = test::dynamic_test_model();
    Dynamics dyn(model, 0.5);
    VecX x = dyn.from_static_state(form::MixedStatics<Q>(model).state_vector());
    dyn.set_translational_momenta(x, Vec3(0.0, 0.0, 6.0));
    VecX xd = VecX::Zero(dyn.size());
    DaeSettings s;
    s.end_time = 0.5;
    s.time_step = 1e-3;
    s.output_interval = 0.05;
    double nodes = 0.0, average = 0.0, angle = 0.0;
    const DaeOutcome out =
        integrate_trapezoidal(dyn, x, xd, s, [&](double t, const VecX& xs, const VecX&, int) {
            nodes = std::max(nodes, dyn.norm_drift(xs, t).nodes);
            angle = std::max(angle, dyn.max_rotation_angle(xs));
            for (int e = 0; e < dyn.element_count(); ++e) {
                const form::MixedElement& el = dyn.layout().elements[static_cast<std::size_t>(e)];
                auto node_q = [&](int n) -> Vec4 {
                    return dyn.supported(n) ? Vec4(Q::identity())
                                            : Vec4(xs.segment<4>(dyn.node_column(n) + 3));
                };
                const double mid = 0.5 * (node_q(el.start_node) + node_q(el.end_node)).norm();
                average = std::max(average,
                                   std::abs(xs.segment<4>(dyn.element_column(e) + 3).norm() - mid));
            }
        });
    BOOST_REQUIRE(out.status == SolveStatus::converged);
    BOOST_TEST_MESSAGE("quaternion, 0.5 s fixed step: max ||q̂| − 1| "
                       << nodes << ", max ||q_i| − midpoint| " << average << ", angle " << angle);
    BOOST_TEST(angle > 1.0);
    BOOST_TEST(nodes < 1e-9);
    BOOST_TEST(average < 1e-9);
}

BOOST_AUTO_TEST_SUITE_END()
