// The output schedule of the time integrations (core/output_times.hpp), used the way the fixed-step
// loop uses it: a long run outputs at every grid time it asks for, and its Δt/2 companion (the time
// estimate's) outputs at the same times, bit for bit.
#include <boost/test/unit_test.hpp>
#include <set>
#include <vector>

#include "core/output_times.hpp"

using rotbeam::OutputTimes;

BOOST_AUTO_TEST_SUITE(output_times)

namespace {

// The fixed-step loop's outputs: grid times start + n·h0, n = 1 … steps, output when due (the
// last always), as core/time_stepping.cpp's run_fixed decides.
std::vector<double> fixed_step_outputs(double start, double h0, long steps, double every) {
    OutputTimes outputs(start, every);
    std::vector<double> out;
    for (long n = 1; n <= steps; ++n) {
        const double t = start + static_cast<double>(n) * h0;
        if (outputs.due(t, 1e-9 * h0) || n == steps) out.push_back(t);
    }
    return out;
}

}  // namespace

// 15 000 steps of 2 ms, an output every step, as in BeamDyn's rotating 5-MW blade deck: a running
// sum of the output interval drifted past 2 425 of these grid times by more than the 1e-9 Δt
// within which an output is due (one output of the run lost, 2 425 of the companion's at other
// times). Exact equality is the claim: both grids compute n·h0 and k·every from the same doubles
// (2·0.001 is 0.002 exactly in binary).
BOOST_AUTO_TEST_CASE(a_long_run_and_its_half_step_companion_output_at_the_same_times) {
    const double h0 = 0.002;
    const long steps = 15000;
    const std::vector<double> run = fixed_step_outputs(0.0, h0, steps, h0);
    const std::vector<double> companion = fixed_step_outputs(0.0, h0 / 2, 2 * steps, h0);
    BOOST_TEST(run.size() == static_cast<std::size_t>(steps));
    BOOST_TEST(companion.size() == static_cast<std::size_t>(steps));
    const std::set<double> at(companion.begin(), companion.end());
    long missing = 0;
    for (const double t : run) missing += at.count(t) == 0 ? 1 : 0;
    BOOST_TEST(missing == 0);
}

// An output interval of several steps from a non-zero start: every fifth grid time, no other.
BOOST_AUTO_TEST_CASE(an_interval_of_several_steps_outputs_every_such_step) {
    const std::vector<double> out = fixed_step_outputs(1.5, 1e-3, 10000, 5e-3);
    BOOST_TEST_REQUIRE(out.size() == 2000u);
    for (std::size_t i = 0; i < out.size(); ++i) {
        BOOST_TEST(out[i] == 1.5 + static_cast<double>(5 * (i + 1)) * 1e-3);
    }
}

BOOST_AUTO_TEST_SUITE_END()
