// Accuracy of the mixed statics under mesh refinement: the roll-up against its exact solution
// (benchmarks.md §1, observed order 2), the 45° bend (§2) converging to one answer, and the
// largest load λ*(N) the N-element equations can carry (§1: ≈ λc (1 − 1.1/N)).
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <iomanip>
#include <vector>

#include "core/static_driver.hpp"
#include "formulations/mixed/mixed_statics.hpp"
#include "parameterizations/rodrigues.hpp"
#include "parameterizations/wiener_milenkovic.hpp"
#include "tests/mixed/models.hpp"

using namespace rotbeam;

namespace {

NewtonSettings tight() {
    NewtonSettings s;
    s.residual_tolerance = 1e-12;
    s.increment_tolerance = 1e-12;
    s.max_iterations = 60;
    return s;
}

template <class P>
double rollup_error(int elements, double lambda) {
    form::MixedStatics<P> problem(test::rollup_model(elements));
    const StaticOutcome out = run_static(problem, {lambda}, tight(), nullptr);
    BOOST_TEST_REQUIRE((out.status == SolveStatus::converged));
    const Vec3 u = problem.point_state(1).displacement;
    return (u - test::rollup_exact_tip(lambda)).norm() / test::kRollupLength;
}

template <class P>
void check_rollup_order(double lambda) {
    std::vector<double> errors;
    for (int n = 16; n <= 1024; n *= 2) {
        errors.push_back(rollup_error<P>(n, lambda));
        const double order = errors.size() < 2 ? 0.0
                                               : std::log2(errors[errors.size() - 2] /
                                                           errors.back());
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

}  // namespace

BOOST_AUTO_TEST_SUITE(mixed_convergence)

BOOST_AUTO_TEST_CASE(wiener_milenkovic_rollup_converges_at_second_order) {
    check_rollup_order<param::WienerMilenkovic>(1.6);
}

BOOST_AUTO_TEST_CASE(rodrigues_rollup_converges_at_second_order) {
    check_rollup_order<param::Rodrigues>(0.8);
}

BOOST_AUTO_TEST_SUITE_END()
