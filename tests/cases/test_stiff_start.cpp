// A very stiff beam (EA = GA = EI = GJ = 1e9, m = 1, length 1, 8 mixed elements) started at rest
// and undeformed under gravity, every parameterization × integrator of the mixed formulation,
// steps of 0.0105 over 1.05 s (the rigid-rotation test's steps, tests/cases/
// test_mixed_rotating_dynamics.cpp, without the frame). Gravity comes on at once, so the exact
// motion oscillates about the static deflection w_s between 0 and 2 w_s at ω₁ ≈ 1.1e5 rad/s, far
// beyond the step. The static deflection of the cantilever under q = m g is the closed form
// w_s = q L⁴/(8 EI) + q L²/(2 GA) = 6.13125e-9 (bending and shear; the mixed element's nodal
// values reproduce it, its equilibrium is exact for a uniform load). What each integrator must
// give, at every output:
//  - the trapezoidal rule does not damp the unresolved vibration: within [0, 2 w_s] (+1 % of w_s
//    for the sampling of a vibration the step does not resolve, and for round-off);
//  - IDA (BDF2) and Radau IIA damp it out in the first steps (amplification → 0 as hω → ∞):
//    within 1e-3 w_s of w_s at t ≥ 0.5 s (measured: 5.4e-16 w_s at most).
#include <boost/test/unit_test.hpp>
#include <cmath>

#include "tests/cases/spinning_beam.hpp"

using namespace rotbeam;

BOOST_AUTO_TEST_SUITE(stiff_start)

BOOST_AUTO_TEST_CASE(a_stiff_beam_starts_at_rest_under_gravity_in_every_integrator) {
    test::SpinningBeam b;
    b.stiffness = {1e9, 1e9, 1e9, 1e9, 1e9, 1e9};
    b.elements = 8;
    b.mixed = true;
    const std::string text =
        test::spinning_beam_case(
            "  type: dynamic\n  time_step: 0.0104719755\n  end_time: 1.0471975512\n"
            "  output_interval: 0.10471975512\n",
            b) +
        "gravity: [0, 0, -9.81]\n";
    const double w_s = 9.81 / (8.0 * 1e9) + 9.81 / (2.0 * 1e9);
    for (const auto& o :
         test::dynamic_overrides(Formulation::mixed, {"trapezoidal", "ida", "radau-iia-3"})) {
        const nlohmann::json r = test::run_spinning_case(text, o);
        BOOST_TEST_CONTEXT(test::override_label(o)
                           << ": " << r["status"] << " " << r.value("message", "")) {
            BOOST_REQUIRE(test::solved(r));
            BOOST_REQUIRE(r["steps"].size() == 11U);
            const bool damping = o[1] != "analysis.integrator=trapezoidal";
            double worst = 0.0;
            for (const auto& step : r["steps"]) {
                const double w = -step["points"]["tip"]["displacement"][2].get<double>();
                if (damping && step["time"].get<double>() >= 0.5) {
                    worst = std::max(worst, std::abs(w - w_s) / w_s);
                    BOOST_CHECK_SMALL(w - w_s, 1e-3 * w_s);
                } else {
                    BOOST_CHECK(w >= -0.01 * w_s);
                    BOOST_CHECK(w <= 2.01 * w_s);
                }
            }
            BOOST_TEST_MESSAGE(test::override_label(o)
                               << ": worst |w - w_s|/w_s after 0.5 s " << worst);
        }
    }
}

BOOST_AUTO_TEST_SUITE_END()
