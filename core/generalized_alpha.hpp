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

#include "core/nonlinear_system.hpp"
#include "core/static_driver.hpp"

namespace rotbeam {

struct GeneralizedAlpha {
    double alpha_m = 0.5, alpha_f = 0.5, gamma = 0.5, beta = 0.25;
    // Chung–Hulbert parameters; throws InputError unless 0 ≤ ρ∞ ≤ 1.
    static GeneralizedAlpha from_rho_infinity(double rho_infinity);
    double velocity_slope(double h) const { return gamma / (beta * h); }
    double acceleration_slope(double h) const {
        return (1.0 - alpha_m) / ((1.0 - alpha_f) * beta * h * h);
    }
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
};

struct TimeIntegrationSettings {
    double time_step = 0.0;
    double start_time = 0.0;
    double end_time = 0.0;
    double output_interval = 0.0;  // 0: every step
    double rho_infinity = 1.0;
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
};

// Fixed steps from start_time to end_time (the last step lands on end_time). `on_output` is
// called at the initial state and every output_interval (and at end_time), the problem being at
// that state. A step whose Newton fails ends the run with status diverged or singular, the time
// and step in the message (no step cutting: the step size is part of what is studied).
DynamicOutcome run_generalized_alpha(SecondOrderProblem& problem,
                                     const TimeIntegrationSettings& settings,
                                     const NewtonSettings& newton,
                                     const std::function<void(const TimeStepRecord&)>& on_output);

}  // namespace rotbeam
