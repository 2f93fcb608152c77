#include "core/generalized_alpha.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/errors.hpp"
#include "core/step_observer.hpp"
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

namespace {

std::string step_failure(const char* what, int step, double t, const NewtonOutcome& out,
                         const NonlinearSystem& problem) {
    std::ostringstream s;
    s.precision(9);
    s << what << " at time step " << step << " (t = " << t << "): " << out.failure;
    const std::string state = problem.describe_state();
    if (!state.empty()) s << "; " << state;
    return s.str();
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
    const GeneralizedAlpha scheme = GeneralizedAlpha::from_rho_infinity(settings.rho_infinity);
    // The consistent acceleration belongs to the motion on (t_0, t_1]: loads are taken at the right
    // limit t_0 + 1e-6 h. For continuous time functions this changes v˙_0 by O(1e-6 h ḟ), far below
    // the scheme's O(h²); for a load released at t_0 (docs/benchmarks.md §8: a table dropping to 0
    // within 1e-12 s) it gives the acceleration of the free motion, as a second-order start needs.
    constexpr double kRightLimit = 1e-6;
    problem.initialize_acceleration(settings.start_time + kRightLimit * h0);
    const double span = settings.end_time - settings.start_time;
    const long steps = std::max(1L, std::lround(std::ceil(span / h0 - 1e-9)));
    const double every = settings.output_interval > 0.0 ? settings.output_interval : h0;
    double next_output = settings.start_time + every;
    if (on_output) on_output({settings.start_time, 0});
    double t = settings.start_time;
    // One per run: buffers, the LU analysis and (KLU, refactored in place) the factors' memory are
    // reused by every step, so a step allocates nothing in the Newton driver.
    NewtonWorkspace workspace(true);
    StallSummary stalls;
    for (long n = 1; n <= steps; ++n) {
        const double t_next = n == steps ? settings.end_time : settings.start_time + n * h0;
        const double h = t_next - t;
        check_time_limit("at time", t);
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
        if (!out.accepted()) {
            outcome.status = out.singular ? SolveStatus::singular : SolveStatus::diverged;
            outcome.message = step_failure(out.singular ? "singular" : "diverged",
                                           static_cast<int>(n), t_next, out, problem);
            outcome.last_time = t;
            return outcome;
        }
        stalls.add(out);
        problem.end_step();
        t = t_next;
        ++outcome.steps;
        outcome.newton_iterations += out.iterations;
        outcome.last_time = t;
        if (n == steps || t >= next_output - 1e-9 * h0) {
            if (on_output) on_output({t, out.iterations});
            while (next_output <= t + 1e-9 * h0) next_output += every;
        }
        notify_step({t, outcome.steps, outcome.newton_iterations, -1});
    }
    std::ostringstream s;
    s << outcome.steps << " time steps (" << outcome.newton_iterations << " Newton iterations)";
    if (stalls.count > 0) {
        outcome.status = SolveStatus::stalled_at_round_off;
        s << "; " << stalls.describe("time steps", newton.residual_tolerance);
    }
    outcome.message = s.str();
    return outcome;
}

}  // namespace rotbeam
