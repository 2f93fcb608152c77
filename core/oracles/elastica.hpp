// Inextensible, unshearable Euler elastica: cantilever of length L, bending stiffness EI, dead tip
// force P perpendicular to the undeformed beam (Bisshopp & Drucker 1945; Mattiasson 1981).
//
// With θ(s) the tangent angle toward the force, EI θ'' = −P cos θ, θ(0) = 0, θ'(L) = 0. The
// substitution 1 + sin θ = 2k² sin²φ, k² = (1 + sin θ₀)/2, sin φ₀ = 1/(k√2) gives
//   √α = K(k) − F(φ₀, k),                         α = PL²/EI,
//   w/L = 1 − 2 [E(k) − E(φ₀, k)] / √α,           (deflection along the force)
//   u/L = 1 − √(2 sin θ₀ / α),                    (shortening along the beam)
// derived in docs/reference-solutions.md §3. k is found by Brent's method on ln(1 − k²), with
// K(k) from the arithmetic–geometric mean of 1 and k' so that loads near θ₀ = π/2 stay exact.
#pragma once

namespace rotbeam::oracle {

struct ElasticaTip {
    double deflection = 0.0;  // w/L, along the force
    double shortening = 0.0;  // u/L, toward the root (the tip moves by −u along the beam axis)
    double angle = 0.0;       // tip rotation θ₀ [rad]
    double modulus = 0.0;     // k
};

// Tip of the cantilever for α = PL²/EI ≥ 0 (dimensionless). The cancellation in w/L costs
// about 1e-16/α relative accuracy for small α. Loads up to α ≈ 1e5 (1 − k² ≥ 1e-300) are
// solved; beyond, SolverError.
ElasticaTip elastica_tip(double alpha);

}  // namespace rotbeam::oracle
