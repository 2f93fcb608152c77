// Step-size control shared by the adaptive time integrators (generalized-α,
// core/generalized_alpha.hpp; the trapezoidal DAE scheme, core/dae_driver.hpp; Radau IIA,
// core/dae_radau.hpp), and the step cut on a Newton failure that every fixed-step run has too.
//
// Error per unit step (Hairer, Nørsett & Wanner, "Solving ODEs I", §II.4, and Shampine's
// "error per unit step"): a step of size h is accepted when its local error estimate e (scaled:
// translations by a length, rotations in rad, other unknowns by their state scale) is at most
//     τ h / T,
// τ the tolerance on the GLOBAL error over the window of length T. For a stable undamped system
// local errors propagate without growth (each mode is a rotation in its phase plane), so the
// global error is at most their sum, Σ e ≤ τ Σ h / T = τ; the Δt/2 companion of the run checks
// the global error afterwards (docs/error-estimates.md, Dynamics).
// A scheme of order p has local error C h^(p+1) (q = p + 1: 3 for generalized-α and the
// trapezoidal rule, 2s + 1 for s-stage Gauss–Legendre). The ratio r = e / (τ h / T) then scales as
// h^(q−1), so the step that makes r = 1 is h r^(−1/(q−1)); it is taken with a safety factor and
// bounded growth and shrink per step. The step count over the window then scales as τ^(−1/(q−1)):
// τ/4 doubles it for a second-order scheme, τ/16 for a fourth-order one.
#pragma once

#include <algorithm>
#include <cmath>

namespace rotbeam {

// A Newton failure at a step retries it with h/2, at most this many times in a row (h/1024):
// below that the step is not what stops Newton (a chart at its singular angle, a load the beam
// cannot carry), and the run stops with the cause.
inline constexpr int kDynamicStepCuts = 10;

// What a run's step control did (reported only when it did something: adaptive steps or a cut).
struct StepControlRecord {
    int step_cuts = 0;  // Newton failures recovered by halving the step
    double first_cut_time = 0.0;
    int rejected_steps = 0;    // adaptive: steps whose local error exceeded the allowance
    int matrix_refreshes = 0;  // Gauss: steps passed after refreshing the stage iteration matrix
    double smallest_step = 0.0, largest_step = 0.0;  // of the converged steps
    void add_step(double h, bool first) {
        smallest_step = first ? h : std::min(smallest_step, h);
        largest_step = std::max(largest_step, h);
    }
};

struct StepSizeControl {
    double tolerance = 0.0;  // τ: the global error allowed over the window (scaled)
    double span = 1.0;       // T
    int order = 3;           // q: the local error is C h^q

    static constexpr double kSafety = 0.9;     // aim at 0.9² of the allowed error
    static constexpr double kMaxGrowth = 2.0;  // per accepted step
    static constexpr double kMaxShrink = 0.2;  // per rejected step
    // A step below this fraction of the window is a step-size underflow: the run stops.
    static constexpr double kMinStep = 1e-12;

    // e / (τ h / T): ≤ 1 accepts the step.
    double ratio(double error, double h) const { return error / (tolerance * h / span); }
    // The next step after a step h with ratio r (local error ∝ h^q against an allowance ∝ h).
    double next(double h, double r) const {
        const double f =
            r > 0.0 ? kSafety / (order == 3 ? std::sqrt(r) : std::pow(r, 1.0 / (order - 1)))
                    : kMaxGrowth;
        return h * std::clamp(f, kMaxShrink, r > 1.0 ? kSafety : kMaxGrowth);
    }
    bool underflow(double h) const { return h < kMinStep * span; }

    // The adaptive loop's interface (run_adaptive_steps, core/dae_fixed_steps.hpp): a converged
    // step h with ratio r is accepted when r ≤ 1; `next` is the step to try after it. The
    // stage/Newton iterations of the attempt are not used by this control.
    struct Decision {
        bool accept = false;
        double next = 0.0;
    };
    Decision decide(double r, double h, int /*iterations*/) { return {r <= 1.0, next(h, r)}; }
};

// The step-size control of the Radau IIA scheme: the standard proposal on the same
// error-per-unit-step ratio, with two parts of Hairer & Wanner's RADAU5 (Solving ODEs II, §IV.8,
// "Step size selection", and the code's defaults):
//  - the factor limited to [1/5, 8] after an accepted step (RADAU5's FACL, FACR), below 0.9 after
//    a rejection;
//  - a proposed factor within [1, 1.2] keeps h: the stage matrices of the same h are reused
//    (core/dae_radau.cpp) and a growth that small does not pay for a fresh factorization.
// Measured on the released free-vibration cantilever (docs/mixed-dynamics.md "Radau IIA",
// adaptive steps) and left out because they cost steps there: RADAU5's safety factor falling
// with the stage iterations, 0.9 (1 + 2·7)/(k + 2·7), and Gustafsson's predictive proposal
// (h/h_acc)(r_acc/r²)^(1/(q−1)) taken when smaller.
struct RadauStepControl {
    double tolerance = 0.0;  // τ
    double span = 1.0;       // T
    int order = 4;           // q: the estimated local error is C h^q

    static constexpr double kSafety = 0.9;
    static constexpr double kMaxGrowth = 8.0;
    static constexpr double kMaxShrink = 0.2;
    static constexpr double kKeepBelow = 1.2;  // a factor in [1, kKeepBelow] keeps h
    static constexpr double kMinStep = StepSizeControl::kMinStep;

    using Decision = StepSizeControl::Decision;

    double ratio(double error, double h) const { return error / (tolerance * h / span); }
    bool underflow(double h) const { return h < kMinStep * span; }
    Decision decide(double r, double h, int /*iterations*/) const {
        double f = r > 0.0 ? kSafety * std::pow(r, -1.0 / (order - 1)) : kMaxGrowth;
        if (r > 1.0) return {false, h * std::clamp(f, kMaxShrink, kSafety)};
        f = std::clamp(f, kMaxShrink, kMaxGrowth);
        if (f >= 1.0 && f <= kKeepBelow) f = 1.0;
        return {true, h * f};
    }
};

}  // namespace rotbeam
