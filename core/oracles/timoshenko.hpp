// Linear Timoshenko cantilever (clamped at x = 0, free at x = L): static tip deflection under a
// transverse tip force and the natural frequencies of bending in one plane.
//
// Free vibration w(x) e^{iωt}, ψ(x) e^{iωt} (deflection, section rotation):
//   κGA (w'' − ψ') + ρA ω² w = 0,   EI ψ'' + κGA (w' − ψ) + ρI ω² ψ = 0,
// clamped: w = ψ = 0 at x = 0; free: EI ψ' = 0 and κGA (w' − ψ) = 0 at x = L. The characteristic
// exponents λ solve κGA EI λ⁴ + ω² (κGA ρI + ρA EI) λ² + ρA ω² (ρI ω² − κGA) = 0; below the
// cut-off ω² < κGA/ρI one root is λ² = a² > 0, the other λ² = −b² < 0, and the four boundary
// conditions give a 4×4 determinant whose zeros are the natural frequencies (derivation in
// docs/reference-solutions.md §4). As κGA → ∞ and ρI → 0 they reduce to Euler–Bernoulli,
// ω_n = β_n² √(EI/(ρA L⁴)) with β_n = 1.875104, 4.694091, 7.854757, ...
#pragma once

#include <vector>

namespace rotbeam::oracle {

struct TimoshenkoBeam {
    double length = 1.0;
    double bending_stiffness = 1.0;  // EI
    double shear_stiffness = 1.0;    // κGA
    double mass_per_length = 1.0;    // ρA
    double rotary_inertia = 0.0;     // ρI per unit length
};

// δ = PL³/(3EI) + PL/(κGA).
double timoshenko_tip_deflection(const TimoshenkoBeam& beam, double force);

// The boundary-condition determinant at circular frequency ω (exposed for tests: its zeros are
// the natural frequencies). Requires 0 < ω² < κGA/ρI.
double timoshenko_cantilever_determinant(const TimoshenkoBeam& beam, double omega);

// The lowest `count` natural circular frequencies ω [rad/time] below the cut-off √(κGA/ρI),
// bracketed by a scan in the Euler–Bernoulli wave number and refined by Brent's method to
// ~1e-14 relative. Throws SolverError when fewer than `count` lie below the cut-off.
std::vector<double> timoshenko_cantilever_frequencies(const TimoshenkoBeam& beam, int count);

}  // namespace rotbeam::oracle
