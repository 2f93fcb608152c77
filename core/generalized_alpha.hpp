// Generalized-α time integration on a Lie group (Brüls, Cardona & Arnold 2012, "Lie group
// generalized-α time integration of constrained flexible multibody systems", Mech. Mach. Theory
// 48), with the Chung–Hulbert parameters from the spectral radius at infinity ρ∞ (Chung & Hulbert
// 1993):
//   α_m = (2ρ∞ − 1)/(ρ∞ + 1),  α_f = ρ∞/(ρ∞ + 1),  γ = ½ + α_f − α_m,  β = ¼ (γ + ½)².
// One step n → n+1 of size h, for the configuration q, the velocity v (spatial), the true
// acceleration v˙ and the pseudo-acceleration a (BCA Eqs. 15–18, written with the increment
// Δ = h Δq of the configuration):
//   q_{n+1} = exp(Δ) ∘ q_n                     (the problem's composition; spatial: on the left)
//   Δ       = h v_n + h² (½ − β) a_n + h² β a_{n+1}
//   v_{n+1} = v_n + h (1 − γ) a_n + h γ a_{n+1}
//   (1 − α_m) a_{n+1} + α_m a_n = (1 − α_f) v˙_{n+1} + α_f v˙_n
//   r(q_{n+1}, v_{n+1}, v˙_{n+1}, t_{n+1}) = 0.
// The Newton unknown is Δ; v_{n+1} and v˙_{n+1} are affine in it with slopes
//   ∂v/∂Δ = γ/(β h),   ∂v˙/∂Δ = (1 − α_m)/((1 − α_f) β h²),
// and the iteration matrix is ∂r/∂q T(Δ) + γ/(β h) ∂r/∂v + (1 − α_m)/((1 − α_f) β h²) ∂r/∂v˙, with
// T the tangent of the exponential (BCA's T(hΔq)). Second order for every ρ∞ ∈ [0, 1] when a_0 =
// v˙_0 is consistent (M v˙_0 = −r(q_0, v_0, v˙ = 0, t_0)); ρ∞ = 1 is the trapezoidal rule (no
// numerical dissipation).
//
// This file knows nothing of the formulation: a SecondOrderProblem is a NonlinearSystem whose
// unknowns are the step increment Δ, plus the calls below. The per-step Newton is the shared
// solve_newton (core/static_driver.hpp), with the same settings and reporting as statics, and a
// NewtonWorkspace kept for the run (KLU refactored in place: no allocation per step).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "core/energy_balance.hpp"
#include "core/nonlinear_system.hpp"
#include "core/static_driver.hpp"
#include "core/step_size_control.hpp"

namespace rotbeam {

struct GeneralizedAlpha {
    double alpha_m = 0.5, alpha_f = 0.5, gamma = 0.5, beta = 0.25;
    // Chung–Hulbert parameters; throws InputError unless 0 ≤ ρ∞ ≤ 1.
    static GeneralizedAlpha from_rho_infinity(double rho_infinity);
    double velocity_slope(double h) const { return gamma / (beta * h); }
    double acceleration_slope(double h) const {
        return (1.0 - alpha_m) / ((1.0 - alpha_f) * beta * h * h);
    }
    // The local error of the configuration update, c h² (a_{n+1} − a_n) (Zienkiewicz & Xie 1991,
    // "A simple error estimator and adaptive time stepping procedure for dynamic analysis",
    // Earthquake Eng. Struct. Dyn. 20, Eq. 9: (β − 1/6) h² (ü_{n+1} − ü_n) for Newmark). Here a is
    // the pseudo-acceleration, a_n ≈ v˙(t_n + δh) with δ = α_m − α_f = ½ − γ (second-order
    // consistency), so Δ = h v_n + h² (½ − β) a_n + h² β a_{n+1} = h v + h²/2 v˙ + h³ (β + δ/2) v⃛
    // against the exact h v + h²/2 v˙ + h³/6 v⃛: c = β − γ/2 + 1/12, and a_{n+1} − a_n ≈ h v⃛.
    // ρ∞ = 1 (β = ¼, γ = ½): c = 1/12, the trapezoidal rule's; ρ∞ = 0.5: 1/9.
    double local_error_coefficient() const { return beta - 0.5 * gamma + 1.0 / 12.0; }
};

// A second-order system driven by the integrator. Its NonlinearSystem unknowns are the increment
// Δ of the current step (retract adds to it); evaluate returns r(q_{n+1}(Δ), v_{n+1}(Δ),
// v˙_{n+1}(Δ), t_{n+1}) and the iteration matrix above.
class SecondOrderProblem : public NonlinearSystem {
  public:
    // At the initial state (q_0, v_0): v˙_0 = a_0 from M v˙_0 = −r(q_0, v_0, 0, t), loads at t.
    // Throws SolverError when M is singular.
    virtual void initialize_acceleration(double t) = 0;
    // Start the step to t_next = t_n + h: predict Δ, set the loads at t_next.
    virtual void begin_step(double t_next, double h, const GeneralizedAlpha& scheme) = 0;
    // Accept the converged step: q_n, v_n, v˙_n, a_n ← the values at n+1.
    virtual void end_step() = 0;
    // For adaptive steps, after a converged step (before end_step): max over the nodes of
    // |a_{n+1} − a_n| of the pseudo-accelerations, translations divided by `length`, rotations
    // in rad. A problem without it cannot run with adaptive steps (SolverError).
    virtual double acceleration_change(double length) const;
    // For the energy balance (core/energy_balance.hpp), at the current state: kinetic + strain
    // energy, external loads and velocity, damping power. False (the default) when the problem
    // cannot give them: its runs have no energy check.
    virtual bool energy_terms(EnergyTerms& terms);
};

struct TimeIntegrationSettings {
    double time_step = 0.0;
    double start_time = 0.0;
    double end_time = 0.0;
    double output_interval = 0.0;  // 0: every step
    double rho_infinity = 1.0;
    // Adaptive steps when > 0 (core/step_size_control.hpp): the tolerance on the global error of
    // the configuration over the window, translations divided by length_scale, rotations in rad.
    // time_step is then the first step's size. Outputs land exactly on the output times.
    double tolerance = 0.0;
    double length_scale = 1.0;
    // A step whose Newton fails is retried with h/2, at most max_cuts times in a row (0: off).
    int max_cuts = kDynamicStepCuts;
};

struct TimeStepRecord {
    double time = 0.0;
    int newton_iterations = 0;  // of the step that reached `time` (0 at the initial state)
};

struct DynamicOutcome {
    SolveStatus status = SolveStatus::converged;
    std::string message;
    int steps = 0;  // converged steps
    long newton_iterations = 0;
    double last_time = 0.0;  // the state the problem is left in
    StepControlRecord control;
};

// Fixed steps from start_time to end_time (the last step lands on end_time), or adaptive steps
// (settings.tolerance > 0). `on_output` is called at the initial state and every output_interval
// (and at end_time), the problem being at that state; adaptive steps with output_interval 0 output
// every time_step. A step whose Newton fails is retried with h/2 from the unchanged state n (the
// problem's begin_step again), up to max_cuts times in a row; a fixed-step run then continues on
// its grid (the cut step's remainder in halves), says so in `step_cuts` and its message, and
// produces exactly the results of the uncut run when nothing is cut. Past max_cuts the run ends
// with status diverged or singular, the step, time, step size and Newton's failure in the message.
// When the problem gives energy_terms, the energy balance is checked after every accepted step;
// energy growth (core/energy_balance.hpp) ends the run with status diverged and a message naming
// it, the step and time where it was detected and where it started.
DynamicOutcome run_generalized_alpha(SecondOrderProblem& problem,
                                     const TimeIntegrationSettings& settings,
                                     const NewtonSettings& newton,
                                     const std::function<void(const TimeStepRecord&)>& on_output);

}  // namespace rotbeam
