// A fixed Radau IIA step of the mixed dynamics (core/dae_radau.hpp) allocates nothing after the
// first steps: the stage residuals, the Jacobians at the step start, the real (KLU) and complex
// (complex KLU) factorizations refactored in place, the transformed solves and the step loop. The
// moving two-member structure with its follower loads driven by sines (the stage matrices are
// refreshed on some steps and kept on others; both counted in the printed totals).
#include <boost/test/unit_test.hpp>
#include <iostream>
#include <vector>

#include "core/dae_driver.hpp"
#include "formulations/mixed/mixed_dynamics_of.hpp"
#include "formulations/mixed/mixed_statics_of.hpp"
#include "parameterizations/wiener_milenkovic.hpp"
#include "tests/mixed/allocation_counter.hpp"
#include "tests/mixed/dynamic_models.hpp"

using namespace rotbeam;

BOOST_AUTO_TEST_SUITE(mixed_radau_allocation)

BOOST_AUTO_TEST_CASE(radau_iia_steps_allocate_nothing_after_the_first) {
    using P = param::WienerMilenkovic;
    const Model model = test::dynamic_test_model();
    form::MixedDynamicsOf<P> dyn(model, 1.0);
    VecX x = dyn.from_static_state(form::MixedStaticsOf<P>(model).state_vector());
    VecX xdot = VecX::Zero(dyn.size());
    DaeSettings s;
    s.time_step = 2e-3;
    s.end_time = 40e-3;
    std::vector<long> at_step;
    at_step.reserve(64);
    const DaeOutcome out =
        integrate_radau_iia(dyn, x, xdot, s, [&](double, const VecX&, const VecX&, int) {
            at_step.push_back(test::allocation_count());
        });
    BOOST_TEST_REQUIRE(
        (out.status == SolveStatus::converged || out.status == SolveStatus::stalled_at_round_off),
        out.message);
    BOOST_TEST_REQUIRE(at_step.size() == 21U);
    std::cout << "Radau IIA: " << out.steps << " steps, " << out.newton_iterations
              << " stage iterations, " << out.factorizations
              << " factorizations; allocations per step (steps 3-20):";
    for (std::size_t k = 3; k < at_step.size(); ++k)
        std::cout << " " << at_step[k] - at_step[k - 1];
    std::cout << "\n";
    if constexpr (test::kCountsAllocations) {
        for (std::size_t k = 3; k < at_step.size(); ++k)
            BOOST_TEST(at_step[k] - at_step[k - 1] == 0);
    } else {
        BOOST_TEST_MESSAGE("allocations not counted under the sanitizers (allocation_counter.hpp)");
    }
}

BOOST_AUTO_TEST_SUITE_END()
