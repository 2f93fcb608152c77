// Linear Timoshenko cantilever (clamped at x = 0, free at x = L): static tip deflection under a
// transverse tip force, the natural frequencies of bending in one plane, and the free vibration
// after a release from the static deflection (modal superposition).
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

// The tip's motion under a transverse tip force P f(t) by modal superposition over the lowest
// modes (docs/reference-solutions.md §4). Mode k (deflection W_k, section rotation Ψ_k, modal mass
// m_k = ∫(ρA W_k² + ρI Ψ_k²) dx) responds with q_k(t) = P W_k(L)/(m_k ω_k²) g_k(t), so that
//   w(L, t) = Σ_k s_k g_k(t),  s_k = P W_k(L)² / (ω_k² m_k),
//   ψ(L, t) = Σ_k r_k g_k(t),  r_k = P W_k(L) Ψ_k(L) / (ω_k² m_k),
// and Σ_k s_k, Σ_k r_k over all modes are the static tip deflection and rotation under P (the
// flexibility's modal expansion). g_k = cos ω_k t for the release at rest from the static
// deflection (f = 1 before t = 0, 0 after); g_k = ω_k² (sin Ωt − (Ω/ω_k) sin ω_k t)/(ω_k² − Ω²)
// for f = sin Ωt from rest, where the truncated modes' quasi-static part sin Ωt is added in closed
// form (the static values less the kept modes' sums: the mode-acceleration method), so only their
// dynamic part g_k − sin Ωt, at most Ω/(ω_k − Ω), is left out.
struct TimoshenkoTipModes {
    std::vector<double> omegas;      // ω_k
    std::vector<double> deflection;  // s_k
    std::vector<double> rotation;    // r_k
    double static_deflection = 0.0;  // P δ(1): PL³/(3EI) + PL/(κGA)
    double static_rotation = 0.0;    // PL²/(2EI)
    // Bounds on Σ |s_k| and Σ |r_k| over the truncated modes: what the kept modes leave of the
    // flexibilities δ/P and L/EI (for r_k through Cauchy–Schwarz, √(Σ s_k · Σ P²Ψ_k²/(ω_k² m_k))).
    double deflection_tail = 0.0;
    double rotation_tail = 0.0;
};

TimoshenkoTipModes timoshenko_tip_modes(const TimoshenkoBeam& beam, double force, int modes);

// Released at rest from the static deflection under P at t = 0.
double release_tip_deflection(const TimoshenkoTipModes& modes, double t);
double release_tip_rotation(const TimoshenkoTipModes& modes, double t);

// Driven from rest by P sin Ωt (Ω below the first frequency).
double sine_tip_deflection(const TimoshenkoTipModes& modes, double omega, double t);
double sine_tip_rotation(const TimoshenkoTipModes& modes, double omega, double t);
// The factor of the tails for the sine: Ω/(ω − Ω) at ω = the last kept frequency (a bound on
// |g_k − sin Ωt| for every truncated mode, all above it). The release's factor is 1.
double sine_tail_factor(const TimoshenkoTipModes& modes, double omega);

}  // namespace rotbeam::oracle
