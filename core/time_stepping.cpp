#include "core/time_stepping.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/errors.hpp"
#include "core/output_times.hpp"
#include "core/step_observer.hpp"
#include "core/step_size_control.hpp"
#include "core/time_limit.hpp"

namespace rotbeam {

namespace {

// The run's loop state and its bookkeeping of converged, cut and rejected steps.
class Stepper {
  public:
    Stepper(StepScheme& scheme, SecondOrderProblem& problem,
            const TimeIntegrationSettings& settings, const NewtonSettings& newton,
            DynamicOutcome& outcome)
        : scheme_(scheme),
          problem_(problem),
          settings_(settings),
          newton_(newton),
          outcome_(outcome) {}

    double time() const { return t_; }
    void start(double t) {
        t_ = t;
        balanced_ = problem_.energy_terms(terms_);
        if (balanced_) balance_.start(terms_);
    }

    // Tries the step of size h to t_next; on success it is converged but not yet accepted.
    bool try_step(double t_next, double h) {
        last_ = guarded_attempt(t_next, [&] { return scheme_.attempt(t_, t_next, h); });
        return last_.accepted();
    }
    double local_error(double h) { return scheme_.local_error(h); }
    void reject() { scheme_.reject(); }
    // Accepts the converged step; false when the energy balance then stops the run.
    bool accept(double t_next, double h) {
        stalls_.add(last_);
        const int k = scheme_.accept();
        t_ = t_next;
        for (int i = 0; i < k; ++i) {
            ++outcome_.steps;
            outcome_.control.add_step(h / k, outcome_.steps == 1);
        }
        outcome_.newton_iterations += last_.iterations;
        outcome_.last_time = t_;
        notify_step({t_, outcome_.steps, outcome_.newton_iterations, -1});
        if (!balanced_) return true;
        problem_.energy_terms(terms_);
        if (!balance_.add(terms_, outcome_.steps, t_, h)) return true;
        fail(SolveStatus::diverged, balance_.describe(outcome_.steps, t_));
        return false;
    }
    int iterations() const { return last_.iterations; }
    // A failed step of size h: counts a cut (returns true: retry with h/2) or, at `cuts` =
    // max_cuts, ends the run with the cause.
    bool cut(double h, int cuts) {
        if (cuts < settings_.max_cuts) {
            if (outcome_.control.step_cuts == 0) outcome_.control.first_cut_time = t_;
            ++outcome_.control.step_cuts;
            return true;
        }
        std::ostringstream s;
        s.precision(9);
        s << (last_.singular ? "singular" : "diverged") << " at time step " << outcome_.steps + 1
          << " (t = " << t_ + h << ", from t = " << t_ << " with step " << h;
        if (cuts > 0) s << " after " << cuts << " cuts to h/2";
        s << "): " << last_.failure;
        const std::string state = problem_.describe_state();
        if (!state.empty()) s << "; " << state;
        fail(last_.singular ? SolveStatus::singular : SolveStatus::diverged, s.str());
        return false;
    }
    void fail(SolveStatus status, const std::string& message) {
        outcome_.status = status;
        outcome_.message = message;
        outcome_.last_time = t_;
    }
    void finish(const StepLoopLabels& labels) {
        std::ostringstream s;
        s << outcome_.steps << " time steps";
        if (!labels.scheme.empty()) s << ", " << labels.scheme;
        s << " (" << outcome_.newton_iterations << " " << labels.iterations << ")";
        if (settings_.tolerance > 0.0) {
            s.precision(3);
            s << "; adaptive, tolerance " << settings_.tolerance << ", steps "
              << outcome_.control.smallest_step << " … " << outcome_.control.largest_step << ", "
              << outcome_.control.rejected_steps << " rejected";
        }
        if (outcome_.control.step_cuts > 0) {
            s.precision(9);
            s << "; " << outcome_.control.step_cuts
              << " steps cut to h/2 after a Newton failure (first from t = "
              << outcome_.control.first_cut_time << ")";
        }
        if (stalls_.count > 0) {
            outcome_.status = SolveStatus::stalled_at_round_off;
            s << "; " << stalls_.describe("time steps", newton_.residual_tolerance);
        }
        outcome_.message = s.str();
    }

  private:
    StepScheme& scheme_;
    SecondOrderProblem& problem_;
    const TimeIntegrationSettings& settings_;
    const NewtonSettings& newton_;
    DynamicOutcome& outcome_;
    StallSummary stalls_;
    NewtonOutcome last_;
    double t_ = 0.0;
    bool balanced_ = false;
    EnergyTerms terms_;
    EnergyBalance balance_;
};

// Fixed steps on the grid start + n h0; a step that fails is covered by halves (then quarters, …)
// of itself, and the grid goes on unchanged.
bool run_fixed(Stepper& stepper, const TimeIntegrationSettings& settings,
               const std::function<void(const TimeStepRecord&)>& on_output) {
    const double h0 = settings.time_step;
    const double span = settings.end_time - settings.start_time;
    const long steps = std::max(1L, std::lround(std::ceil(span / h0 - 1e-9)));
    const double every = settings.output_interval > 0.0 ? settings.output_interval : h0;
    OutputTimes outputs(settings.start_time, every);
    for (long n = 1; n <= steps; ++n) {
        const double t_next =
            n == steps ? settings.end_time : settings.start_time + static_cast<double>(n) * h0;
        const double h = t_next - stepper.time();
        check_time_limit("at time", stepper.time());
        int cuts = 0;
        while (true) {
            // The remainder of the grid step in pieces of h / 2^cuts, the last landing on t_next.
            const double piece = std::ldexp(h, -cuts);
            const bool last = stepper.time() + piece >= t_next - 1e-9 * piece;
            const double hs = last ? t_next - stepper.time() : piece;
            const double to = last ? t_next : stepper.time() + hs;
            if (!stepper.try_step(to, hs)) {
                if (!stepper.cut(hs, cuts)) return false;
                ++cuts;
                continue;
            }
            if (!stepper.accept(to, hs)) return false;
            if (last) break;
        }
        const double t = stepper.time();
        if (outputs.due(t, 1e-9 * h0) || n == steps) {
            if (on_output) on_output({t, stepper.iterations()});
        }
    }
    return true;
}

// Adaptive steps (core/step_size_control.hpp) with the scheme's local error estimate; steps are
// shortened to land on the output times.
bool run_adaptive(Stepper& stepper, int error_order, const TimeIntegrationSettings& settings,
                  const std::function<void(const TimeStepRecord&)>& on_output,
                  DynamicOutcome& outcome) {
    const StepSizeControl control{settings.tolerance, settings.end_time - settings.start_time,
                                  error_order};
    const double every =
        settings.output_interval > 0.0 ? settings.output_interval : settings.time_step;
    OutputTimes outputs(settings.start_time, every);
    double next_output = std::min(outputs.next(), settings.end_time);
    double h = settings.time_step;
    int cuts = 0;
    while (stepper.time() < settings.end_time) {
        check_time_limit("at time", stepper.time());
        const double t = stepper.time();
        const bool lands = t + h >= next_output - 1e-9 * h;
        const double hs = lands ? next_output - t : h;
        const double to = lands ? next_output : t + hs;
        if (control.underflow(hs)) {
            std::ostringstream s;
            s.precision(9);
            s << "step size underflow at t = " << t << ": step " << hs << " below "
              << StepSizeControl::kMinStep << " of the window (" << outcome.control.rejected_steps
              << " steps rejected by the error test)";
            stepper.fail(SolveStatus::diverged, s.str());
            return false;
        }
        if (!stepper.try_step(to, hs)) {
            if (!stepper.cut(hs, cuts)) return false;
            ++cuts;
            h = 0.5 * hs;
            continue;
        }
        cuts = 0;
        const double r = control.ratio(stepper.local_error(hs), hs);
        if (r > 1.0) {
            stepper.reject();
            ++outcome.control.rejected_steps;
            h = control.next(hs, r);
            continue;
        }
        const double grown = control.next(hs, r);
        // A step shortened to land on an output says nothing against the step before it.
        h = lands && grown >= hs ? std::max(h, grown) : grown;
        if (!stepper.accept(to, hs)) return false;
        if (lands) {
            if (on_output) on_output({stepper.time(), stepper.iterations()});
            outputs.advance();
            next_output = std::min(outputs.next(), settings.end_time);
            if (settings.end_time - stepper.time() <= 1e-9 * every) break;
        }
    }
    return true;
}

}  // namespace

DynamicOutcome run_step_loop(StepScheme& scheme, SecondOrderProblem& problem,
                             const TimeIntegrationSettings& settings, const NewtonSettings& newton,
                             const StepLoopLabels& labels,
                             const std::function<void(const TimeStepRecord&)>& on_output) {
    DynamicOutcome outcome;
    Stepper stepper(scheme, problem, settings, newton, outcome);
    stepper.start(settings.start_time);
    outcome.last_time = settings.start_time;
    const bool done = settings.tolerance > 0.0 ? run_adaptive(stepper, scheme.local_error_order(),
                                                              settings, on_output, outcome)
                                               : run_fixed(stepper, settings, on_output);
    if (done) stepper.finish(labels);
    return outcome;
}

}  // namespace rotbeam
