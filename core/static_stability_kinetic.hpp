// The kinetic (Ziegler) stability criterion of a static equilibrium whose loads have no potential
// (follower loads, dead moments): the eigenvalues s of the linearized free motion about it,
//   M q̈ + K q = 0,   (s² M + K) φ = 0,
// K the consistent tangent of the residual (load stiffness included, not symmetric) and M the
// mass matrix in the same unknowns. Without damping or gyroscopic terms s² is an eigenvalue of
// −M⁻¹K, so s and −s are eigenvalues together: the equilibrium is spectrally stable iff every ω² =
// −s² is real and positive (every s imaginary). Divergence: a real ω² < 0 (a real s > 0); flutter:
// a complex ω² (s = ±a ± ib, a > 0). docs/solver-convergence.md, "Kinetic criterion".
//
// What `stable` proves, and what not: no computed eigenvalue has |Re s| above its own error
// estimate (core/quadratic_eigenpair.hpp) among the `modes` lowest |s| — the linearized motion has
// no exponentially growing solution in those modes. It does not prove Lyapunov stability of the
// nonlinear motion (with every s imaginary Lyapunov's indirect method is inconclusive: nonlinear
// terms may still destabilize), and says nothing of the modes above the highest one checked
// (`highest_frequency_hz`).
#pragma once

#include <complex>
#include <string>
#include <vector>

#include "core/static_stability.hpp"

namespace rotbeam {

// The lowest modes the criterion checks: the first four bending modes of each plane of a straight
// beam (Beck's flutter is the coalescence of the first two of one plane; docs/solver-convergence.md
// argues the count).
inline constexpr int kKineticModes = 8;

// One computed eigenvalue s of (s² M + K) φ = 0, refined on the quadratic problem.
struct KineticEigenvalue {
    std::complex<double> s;
    double error = 0.0;  // first-order error estimate of s, absolute (∞: defective)
    bool accepted = false;
    std::string failure;  // the check that failed (when not accepted)
};

// The computed spectrum about the current state, or why there is none.
struct KineticSpectrum {
    std::vector<KineticEigenvalue> eigenvalues;
    std::string unavailable;  // non-empty: no spectrum (no mass, no such linearization)
};

// A static system that forms its linearized free motion about its current state.
class KineticSystem {
  public:
    virtual ~KineticSystem() = default;
    // The `count` eigenvalues nearest s = 0 (one of each pair ±s kept by the solver); leaves the
    // state, and every counter, as it was.
    virtual KineticSpectrum kinetic_spectrum(int count) = 0;
};

// The verdict of a spectrum (header comment): `unstable` when some |Re s| exceeds its error
// (`kinetic.growing` modes, divergence or flutter), `critical` when an eigenvalue is defective
// (two modes meeting: infinite error) or |s| is within its error of zero, `stable` otherwise;
// `not_assessed` when the spectrum is unavailable or a pair failed its check.
StaticStability assess_kinetic_stability(const KineticSpectrum& spectrum);

}  // namespace rotbeam
