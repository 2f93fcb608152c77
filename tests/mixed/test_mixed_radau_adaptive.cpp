// Adaptive Radau IIA (core/dae_radau.hpp, "Adaptive steps"; the control of
// core/step_size_control.hpp) on the mixed free-vibration cantilever released from its first
// bending mode (tests/mixed/released_cantilever_runs.hpp): the global error against a converged
// fixed-step reference stays below the tolerance, and the step count grows with the tolerance as
// the estimate's order says.
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <vector>

#include "tests/mixed/released_cantilever_runs.hpp"

using namespace rotbeam;

BOOST_AUTO_TEST_SUITE(mixed_radau_adaptive)

// The case: tip amplitude 1e-5 m, 0–0.5 s (4.2 periods of the 8.4 Hz mode), outputs every 0.05 s,
// stage Newton tolerance 1e-12 of the state scales (1 m for u: 1e-7 of the amplitude, and 1e-4 of
// the smallest tolerance below). One mode: the stretching it causes at second order excites the
// stiff axial modes with an amplitude ∝ (1e-5 m)²/L ≈ 1e-10 m, below every tolerance tested; at
// τ = 1e-9 the control has to resolve them and the count jumps 100× (21 962 steps against 227 at
// 1e-8, measured with outputs every 0.01 s), which is why the tested tolerances stop at 1e-8
// (docs/mixed-dynamics.md).
//
// Reference: fixed-step Radau at Δt = 2.5e-4, shown converged by halving (measured difference
// 1.7e-15 m; order 5 from 2.5e-4 makes the reference's own error a 31st of it); required below
// 1e-3 of the smallest tolerance, so the reference's error is no part of the bound.
//
// Bound on the global error: the local error per step is kept below τ h / T (error per unit
// step), and local errors of an undamped linear vibration propagate without growth (each mode
// turns in its phase plane), so the global error is at most their sum, τ. The estimate is that of
// the embedded order-3 solution, an overestimate of the order-5 solution's error, so the bound
// holds with room (measured error/τ: 3.8e-3, 1.4e-3, 4.0e-4 at 1e-6, 1e-7, 1e-8); asserted: error ≤
// τ, with no factor — a factor would be a tolerance multiplier.
//
// Step count: the estimate is O(h⁴) (order 3) against an allowance ∝ h, so the step that meets it
// scales as τ^(1/3) and the count over the window as τ^(−1/3): 10^(1/3) = 2.15 per decade where the
// step is set by the error (not by the output grid or the growth limit). Asserted between 1.5 and
// 3.2 (2.15 ÷ 1.43 and × 1.5: the rejections and the steps shortened to land on the outputs
// change the count by tens of per cent; measured 42 → 84 → 219 steps, × 2.0 and × 2.6), for the
// decades 1e-6 → 1e-7 → 1e-8.
BOOST_AUTO_TEST_CASE(global_error_below_the_tolerance_and_steps_scale_as_the_estimate_order) {
    constexpr double kEnd = 0.5, kOutput = 0.05, kNewton = 1e-12, kAmplitude = 1e-5;
    const std::vector<double> tolerances = {1e-6, 1e-7, 1e-8};
    const test::ReleasedRun ref =
        test::released_cantilever_run(0.0, 2.5e-4, kEnd, kOutput, kNewton, kAmplitude);
    const test::ReleasedRun half =
        test::released_cantilever_run(0.0, 1.25e-4, kEnd, kOutput, kNewton, kAmplitude);
    const double ref_error = test::max_difference(ref.tip_z, half.tip_z);
    BOOST_TEST_MESSAGE("reference: |R(2.5e-4) − R(1.25e-4)| = " << ref_error << " m");
    BOOST_REQUIRE(ref.tip_z.size() == 11U && half.tip_z.size() == 11U);
    BOOST_TEST(ref_error < 1e-3 * tolerances.back());
    std::vector<long> steps;
    for (const double tol : tolerances) {
        const test::ReleasedRun r =
            test::released_cantilever_run(tol, 1e-3, kEnd, kOutput, kNewton, kAmplitude);
        BOOST_TEST_CONTEXT("tolerance " << tol << ": " << r.outcome.message) {
            // Converged, or converged to what the arithmetic allows (core/convergence.hpp); a
            // step-size underflow or exhausted cuts would be `diverged` or `singular`.
            BOOST_TEST((r.outcome.status == SolveStatus::converged ||
                        r.outcome.status == SolveStatus::stalled_at_round_off));
            BOOST_REQUIRE(r.tip_z.size() == 11U);
            const double error = test::max_difference(r.tip_z, half.tip_z);
            BOOST_TEST_MESSAGE("tolerance " << tol << ": " << r.outcome.steps << " steps, "
                                            << r.outcome.control.rejected_steps << " rejected, "
                                            << r.outcome.factorizations << " factorizations, cpu "
                                            << r.cpu_seconds << " s, global error " << error
                                            << " m (" << error / tol << " τ)");
            BOOST_TEST(error <= tol);
            BOOST_TEST(r.outcome.control.step_cuts == 0);
        }
        steps.push_back(r.outcome.steps);
    }
    for (std::size_t k = 1; k < steps.size(); ++k) {
        const double growth = static_cast<double>(steps[k]) / static_cast<double>(steps[k - 1]);
        BOOST_TEST_MESSAGE("steps " << steps[k - 1] << " → " << steps[k] << ": × " << growth
                                    << " per decade (τ^(−1/3): × 2.15)");
        BOOST_TEST(growth > 1.5);
        BOOST_TEST(growth < 3.2);
    }
}

BOOST_AUTO_TEST_SUITE_END()
