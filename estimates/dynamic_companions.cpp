#include "estimates/dynamic_companions.hpp"

#include <cmath>
#include <sstream>

#include "cases/loader/limits.hpp"

namespace rotbeam::estimate {

namespace {

bool uses_ida(const Model& model) {
    return model.discretization.formulation == Formulation::mixed &&
           model.analysis.dynamics.integrator == Integrator::ida;
}

}  // namespace

DynamicPlan plan_dynamic_companions(const Model& model) {
    DynamicPlan plan;
    plan.space = plan_space_companions(model);
    const DynamicSettings& d = model.analysis.dynamics;
    Model companion = model;
    DynamicSettings& c = companion.analysis.dynamics;
    if (c.output_interval <= 0.0) c.output_interval = d.time_step;
    if (uses_ida(model) || d.time_tolerance > 0.0) {
        // BDF with a local error test per step: the global error is proportional to the tolerance
        // (Hairer, Nørsett & Wanner, tolerance proportionality), so the ratio 4 gives the same
        // Richardson factor 1/(1 − 1/4) as halving a second-order step. Adaptive steps
        // (core/step_size_control.hpp): the step that meets a local error C h^(p+1) ≤ τ h / T is
        // h ∝ τ^(1/p), so the global error ∝ h^p ∝ τ (order 1 in τ) for every scheme order p; for
        // the second-order schemes τ/4 halves every step (the adaptive run's Δt/2 companion), for
        // Gauss–Legendre s it shortens them by 4^(1/2s).
        plan.time_method = "tolerance/4";
        plan.time_order = 1.0;
        plan.time_ratio = 4.0;
        c.relative_tolerance = d.relative_tolerance / plan.time_ratio;
        c.absolute_tolerance = d.absolute_tolerance / plan.time_ratio;
        c.time_tolerance = d.time_tolerance / plan.time_ratio;
        // Adaptive steps land on the output times (core/time_stepping.cpp), so no step is longer
        // than the output interval. Where a loose tolerance leaves the run's steps at that cap, a
        // companion capped alike would take the very same steps, and the difference, hence the
        // time estimate, would be zero whatever the true time error. The companion's outputs
        // come twice as often (the run's output times among them): its cap is half the run's, so
        // it refines every step, capped or not. At a capped step its error falls by 2^p instead
        // of 4, so the factor above overstates the error there by at most 4/3 (safe side).
        if (!uses_ida(model)) c.output_interval *= 0.5;
        plan.time.push_back({"tolerance/4", std::move(companion)});
        return plan;
    }
    const bool finer = model.analysis.estimate_companions == CompanionSide::finer;
    plan.time_method = finer ? "dt/2" : "2dt";
    // Generalized-α and the mixed trapezoidal scheme are second order; Gauss–Legendre
    // collocation with s stages is of order 2s (core/gauss_collocation.hpp). Radau IIA with 3
    // stages is of order 5, but the histories' observed order falls to 1–3.5 at practical steps
    // wherever the load excites the stiff modes, which it damps (docs/mixed-dynamics.md "Radau
    // IIA": the joined beam, a cantilever driven from rest): the factor assumes order 1, at most
    // 2× pessimistic where order 5 holds and never optimistic while the observed order is ≥ 1.
    // Stiff modes damped by both runs are not seen by the companion at all (same document).
    switch (model.analysis.dynamics.integrator) {
        case Integrator::gauss_legendre_2:
            plan.time_order = 4.0;
            break;
        case Integrator::gauss_legendre_3:
            plan.time_order = 6.0;
            break;
        case Integrator::radau_iia_3:
            plan.time_order = 1.0;
            break;
        default:
            plan.time_order = 2.0;
            break;
    }
    plan.time_ratio = finer ? 2.0 : 0.5;
    c.time_step = d.time_step / plan.time_ratio;
    if (d.end_time / c.time_step > cases::kMaxTimeSteps) {
        plan.time_refusal = "the dt/2 companion would exceed the largest number of time steps, " +
                            std::to_string(static_cast<long>(cases::kMaxTimeSteps));
        return plan;
    }
    if (!finer) {
        // A fixed-step run writes an output at the first step that reaches its output time: the
        // 2dt companion reaches the run's output times only when they are multiples of 2 dt.
        const double every = c.output_interval / c.time_step;
        if (std::abs(every - std::round(every)) > 1e-9 * every) {
            std::ostringstream why;
            why << "the 2dt companion (dt = " << c.time_step
                << ") does not step onto the run's output times every " << c.output_interval
                << " (analysis.output_interval must be a multiple of 2 dt)";
            plan.time_refusal = why.str();
            return plan;
        }
    }
    plan.time.push_back({plan.time_method, std::move(companion)});
    return plan;
}

}  // namespace rotbeam::estimate
