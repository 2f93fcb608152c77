#include "core/generalized_alpha.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/errors.hpp"
#include "core/step_observer.hpp"
#include "core/step_size_control.hpp"
#include "core/time_limit.hpp"

namespace rotbeam {

GeneralizedAlpha GeneralizedAlpha::from_rho_infinity(double rho) {
    if (!(rho >= 0.0 && rho <= 1.0)) {
        std::ostringstream s;
        s << "analysis.rho_infinity: " << rho << " is outside [0, 1]";
        throw InputError(s.str());
    }
    GeneralizedAlpha g;
    g.alpha_m = (2.0 * rho - 1.0) / (rho + 1.0);
    g.alpha_f = rho / (rho + 1.0);
    g.gamma = 0.5 + g.alpha_f - g.alpha_m;
    g.beta = 0.25 * (g.gamma + 0.5) * (g.gamma + 0.5);
    return g;
}

double SecondOrderProblem::acceleration_change(double /*length*/) const {
    throw SolverError("this problem has no local error estimate: adaptive steps are not available");
}

bool SecondOrderProblem::energy_terms(EnergyTerms& /*terms*/) { return false; }

namespace {

// One attempt of the step t → t_next = t + h from the unchanged state n.
NewtonOutcome attempt_step(SecondOrderProblem& problem, double t_next, double h,
                           const GeneralizedAlpha& scheme, const NewtonSettings& newton,
                           NewtonWorkspace& workspace) {
    NewtonOutcome out;
    try {
        problem.begin_step(t_next, h, scheme);
        out = solve_newton(problem, newton, workspace);
    } catch (const TimeLimitReached& e) {
        rethrow_with_context(e, "in the step to time", t_next);
    } catch (const SingularityError& e) {
        out.converged = false;
        out.singular = true;
        out.failure = e.what();
    }
    return out;
}

// The run's loop state and its bookkeeping of converged, cut and rejected steps.
class Stepper {
  public:
    Stepper(SecondOrderProblem& problem, const TimeIntegrationSettings& settings,
            const NewtonSettings& newton, DynamicOutcome& outcome)
        : problem_(problem),
          settings_(settings),
          newton_(newton),
          scheme_(GeneralizedAlpha::from_rho_infinity(settings.rho_infinity)),
          outcome_(outcome),
          // One per run: buffers, the LU analysis and (KLU, refactored in place) the factors'
          // memory are reused by every step, so a step allocates nothing in the Newton driver.
          workspace_(true) {}

    const GeneralizedAlpha& scheme() const { return scheme_; }
    double time() const { return t_; }
    void start(double t) {
        t_ = t;
        balanced_ = problem_.energy_terms(terms_);
        if (balanced_) balance_.start(terms_);
    }

    // Tries the step of size h to t_next; on success it is converged but not yet accepted.
    bool try_step(double t_next, double h) {
        last_ = attempt_step(problem_, t_next, h, scheme_, newton_, workspace_);
        return last_.accepted();
    }
    // Accepts the converged step; false when the energy balance then stops the run.
    bool accept(double t_next, double h) {
        stalls_.add(last_);
        problem_.end_step();
        t_ = t_next;
        ++outcome_.steps;
        outcome_.newton_iterations += last_.iterations;
        outcome_.last_time = t_;
        outcome_.control.add_step(h, outcome_.steps == 1);
        notify_step({t_, outcome_.steps, outcome_.newton_iterations, -1});
        if (!balanced_) return true;
        problem_.energy_terms(terms_);
        if (!balance_.add(terms_, outcome_.steps, t_, h)) return true;
        fail(SolveStatus::diverged, balance_.describe(outcome_.steps, t_));
        return false;
    }
    int iterations() const { return last_.iterations; }
    // A Newton failure at the step of size h: counts a cut (returns true: retry with h/2) or, at
    // `cuts` = max_cuts, ends the run with the cause.
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
    void finish() {
        std::ostringstream s;
        s << outcome_.steps << " time steps (" << outcome_.newton_iterations
          << " Newton iterations)";
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
    SecondOrderProblem& problem_;
    const TimeIntegrationSettings& settings_;
    const NewtonSettings& newton_;
    GeneralizedAlpha scheme_;
    DynamicOutcome& outcome_;
    NewtonWorkspace workspace_;
    StallSummary stalls_;
    NewtonOutcome last_;
    double t_ = 0.0;
    bool balanced_ = false;
    EnergyTerms terms_;
    EnergyBalance balance_;
};

// Fixed steps on the grid start + n h0; a step whose Newton fails is covered by halves (then
// quarters, …) of itself, and the grid goes on unchanged.
bool run_fixed(Stepper& stepper, const TimeIntegrationSettings& settings,
               const std::function<void(const TimeStepRecord&)>& on_output) {
    const double h0 = settings.time_step;
    const double span = settings.end_time - settings.start_time;
    const long steps = std::max(1L, std::lround(std::ceil(span / h0 - 1e-9)));
    const double every = settings.output_interval > 0.0 ? settings.output_interval : h0;
    double next_output = settings.start_time + every;
    for (long n = 1; n <= steps; ++n) {
        const double t_next = n == steps ? settings.end_time : settings.start_time + n * h0;
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
        if (n == steps || t >= next_output - 1e-9 * h0) {
            if (on_output) on_output({t, stepper.iterations()});
            while (next_output <= t + 1e-9 * h0) next_output += every;
        }
    }
    return true;
}

// Adaptive steps (core/step_size_control.hpp) with the local error estimate of
// GeneralizedAlpha::local_error_coefficient; steps are shortened to land on the output times.
bool run_adaptive(Stepper& stepper, SecondOrderProblem& problem,
                  const TimeIntegrationSettings& settings,
                  const std::function<void(const TimeStepRecord&)>& on_output,
                  DynamicOutcome& outcome) {
    const StepSizeControl control{settings.tolerance, settings.end_time - settings.start_time};
    const double c = std::abs(stepper.scheme().local_error_coefficient());
    const double every =
        settings.output_interval > 0.0 ? settings.output_interval : settings.time_step;
    double next_output = std::min(settings.start_time + every, settings.end_time);
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
        const double error = c * hs * hs * problem.acceleration_change(settings.length_scale);
        const double r = control.ratio(error, hs);
        if (r > 1.0) {
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
            next_output = std::min(next_output + every, settings.end_time);
            if (settings.end_time - stepper.time() <= 1e-9 * every) break;
        }
    }
    return true;
}

}  // namespace

DynamicOutcome run_generalized_alpha(SecondOrderProblem& problem,
                                     const TimeIntegrationSettings& settings,
                                     const NewtonSettings& newton,
                                     const std::function<void(const TimeStepRecord&)>& on_output) {
    DynamicOutcome outcome;
    const double h0 = settings.time_step;
    if (!(h0 > 0.0) || !(settings.end_time > settings.start_time)) {
        throw InputError("analysis: a dynamic analysis needs time_step > 0 and end_time > 0");
    }
    Stepper stepper(problem, settings, newton, outcome);
    // The consistent acceleration belongs to the motion on (t_0, t_1]: loads are taken at the right
    // limit t_0 + 1e-6 h. For continuous time functions this changes v˙_0 by O(1e-6 h ḟ), far below
    // the scheme's O(h²); for a load released at t_0 (docs/benchmarks.md §8: a table dropping to 0
    // within 1e-12 s) it gives the acceleration of the free motion, as a second-order start needs.
    constexpr double kRightLimit = 1e-6;
    problem.initialize_acceleration(settings.start_time + kRightLimit * h0);
    if (on_output) on_output({settings.start_time, 0});
    stepper.start(settings.start_time);
    outcome.last_time = settings.start_time;
    const bool done = settings.tolerance > 0.0
                          ? run_adaptive(stepper, problem, settings, on_output, outcome)
                          : run_fixed(stepper, settings, on_output);
    if (done) stepper.finish();
    return outcome;
}

}  // namespace rotbeam
