// The joined-beam studies' numerics (studies/study_extrapolation.hpp): Richardson
// extrapolation with its observed order, the history error and the extrapolated history.
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <stdexcept>

#include "studies/study_extrapolation.hpp"

using namespace rotbeam::cli;

BOOST_AUTO_TEST_SUITE(study_extrapolation)

BOOST_AUTO_TEST_CASE(richardson_recovers_the_limit_and_order_of_a_power_law) {
    // f(h) = 35 + 2 h² − 0.3 h³ at h = 1/4, 1/8, 1/16: order → 2 with a higher-order term.
    auto f = [](double h) { return 35.0 + 2.0 * h * h - 0.3 * h * h * h; };
    const Richardson r = richardson(f(0.25), f(0.125), f(0.0625), 2.0);
    BOOST_TEST(r.valid);
    BOOST_TEST(std::abs(r.order - 2.0) < 0.1);
    // The extrapolation is far closer to the limit than the finest value.
    BOOST_TEST(std::abs(r.value - 35.0) < 0.05 * std::abs(f(0.0625) - 35.0));
    // A pure power law is extrapolated exactly, whatever the ratio.
    auto g = [](double h) { return -1.0 + 0.7 * std::pow(h, 4.0); };
    const Richardson s = richardson(g(0.9), g(0.3), g(0.1), 3.0);
    BOOST_TEST(s.order == 4.0, boost::test_tools::tolerance(1e-8));
    BOOST_TEST(s.value == -1.0, boost::test_tools::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(richardson_refuses_a_sequence_that_is_not_asymptotic) {
    // Oscillating differences, growing differences, a converged (flat) tail.
    for (const Richardson& r : {richardson(1.0, 1.1, 1.05, 2.0), richardson(1.0, 1.1, 1.3, 2.0),
                                richardson(1.0, 1.0, 1.0, 2.0)}) {
        BOOST_TEST(!r.valid);
        BOOST_TEST(std::isnan(r.order));
    }
    BOOST_TEST(richardson(1.0, 1.1, 1.3, 2.0).value == 1.3);  // the finest value, unchanged
    BOOST_CHECK_THROW(richardson(1.0, 2.0, 3.0, 1.0), std::logic_error);
}

History make_history(const std::vector<double>& t, double amplitude, double shift) {
    History h;
    for (double ti : t) {
        h.time.push_back(ti);
        h.x.push_back(0.1 * amplitude * ti);
        h.y.push_back(0.0);
        h.z.push_back(amplitude * std::sin(20.0 * ti + shift));
    }
    return h;
}

BOOST_AUTO_TEST_CASE(history_error_is_the_largest_distance_over_the_largest_reference_norm) {
    const std::vector<double> t = {0.0, 0.1, 0.2, 0.3};
    const History ref = make_history(t, 2.0, 0.0);
    BOOST_TEST(history_error(ref, ref) == 0.0);
    History u = ref;
    u.z[2] += 0.01;
    u.x[1] -= 0.003;
    double scale = 0.0;
    for (size_t i = 0; i < t.size(); ++i)
        scale = std::max(scale, std::hypot(ref.x[i], ref.y[i], ref.z[i]));
    BOOST_TEST(history_error(u, ref) == 0.01 / scale, boost::test_tools::tolerance(1e-12));
    // A reference with more samples (a finer output grid) is matched by time; its scale is its own
    // largest norm over all its samples.
    const History dense = make_history({0.0, 0.05, 0.1, 0.15, 0.2, 0.25, 0.3}, 2.0, 0.0);
    double dense_scale = 0.0;
    for (size_t i = 0; i < dense.size(); ++i)
        dense_scale = std::max(dense_scale, std::hypot(dense.x[i], dense.y[i], dense.z[i]));
    BOOST_TEST(dense_scale > scale);
    BOOST_TEST(history_error(u, dense) == 0.01 / dense_scale, boost::test_tools::tolerance(1e-12));
    // A sample without a reference sample is never compared silently.
    const History other = make_history({0.0, 0.1, 0.21, 0.3}, 2.0, 0.0);
    BOOST_TEST(std::isnan(history_error(u, other)));
}

BOOST_AUTO_TEST_CASE(extrapolated_history_cancels_the_leading_error_term) {
    const std::vector<double> t = {0.0, 0.5, 1.0, 1.5, 2.0};
    const History exact = make_history(t, 1.0, 0.0);
    // Phase error c Δt² t, the trapezoidal rule's leading term, at Δt and Δt/2.
    auto with_phase = [&](double dt) {
        History h = exact;
        for (size_t i = 0; i < t.size(); ++i)
            h.z[i] = std::sin(20.0 * t[i] + 40.0 * dt * dt * t[i]);
        return h;
    };
    const History coarse = with_phase(1e-2), fine = with_phase(5e-3);
    const History x = extrapolate_history(coarse, fine, 2.0, 2.0);
    BOOST_TEST(history_error(x, exact) < 0.01 * history_error(fine, exact));
    BOOST_CHECK_THROW(extrapolate_history(coarse, make_history({0.0, 0.5}, 1.0, 0.0), 2.0, 2.0),
                      std::logic_error);
}

BOOST_AUTO_TEST_SUITE_END()
