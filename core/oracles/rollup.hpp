// Exact roll-up of a cantilever under a tip moment (docs/benchmarks.md §1, seed 002 Example 1).
//
// Straight cantilever along +x of length L, clamped at s = 0, tip moment M = −λ (π EI / L) e_y.
// The internal force is zero, so the bending moment is M everywhere and the curvature is the
// constant λπ/L: the centreline is a circular arc of radius ρ = L/(λπ) in the x–z plane and the
// section at s is rotated by θ(s) = λπ s/L about −e_y (it bends upward, u₃ > 0). λ = 2 closes a
// full circle; any λ (including 0 and λ > 2) is valid.
#pragma once

#include "core/types.hpp"

namespace rotbeam::oracle {

struct RollupState {
    Vec3 displacement = Vec3::Zero();  // x(s) − s e_x
    Mat3 rotation = Mat3::Identity();  // relative to the reference configuration
    double angle = 0.0;                // unwrapped rotation angle θ(s) = λπ s/L about −e_y
};

// The tip moment magnitude of load factor λ: M = λ π EI / L.
double rollup_moment(double length, double bending_stiffness, double lambda);

// The state at arc length s ∈ [0, L] (u₁ = ρ sin θ − s, u₃ = ρ (1 − cos θ), series near θ = 0).
RollupState rollup_state(double length, double lambda, double s);

// The tip state, s = L: u₁ = ρ sin(λπ) − L, u₃ = ρ (1 − cos(λπ)).
inline RollupState rollup_tip(double length, double lambda) {
    return rollup_state(length, lambda, length);
}

}  // namespace rotbeam::oracle
