// Adaptive Radau IIA on the released free-vibration cantilever
// (tests/mixed/released_cantilever_runs.hpp): steps, rejections, factorizations, CPU and the global
// error of the tip u_z against a fixed-step reference, with the shape of the step-size history
// (ratios of consecutive accepted steps). A measurement, not a test (docs/mixed-dynamics.md "Radau
// IIA", adaptive steps).
//   bench_radau_adaptive [END [REFERENCE_DT [MODE_AMPLITUDE [TOL ...]]]]
// defaults: END = 0.5 s, REFERENCE_DT = 2.5e-5 s (and its half, to show it converged), TOL = 1e-4,
// 1e-6, 1e-8; MODE_AMPLITUDE 0 (released from the static deflection; > 0: from the first mode
// with that tip u_z); outputs every 0.01 s; Newton tolerance 1e-12.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "core/time_limit.hpp"
#include "tests/mixed/released_cantilever_runs.hpp"

using namespace rotbeam;

namespace {

constexpr double kOutput = 0.01;
constexpr double kNewton = 1e-12;
constexpr double kLimit = 120.0;  // wall seconds per adaptive run

void print_history(const std::vector<double>& h) {
    // Ratios h_{n+1}/h_n of consecutive accepted steps, in bins; the last step of each output
    // interval is shortened to land on it, so the ratios around it say nothing of the control.
    const double edges[] = {0.5, 0.9, 0.999999, 1.000001, 1.2, 1.99};
    const char* names[] = {"<0.5", "0.5-0.9", "0.9-1", "=1", "1-1.2", "1.2-2", ">=2"};
    int bins[7] = {};
    for (std::size_t k = 1; k < h.size(); ++k) {
        const double r = h[k] / h[k - 1];
        int b = 0;
        while (b < 6 && r >= edges[b]) ++b;
        ++bins[b];
    }
    std::vector<double> sorted = h;
    std::sort(sorted.begin(), sorted.end());
    std::printf("    h min %.3g median %.3g max %.3g; ratios h(n+1)/h(n):", sorted.front(),
                sorted[sorted.size() / 2], sorted.back());
    for (int b = 0; b < 7; ++b) std::printf(" %s %d", names[b], bins[b]);
    std::printf("\n");
}

}  // namespace

int main(int argc, char** argv) {
    const double end = argc > 1 ? std::atof(argv[1]) : 0.5;
    const double ref_dt = argc > 2 ? std::atof(argv[2]) : 2.5e-5;
    std::vector<double> tolerances;
    const double mode = argc > 3 ? std::atof(argv[3]) : 0.0;
    for (int i = 4; i < argc; ++i) tolerances.push_back(std::atof(argv[i]));
    if (tolerances.empty()) tolerances = {1e-4, 1e-6, 1e-8};
    const test::ReleasedRun ref =
        test::released_cantilever_run(0.0, ref_dt, end, kOutput, kNewton, mode);
    const test::ReleasedRun half =
        test::released_cantilever_run(0.0, ref_dt / 2, end, kOutput, kNewton, mode);
    std::printf(
        "reference fixed Δt %.3g: %ld steps, cpu %.2f s; |R(Δt) − R(Δt/2)| = %.3g m "
        "(max over %zu outputs; amplitude %.3g m)\n",
        ref_dt, ref.outcome.steps, ref.cpu_seconds, test::max_difference(ref.tip_z, half.tip_z),
        ref.tip_z.size(), std::abs(ref.tip_z.front()));
    for (const double dt : {1e-3, 1e-4}) {
        const test::ReleasedRun r =
            test::released_cantilever_run(0.0, dt, end, kOutput, kNewton, mode);
        std::printf(
            "fixed Δt %.3g: %ld steps, %ld factorizations, %ld iterations, cpu %.2f s, "
            "error %.3g m\n",
            dt, r.outcome.steps, r.outcome.factorizations, r.outcome.newton_iterations,
            r.cpu_seconds, test::max_difference(r.tip_z, half.tip_z));
    }
    for (const double tol : tolerances) {
        test::ReleasedRun r;
        {
            const ScopedTimeLimit limit(kLimit);
            r = test::released_cantilever_run(tol, 1e-3, end, kOutput, kNewton, mode);
        }
        if (r.timed_out) {
            double t = 0.0;
            for (const double h : r.steps) t += h;
            std::printf(
                "TOL %.0e: not finished in %.0f s wall: %zu steps to t = %.4g s, cpu %.2f s\n", tol,
                kLimit, r.steps.size(), t, r.cpu_seconds);
            if (!r.steps.empty()) print_history(r.steps);
            continue;
        }
        std::printf(
            "TOL %.0e: %s, %ld steps, %d rejected, %d cuts, %ld factorizations, %ld "
            "iterations, cpu %.2f s, error %.3g m (%.3g TOL)\n",
            tol, to_string(r.outcome.status), r.outcome.steps, r.outcome.control.rejected_steps,
            r.outcome.control.step_cuts, r.outcome.factorizations, r.outcome.newton_iterations,
            r.cpu_seconds, test::max_difference(r.tip_z, half.tip_z),
            test::max_difference(r.tip_z, half.tip_z) / tol);
        if (r.outcome.status != SolveStatus::converged &&
            r.outcome.status != SolveStatus::stalled_at_round_off)
            std::printf("    %s\n", r.outcome.message.c_str());
        if (!r.steps.empty()) print_history(r.steps);
    }
    return 0;
}
