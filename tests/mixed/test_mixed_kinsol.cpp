// KINSOL (line search, scaling, KLU with the analytic sparse Jacobian) as the alternative driver
// of the additive mixed statics: same solution as the shared Newton driver, iteration counts
// reported, non-additive systems refused.
#include <algorithm>
#include <boost/test/unit_test.hpp>

#include "core/errors.hpp"
#include "core/kinsol_driver.hpp"
#include "core/static_driver.hpp"
#include "formulations/mixed/mixed_statics_of.hpp"
#include "parameterizations/quaternion.hpp"
#include "parameterizations/rodrigues.hpp"
#include "parameterizations/wiener_milenkovic.hpp"
#include "tests/harness/type_lists.hpp"
#include "tests/mixed/models.hpp"

using namespace rotbeam;
using EveryParameterization = test::ParameterizationTypes<>;

BOOST_AUTO_TEST_SUITE(mixed_kinsol)

BOOST_AUTO_TEST_CASE_TEMPLATE(kinsol_and_shared_newton_reach_the_same_rollup_state, P,
                              EveryParameterization) {
    // The roll-up's tip turns by λπ: λ = 0.8, or 0.8 of the way to the singular angle of a chart
    // that ends before π (the Euler angles' gimbal lock at π/2: λ = 0.4).
    const double lambda = std::min(0.8, 0.8 * P::singular_angle() / kPi);
    form::MixedStaticsOf<P> newton(test::rollup_model(32));
    NewtonSettings ns;
    const StaticOutcome reference = run_static(newton, {lambda}, ns, nullptr);
    BOOST_TEST_REQUIRE((reference.status == SolveStatus::converged));

    form::MixedStaticsOf<P> kin(test::rollup_model(32));
    kin.set_load_factor(lambda);
    KinsolSettings ks;
    const KinsolOutcome out = solve_kinsol(kin, ks);
    BOOST_TEST_MESSAGE(P::kName << ": KINSOL " << out.iterations << " iterations, "
                                << out.residual_evaluations << " residuals, flag " << out.flag
                                << "; shared Newton " << reference.steps.back().newton_iterations);
    BOOST_TEST_REQUIRE(out.converged);
    BOOST_TEST(out.iterations > 0);
    BOOST_TEST(out.scaled_residual <= ks.residual_tolerance);
    // Both states solve the same equations to a scaled residual of 1e-12; the tip displacement
    // (≈ 10 in) of two such solutions differs by ≲ cond × 1e-12 × L, far below 1e-8.
    const Vec3 d = kin.point_state(1).displacement - newton.point_state(1).displacement;
    BOOST_TEST(d.norm() < 1e-8);
}

BOOST_AUTO_TEST_CASE(kinsol_reports_failure_past_the_limit_load) {
    // Rodrigues with 16 elements has no solution beyond λ ≈ 0.937: KINSOL must say so.
    form::MixedStatics<param::Rodrigues> problem(test::rollup_model(16));
    problem.set_load_factor(0.97);
    KinsolSettings ks;
    ks.max_iterations = 100;
    const KinsolOutcome out = solve_kinsol(problem, ks);
    BOOST_TEST_MESSAGE("Rodrigues λ = 0.97: " << out.failure);
    BOOST_TEST(!out.converged);
    BOOST_TEST(!out.failure.empty());
}

BOOST_AUTO_TEST_SUITE_END()
