// The fixed-step loop of the DAE integrators (core/dae_driver.hpp: the trapezoidal rule and
// Radau IIA): steps on the grid start + n Δt; a step whose Newton fails is retried with h/2 from
// the unchanged state, up to max_cuts times in a row, and covered by halves of itself, so the grid
// and the output times do not change. `Run` offers time(), x(), xdot(), iterations(),
// try_step(t_next, h) (the state unchanged until accept), accept(t_next, h) and cut(h, cuts)
// (true: retry with h/2; false: the status is set).
#pragma once

#include <cmath>

#include "core/dae_driver.hpp"
#include "core/time_limit.hpp"

namespace rotbeam {

template <class Run>
bool run_fixed_steps(Run& run, const DaeSettings& s, const DaeOutput& output) {
    const long steps = std::lround((s.end_time - s.start_time) / s.time_step);
    const long every =
        s.output_interval > 0.0 ? std::max(1L, std::lround(s.output_interval / s.time_step)) : 1;
    for (long n = 1; n <= steps; ++n) {
        const double t = s.start_time + static_cast<double>(n) * s.time_step;
        check_time_limit("at time", run.time());
        for (int cuts = 0;;) {
            // Uncut: the case's Δt itself; cut: pieces of Δt / 2^cuts, the last landing on t.
            const double piece = std::ldexp(s.time_step, -cuts);
            const bool last = cuts == 0 || run.time() + piece >= t - 1e-9 * piece;
            const double hs = cuts == 0 ? s.time_step : last ? t - run.time() : piece;
            const double to = last ? t : run.time() + hs;
            if (!run.try_step(to, hs)) {
                if (!run.cut(hs, cuts)) return false;
                ++cuts;
                continue;
            }
            run.accept(to, hs);
            if (last) break;
        }
        if (output && (n % every == 0 || n == steps))
            output(t, run.x(), run.xdot(), run.iterations());
    }
    return true;
}

}  // namespace rotbeam
