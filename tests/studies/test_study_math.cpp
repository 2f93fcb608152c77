// The studies' decision logic (studies/study_math.hpp, timing.hpp's median and cap on repeats):
// order fits, the Pareto front, the singularity study's reach classifier and the round-off floor.
#include <stdlib.h>

#include <boost/test/unit_test.hpp>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "runs/timing.hpp"
#include "studies/study_math.hpp"

using namespace rotbeam::cli;

BOOST_AUTO_TEST_SUITE(study_math)

BOOST_AUTO_TEST_CASE(median_is_the_middle_sample_and_ignores_outliers) {
    BOOST_TEST(median({5.0, 1.0, 3.0}) == 3.0);
    BOOST_TEST(median({4.0, 1.0, 3.0, 100.0}) == 3.5);     // even count: mean of the two middle
    BOOST_TEST(median({2.0, 2.0, 2.0, 2.0, 1e9}) == 2.0);  // one descheduled run changes nothing
    BOOST_CHECK_THROW(median({}), std::logic_error);
}

// ROTBEAM_TIMING_REPEATS caps the timed repeats and never raises them; unset, the wanted count
// (at least one); a value that is not a positive integer is refused by name.
BOOST_AUTO_TEST_CASE(timing_repeats_are_capped_by_the_environment_only_downwards) {
    unsetenv("ROTBEAM_TIMING_REPEATS");
    BOOST_TEST(timing_repeats(5) == 5);
    BOOST_TEST(timing_repeats(0) == 1);
    setenv("ROTBEAM_TIMING_REPEATS", "1", 1);
    BOOST_TEST(timing_repeats(5) == 1);
    int calls = 0;
    const Timing t = time_in_process([&] { ++calls; }, 7);
    BOOST_TEST(calls == 1);
    BOOST_TEST(t.repeats == 1);
    setenv("ROTBEAM_TIMING_REPEATS", "3", 1);
    BOOST_TEST(timing_repeats(2) == 2);
    BOOST_TEST(timing_repeats(101) == 3);
    for (const char* bad : {"0", "-1", "two", "1x", ""}) {
        setenv("ROTBEAM_TIMING_REPEATS", bad, 1);
        BOOST_CHECK_EXCEPTION(
            timing_repeats(3), rotbeam::InputError, [](const rotbeam::InputError& e) {
                return std::string(e.what()).find("ROTBEAM_TIMING_REPEATS") != std::string::npos;
            });
    }
    unsetenv("ROTBEAM_TIMING_REPEATS");
}

BOOST_AUTO_TEST_CASE(fit_order_recovers_the_exponent_of_a_power_law) {
    const std::vector<double> n = {4, 8, 16, 32, 64};
    std::vector<double> e2, e4;
    for (double x : n) {
        e2.push_back(3.0 * std::pow(x, -2.0));
        e4.push_back(0.1 * std::pow(x, -4.0) * (1.0 + 0.5 / x));  // with a higher-order term
    }
    BOOST_TEST(fit_order(n, e2) == 2.0, boost::test_tools::tolerance(1e-12));
    // The tail of the perturbed law is closer to 4 than the whole-range fit.
    BOOST_TEST(std::abs(tail_order(n, e4, 2) - 4.0) < std::abs(fit_order(n, e4) - 4.0));
    BOOST_TEST(std::abs(tail_order(n, e4, 2) - 4.0) < 0.02);
}

BOOST_AUTO_TEST_CASE(fit_order_drops_points_below_the_floor_and_non_finite_ones) {
    const std::vector<double> n = {2, 4, 8, 16, 32};
    const std::vector<double> e = {1e-2, 2.5e-3, 6.25e-4, 3e-15, NAN};  // last two: round-off, NaN
    BOOST_TEST(fit_order(n, e, 1e-13) == 2.0, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(std::isnan(fit_order({1.0}, {0.1})));            // one point has no slope
    BOOST_TEST(std::isnan(fit_order({2.0, 2.0}, {0.1, 0.2})));  // no spread in n
}

BOOST_AUTO_TEST_CASE(pareto_front_keeps_exactly_the_non_dominated_points) {
    //                      0     1     2     3     4     5
    const std::vector<double> cost = {1.0, 2.0, 3.0, 2.5, 0.5, NAN};
    const std::vector<double> err = {1e-3, 1e-6, 1e-9, 1e-5, 1e-2, 1e-12};
    const std::vector<bool> front = pareto_front(cost, err);
    // 3 is dominated by 1 (cheaper and more accurate); NaN cost is never on the front.
    const std::vector<bool> expected = {true, true, true, false, true, false};
    BOOST_TEST(front == expected, boost::test_tools::per_element());
    // Equal points do not dominate each other.
    BOOST_TEST((pareto_front({1.0, 1.0}, {2.0, 2.0}) == std::vector<bool>{true, true}));
}

BOOST_AUTO_TEST_CASE(classify_reach_tells_wrong_branch_from_lost_accuracy_and_solver_stops) {
    const std::vector<ConvergedStep> good = {{0.5, 1e-8}, {1.0, 2e-8}, {1.5, 3e-8}};
    Reach r = classify_reach(good, "converged", 3, 1e-3);
    BOOST_TEST(r.stopped == "completed");
    BOOST_TEST(r.load_factor == 1.5);
    r = classify_reach(good, "singular", 4, 1e-3);  // stopped before the fourth step
    BOOST_TEST(r.stopped == "singular");
    BOOST_TEST(r.steps_reached == 3);
    // Converged, but on another branch from the second step on: the reach ends before it, even
    // though a later step happens to be close to the answer again.
    const std::vector<ConvergedStep> wrong = {{0.5, 1e-8}, {1.0, 0.4}, {1.5, 1e-8}};
    r = classify_reach(wrong, "converged", 3, 1e-3);
    BOOST_TEST(r.stopped == "wrong branch");
    BOOST_TEST(r.load_factor == 0.5);
    // A smooth growth past the tolerance is lost accuracy, not a branch switch.
    const std::vector<ConvergedStep> drift = {{0.5, 4e-4}, {1.0, 8e-4}, {1.5, 1.6e-3}};
    r = classify_reach(drift, "converged", 3, 1e-3);
    BOOST_TEST(r.stopped == "lost accuracy");
    BOOST_TEST(r.load_factor == 1.0);
    r = classify_reach({{0.5, NAN}}, "converged", 1, 1e-3);
    BOOST_TEST(r.stopped == "wrong branch");
    BOOST_TEST(r.steps_reached == 0);
}

BOOST_AUTO_TEST_CASE(floor_index_finds_where_refinement_stops_paying) {
    BOOST_TEST(floor_index({1e-2, 1e-6, 1e-10, 3e-13, 8e-13, 2e-12}) == 3);
    BOOST_TEST(floor_index({NAN, 1e-3}) == 1);
    BOOST_TEST(floor_index({}) == -1);
}

BOOST_AUTO_TEST_SUITE_END()
