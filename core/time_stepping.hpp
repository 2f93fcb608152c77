// The step loop shared by the displacement formulation's time integrators (generalized-α,
// core/generalized_alpha.hpp; Gauss–Legendre collocation, core/gauss_collocation.hpp): fixed steps
// on a grid or adaptive steps (core/step_size_control.hpp), the step cut to h/2 after a failed
// step, the energy balance (core/energy_balance.hpp) after every accepted step, and the run's
// message. A scheme supplies only its step: an attempt from the accepted state, its acceptance,
// and (adaptive) its local error estimate.
#pragma once

#include <functional>
#include <string>

#include "core/errors.hpp"
#include "core/generalized_alpha.hpp"
#include "core/time_limit.hpp"

namespace rotbeam {

// One scheme's step, as the loop drives it.
class StepScheme {
  public:
    virtual ~StepScheme() = default;
    // Tries the step t → t_next = t + h (t_next exactly as the loop's grid has it) from the
    // accepted state at t, which a failed attempt leaves unchanged; a converged attempt is not
    // accepted yet. SingularityError is caught by the loop (guarded_attempt) and reported as a
    // singular step.
    virtual NewtonOutcome attempt(double t, double t_next, double h) = 0;
    // Accepts the converged attempt; returns the number of time steps it consists of (1, or 2 for
    // a step-doubling pair).
    virtual int accept() = 0;
    // Adaptive steps, after a converged attempt: its scaled local error estimate (translations
    // divided by the length scale, rotations in rad), and `reject()` to return to the accepted
    // state at t when the loop refuses it.
    virtual double local_error(double h) = 0;
    virtual void reject() {}
    // The exponent q of the local error C h^q (3 for second-order schemes).
    virtual int local_error_order() const = 0;
};

// The labels of a run's message: "N time steps[, scheme] (M iterations)".
struct StepLoopLabels {
    std::string scheme;                            // e.g. "Gauss–Legendre 2 stages", or empty
    std::string iterations = "Newton iterations";  // what the iteration count counts
};

// InputError unless settings.time_step > 0 and settings.end_time > settings.start_time.
inline void require_time_window(const TimeIntegrationSettings& settings) {
    if (!(settings.time_step > 0.0) || !(settings.end_time > settings.start_time)) {
        throw InputError("analysis: a dynamic analysis needs time_step > 0 and end_time > 0");
    }
}

// `attempt()` with a parameterization's refusal (SingularityError) turned into a singular outcome
// and the time limit given the step's end time. A template, not a std::function: a step allocates
// nothing (test_displacement_allocation).
template <class Attempt>
NewtonOutcome guarded_attempt(double t_next, Attempt&& attempt) {
    NewtonOutcome out;
    try {
        out = attempt();
    } catch (const TimeLimitReached& e) {
        rethrow_with_context(e, "in the step to time", t_next);
    } catch (const SingularityError& e) {
        out.converged = false;
        out.singular = true;
        out.failure = e.what();
    }
    return out;
}

// Runs `scheme` from settings.start_time (the problem at its initial state, its acceleration set)
// to settings.end_time as run_generalized_alpha documents (core/generalized_alpha.hpp): outputs,
// cuts, adaptive steps, energy balance and the outcome's message. The initial output is the
// caller's.
DynamicOutcome run_step_loop(StepScheme& scheme, SecondOrderProblem& problem,
                             const TimeIntegrationSettings& settings, const NewtonSettings& newton,
                             const StepLoopLabels& labels,
                             const std::function<void(const TimeStepRecord&)>& on_output);

}  // namespace rotbeam
