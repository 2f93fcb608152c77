// The fixed-step loop of the DAE integrators (core/dae_driver.hpp: the trapezoidal rule and
// Radau IIA): steps on the grid start + n Δt; a step whose Newton fails is retried with h/2 from
// the unchanged state, up to max_cuts times in a row, and covered by halves of itself, so the grid
// and the output times do not change. `Run` offers time(), x(), xdot(), iterations(),
// try_step(t_next, h) (the state unchanged until accept), accept(t_next, h) and cut(h, cuts)
// (true: retry with h/2; false: the status is set). DaeRun holds what every scheme's run shares.
// The adaptive loop (run_adaptive_steps) drives the same interface and the run's local error
// estimate.
#pragma once

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "core/dae_driver.hpp"
#include "core/errors.hpp"
#include "core/output_times.hpp"
#include "core/static_driver.hpp"
#include "core/step_observer.hpp"
#include "core/step_size_control.hpp"
#include "core/time_limit.hpp"

namespace rotbeam {

// What a DAE run keeps besides its scheme's step: the state it advances (the caller's x, ẋ), its
// time, the last attempt's Newton outcome, the stalls, and the outcome's counters, step-control
// record and message. A scheme derives from it and adds try_step (through attempted()) and
// accept (through accepted()).
class DaeRun {
  public:
    // `failing`: what a failed step's message names ("fixed-step Newton"); `iteration`: what a cut
    // recovered from ("Newton" in "after a Newton failure").
    DaeRun(DaeSystem& dae, VecX& x, VecX& xdot, const DaeSettings& s, DaeOutcome& outcome,
           std::string failing, std::string iteration)
        : dae_(dae),
          x_(x),
          xdot_(xdot),
          s_(s),
          outcome_(outcome),
          failing_(std::move(failing)),
          iteration_(std::move(iteration)) {}

    double time() const { return t_; }
    void start(double t) { t_ = t; }
    const VecX& x() const { return x_; }
    const VecX& xdot() const { return xdot_; }
    int iterations() const { return last_.iterations; }
    void add_initial(const NewtonOutcome& ic) { stalls_.add(ic); }
    void fail(SolveStatus status, const std::string& message) {
        outcome_.status = status;
        outcome_.message = message;
    }
    // A failed attempt at the step h: true to retry with h/2, false (status and message set, with
    // the time, the step and the state the system describes) past the cuts.
    bool cut(double h, int cuts) {
        if (cuts < s_.max_cuts) {
            if (outcome_.control.step_cuts == 0) outcome_.control.first_cut_time = t_;
            ++outcome_.control.step_cuts;
            return true;
        }
        std::ostringstream m;
        m.precision(9);
        m << failing_ << " failed at t = " << t_ + h << " (step " << outcome_.steps + 1 << ", Δt "
          << h;
        if (cuts > 0) m << " after " << cuts << " cuts to h/2";
        m << "): " << last_.failure;
        const std::string state = dae_.describe_state(x_);
        if (!state.empty()) m << "; " << state;
        fail(last_.singular ? SolveStatus::singular : SolveStatus::diverged, m.str());
        return false;
    }
    // The outcome's counters and message: `what`, the cuts, the stalls (counted in `stalled`).
    void finish(const std::string& what, const std::string& stalled) {
        const AssemblyCounters c = dae_.counters();
        outcome_.residual_evaluations = c.residual_evaluations;
        outcome_.jacobian_evaluations = c.jacobian_evaluations;
        std::ostringstream m;
        m << what;
        if (outcome_.control.step_cuts > 0) {
            m.precision(9);
            m << "; " << outcome_.control.step_cuts << " steps cut to h/2 after a " << iteration_
              << " failure (first from t = " << outcome_.control.first_cut_time << ")";
        }
        outcome_.message = m.str();
        if (stalls_.count > 0) {
            outcome_.status = SolveStatus::stalled_at_round_off;
            outcome_.message +=
                "; " + stalls_.describe(stalled.c_str(), s_.newton.residual_tolerance);
        }
    }

  protected:
    // The attempt's outcome, counted: true when it converged.
    bool attempted(const NewtonOutcome& out) {
        last_ = out;
        outcome_.newton_iterations += out.iterations;
        return out.accepted();
    }
    // After the scheme moved x_, ẋ_ to the converged step's state at t_next (a step h).
    void accepted(double t_next, double h) {
        stalls_.add(last_);
        t_ = t_next;
        ++outcome_.steps;
        outcome_.last_time = t_;
        outcome_.control.add_step(h, outcome_.steps == 1);
        if (step_observed()) {
            notify_step({t_, static_cast<int>(outcome_.steps), outcome_.newton_iterations,
                         dae_.counters().jacobian_evaluations});
        }
    }

    DaeSystem& dae_;
    VecX& x_;
    VecX& xdot_;
    const DaeSettings& s_;
    DaeOutcome& outcome_;

  private:
    std::string failing_, iteration_;
    StallSummary stalls_;
    NewtonOutcome last_;
    double t_ = 0.0;
};

// The start of every DAE run: the time interval checked, consistent initial conditions at
// s.start_time (consistent_initial_conditions), their iterations counted and the initial output.
// False, with the outcome's status and message set, when they cannot be found.
inline bool start_dae_run(DaeSystem& dae, VecX& x, VecX& xdot, const DaeSettings& s,
                          const DaeOutput& output, DaeOutcome& outcome, NewtonOutcome& ic) {
    ROTBEAM_VERIFY(s.time_step > 0.0 && s.end_time > s.start_time, "bad time interval");
    outcome.last_time = s.start_time;
    ic = consistent_initial_conditions(dae, s.start_time, x, xdot, s.newton, s.time_step);
    if (!ic.accepted()) {
        outcome.status = ic.singular ? SolveStatus::singular : SolveStatus::diverged;
        outcome.message =
            "initial conditions at t = " + std::to_string(s.start_time) + ": " + ic.failure;
        return false;
    }
    outcome.newton_iterations += ic.iterations;
    if (output) output(s.start_time, x, xdot, ic.iterations);
    return true;
}

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

// Adaptive steps (core/step_size_control.hpp) shared by the DAE schemes: from `first_step`, each
// converged attempt's `run.local_error(h)` (scaled; negative when the scheme has no estimate yet:
// the step is accepted and the next may grow by kMaxGrowth) accepts or rejects it; a Newton
// failure retries with h/2 (run.cut); steps are shortened to land on the output times. False,
// with the status set, when the run stops (the cuts exhausted, or a step-size underflow).
template <class Run, class Control>
bool run_adaptive_steps(Run& run, const DaeSettings& s, Control& control, double first_step,
                        const DaeOutput& output, DaeOutcome& outcome) {
    const double every = s.output_interval > 0.0 ? s.output_interval : s.time_step;
    OutputTimes outputs(s.start_time, every);
    double next_output = std::min(outputs.next(), s.end_time);
    double h = first_step;
    int cuts = 0;
    while (run.time() < s.end_time) {
        check_time_limit("at time", run.time());
        const double t = run.time();
        const bool lands = t + h >= next_output - 1e-9 * h;
        const double hs = lands ? next_output - t : h;
        const double to = lands ? next_output : t + hs;
        if (control.underflow(hs)) {
            std::ostringstream m;
            m << "step size underflow at t = " << t << ": step " << hs << " below "
              << Control::kMinStep << " of the window (" << outcome.control.rejected_steps
              << " steps rejected by the error test)";
            run.fail(SolveStatus::diverged, m.str());
            return false;
        }
        if (!run.try_step(to, hs)) {
            if (!run.cut(hs, cuts)) return false;
            ++cuts;
            h = 0.5 * hs;
            continue;
        }
        cuts = 0;
        const double error = run.local_error(hs);
        double grown = Control::kMaxGrowth * hs;  // no estimate yet
        if (error >= 0.0) {
            const auto d = control.decide(control.ratio(error, hs), hs, run.iterations());
            if (!d.accept) {
                ++outcome.control.rejected_steps;
                h = d.next;
                continue;
            }
            grown = d.next;
        }
        // A step shortened to land on an output says nothing against the step before it.
        h = lands && grown >= hs ? std::max(h, grown) : grown;
        run.accept(to, hs);
        if (lands) {
            if (output) output(run.time(), run.x(), run.xdot(), run.iterations());
            outputs.advance();
            next_output = std::min(outputs.next(), s.end_time);
            if (s.end_time - run.time() <= 1e-9 * every) break;
        }
    }
    return true;
}

}  // namespace rotbeam
