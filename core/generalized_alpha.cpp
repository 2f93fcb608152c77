#include "core/generalized_alpha.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/errors.hpp"
#include "core/time_stepping.hpp"

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

// The generalized-α step for the shared loop (core/time_stepping.hpp): one Newton solve per
// attempt, with a NewtonWorkspace kept for the run (buffers, the LU analysis and, KLU refactored in
// place, the factors' memory are reused by every step: a step allocates nothing in the Newton
// driver).
class AlphaScheme : public StepScheme {
  public:
    AlphaScheme(SecondOrderProblem& problem, const TimeIntegrationSettings& settings,
                const NewtonSettings& newton)
        : problem_(problem),
          newton_(newton),
          scheme_(GeneralizedAlpha::from_rho_infinity(settings.rho_infinity)),
          length_(settings.length_scale),
          workspace_(true) {}

    NewtonOutcome attempt(double /*t*/, double t_next, double h) override {
        problem_.begin_step(t_next, h, scheme_);
        return solve_newton(problem_, newton_, workspace_);
    }
    int accept() override {
        problem_.end_step();
        return 1;
    }
    // GeneralizedAlpha::local_error_coefficient's c h² |a_{n+1} − a_n|.
    double local_error(double h) override {
        return std::abs(scheme_.local_error_coefficient()) * h * h *
               problem_.acceleration_change(length_);
    }
    int local_error_order() const override { return 3; }

  private:
    SecondOrderProblem& problem_;
    const NewtonSettings& newton_;
    GeneralizedAlpha scheme_;
    double length_;
    NewtonWorkspace workspace_;
};

}  // namespace

DynamicOutcome run_generalized_alpha(SecondOrderProblem& problem,
                                     const TimeIntegrationSettings& settings,
                                     const NewtonSettings& newton,
                                     const std::function<void(const TimeStepRecord&)>& on_output) {
    require_time_window(settings);
    const double h0 = settings.time_step;
    AlphaScheme scheme(problem, settings, newton);
    // The consistent acceleration belongs to the motion on (t_0, t_1]: loads are taken at the right
    // limit t_0 + 1e-6 h. For continuous time functions this changes v˙_0 by O(1e-6 h ḟ), far below
    // the scheme's O(h²); for a load released at t_0 (docs/benchmarks.md §8: a table dropping to 0
    // within 1e-12 s) it gives the acceleration of the free motion, as a second-order start needs.
    constexpr double kRightLimit = 1e-6;
    problem.initialize_acceleration(settings.start_time + kRightLimit * h0);
    if (on_output) on_output({settings.start_time, 0});
    return run_step_loop(scheme, problem, settings, newton, {}, on_output);
}

}  // namespace rotbeam
