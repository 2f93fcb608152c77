// The elastica and linear Timoshenko oracles against published tables and their limits.
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <limits>
#include <vector>

#include "core/errors.hpp"
#include "core/oracles/elastica.hpp"
#include "core/oracles/timoshenko.hpp"
#include "core/types.hpp"

using namespace rotbeam;
using namespace rotbeam::oracle;

namespace {

// Huang's clamped–free frequency equation (T. C. Huang, J. Appl. Mech. 28:579–584, 1961), in
// b² = ρA L⁴ ω²/EI, r² = I/(A L²), s² = EI/(κGA L²): an independent closed form of the same
// spectrum that the oracle finds from its own 4×4 boundary determinant.
double huang_clamped_free(double b, double r2, double s2) {
    const double root = std::sqrt((r2 - s2) * (r2 - s2) + 4.0 / (b * b));
    const double alpha = std::sqrt(0.5 * (-(r2 + s2) + root));
    const double beta = std::sqrt(0.5 * ((r2 + s2) + root));
    return 2.0 + (b * b * (r2 - s2) * (r2 - s2) + 2.0) * std::cosh(b * alpha) * std::cos(b * beta) -
           b * (r2 + s2) / std::sqrt(1.0 - b * b * r2 * s2) * std::sinh(b * alpha) *
               std::sin(b * beta);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(elastica)

BOOST_AUTO_TEST_CASE(tip_matches_mattiasson_1981_table_1) {
    // K. Mattiasson, "Numerical results from large deflection beam and frame problems analysed by
    // means of elliptic integrals", IJNME 17:145–153 (1981), Table 1 (also Bisshopp & Drucker
    // 1945): PL²/EI → (w/L, u/L), printed to 5 decimals, hence the 5e-6 (+ε) tolerance.
    const double alpha[] = {1.0, 2.0, 5.0, 10.0};
    const double w[] = {0.30172, 0.49346, 0.71379, 0.81061};
    const double u[] = {0.05643, 0.16064, 0.38763, 0.55500};
    for (int i = 0; i < 4; ++i) {
        const ElasticaTip tip = elastica_tip(alpha[i]);
        BOOST_TEST_MESSAGE("elastica α = " << alpha[i] << ": w/L = " << tip.deflection << ", u/L = "
                                           << tip.shortening << ", θ₀ = " << tip.angle);
        BOOST_TEST(std::abs(tip.deflection - w[i]) < 5.01e-6);
        BOOST_TEST(std::abs(tip.shortening - u[i]) < 5.01e-6);
    }
    // Mattiasson's tip angle at PL²/EI = 1: 0.46135 rad.
    BOOST_TEST(std::abs(elastica_tip(1.0).angle - 0.46135) < 5.01e-6);
}

BOOST_AUTO_TEST_CASE(small_loads_reduce_to_linear_beam_theory) {
    // w/L = α/3 + O(α³), θ₀ = α/2 + O(α³), u/L = O(α²): at α = 1e-4 the relative deviation of
    // w and θ₀ is O(α²) = 1e-8, and the cancellation in w costs ~1e-16/α = 1e-12.
    const double alpha = 1e-4;
    const ElasticaTip tip = elastica_tip(alpha);
    BOOST_TEST(std::abs(tip.deflection / (alpha / 3.0) - 1.0) < 1e-7);
    BOOST_TEST(std::abs(tip.angle / (alpha / 2.0) - 1.0) < 1e-7);
    BOOST_TEST(std::abs(tip.shortening) < alpha * alpha);
    BOOST_TEST(elastica_tip(0.0).deflection == 0.0);
}

BOOST_AUTO_TEST_CASE(tip_angle_tends_to_a_right_angle_monotonically) {
    double previous = 0.0;
    for (double alpha : {0.5, 3.0, 20.0, 100.0, 300.0}) {
        const ElasticaTip tip = elastica_tip(alpha);
        BOOST_TEST(tip.angle > previous);
        BOOST_TEST(tip.angle < kPi / 2.0);
        previous = tip.angle;
    }
    BOOST_TEST(previous > 1.5);
    // Very large loads (checked independently against the continuum solver up to α = 1000):
    // the beam hangs along the force, u/L = 1 − √(2/α) + o, w/L = 1 − O(1/√α).
    const ElasticaTip hanging = elastica_tip(1e4);
    BOOST_TEST(std::abs(hanging.shortening - (1.0 - std::sqrt(2.0 / 1e4))) < 1e-12);
    BOOST_TEST(hanging.deflection > 0.97);
    BOOST_TEST(hanging.deflection < 1.0);
    BOOST_TEST(hanging.angle <= kPi / 2.0);  // π/2 − 2√(1 − k²) rounds to π/2 here
    BOOST_TEST(kPi / 2.0 - hanging.angle < 1e-8);
    BOOST_CHECK_THROW(elastica_tip(1e6), SolverError);
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(timoshenko)

BOOST_AUTO_TEST_CASE(tip_deflection_is_bending_plus_shear) {
    const TimoshenkoBeam beam{2.0, 3.0, 5.0, 1.0, 0.0};
    BOOST_TEST(std::abs(timoshenko_tip_deflection(beam, 7.0) - (7.0 * 8.0 / 9.0 + 14.0 / 5.0)) <
               1e-14);
}

BOOST_AUTO_TEST_CASE(frequencies_reduce_to_euler_bernoulli_without_shear_and_rotary_inertia) {
    // β_n L of the clamped–free Euler–Bernoulli beam (cosh β cos β = −1), to 10 digits.
    const double beta[] = {1.875104069, 4.694091133, 7.854757438, 10.99554073};
    // κGA = 1e12 EI/L²: the shear correction is O(EI/(κGA L²)) = 1e-12.
    const TimoshenkoBeam beam{2.0, 3.0, 3.0e12 / 4.0, 5.0, 0.0};
    const std::vector<double> omega = timoshenko_cantilever_frequencies(beam, 4);
    for (int i = 0; i < 4; ++i) {
        const double eb = beta[i] * beta[i] / 4.0 * std::sqrt(3.0 / 5.0);
        BOOST_TEST(std::abs(omega[i] / eb - 1.0) < 1e-9);
    }
}

BOOST_AUTO_TEST_CASE(shear_and_rotary_inertia_lower_the_frequencies_of_a_deep_beam) {
    // Square h × h steel-like section, L/h = 5, κ = 5/6, ν = 0.3 (docs/benchmarks.md §7 section).
    const double E = 2.1e11, G = E / 2.6, h = 0.2, L = 1.0, rho = 7850.0;
    const double A = h * h, I = h * h * h * h / 12.0;
    const TimoshenkoBeam full{L, E * I, 5.0 / 6.0 * G * A, rho * A, rho * I};
    TimoshenkoBeam no_rotary = full;
    no_rotary.rotary_inertia = 0.0;
    const std::vector<double> w_full = timoshenko_cantilever_frequencies(full, 3);
    const std::vector<double> w_shear = timoshenko_cantilever_frequencies(no_rotary, 3);
    const double beta[] = {1.875104069, 4.694091133, 7.854757438};
    for (int i = 0; i < 3; ++i) {
        const double eb = beta[i] * beta[i] / (L * L) * std::sqrt(E * I / (rho * A));
        BOOST_TEST(w_full[i] < w_shear[i]);
        BOOST_TEST(w_shear[i] < eb);
        BOOST_TEST_MESSAGE("L/h = 5 mode " << i + 1 << ": ω/ω_EB = " << w_full[i] / eb);
        // Each is a zero of the boundary determinant (relative to its size nearby).
        const double scale = std::abs(timoshenko_cantilever_determinant(full, 1.01 * w_full[i]));
        BOOST_TEST(std::abs(timoshenko_cantilever_determinant(full, w_full[i])) < 1e-10 * scale);
        // Huang's equation vanishes there too; its slope is O(1–100) per unit relative change
        // of ω, so 1e-8 means agreement to ~1e-9 relative or better.
        const double b = w_full[i] * L * L * std::sqrt(rho * A / (E * I));
        const double r2 = I / (A * L * L), s2 = E * I / (5.0 / 6.0 * G * A * L * L);
        BOOST_TEST(std::abs(huang_clamped_free(b, r2, s2)) < 1e-8);
    }
    // Classical first-mode correction ω/ω_EB ≈ 1 − O((h/L)²): a few percent at L/h = 5.
    const double eb1 = beta[0] * beta[0] / (L * L) * std::sqrt(E * I / (rho * A));
    BOOST_TEST(w_full[0] / eb1 > 0.95);
    BOOST_TEST(w_full[0] / eb1 < 0.995);
}

// The tip's modal series (timoshenko_tip_modes). In the Euler–Bernoulli limit the
// modal amplitudes of the tip deflection are known in closed form: with the normalised clamped–free
// modes (W_k(L)² = 4 for ∫W² = L, m_k = ρAL, ω_k² = β_k⁴ EI/(ρA L⁴)) they are 4PL³/(β_k⁴ EI), whose
// sum is PL³/(3EI). Checks the mode shapes and modal masses independently of their construction.
BOOST_AUTO_TEST_CASE(release_amplitudes_reduce_to_euler_bernoulli) {
    const double beta[] = {1.875104069, 4.694091133, 7.854757438, 10.99554073};
    const double L = 2.0, EI = 3.0, P = 7.0;
    const TimoshenkoBeam beam{L, EI, 3.0e12 / 4.0, 5.0, 0.0};
    const TimoshenkoTipModes r = timoshenko_tip_modes(beam, P, 4);
    for (int k = 0; k < 4; ++k) {
        const double b4 = std::pow(beta[k], 4);
        // β to 10 digits: 4e-10 relative in β⁴; the shear correction 1e-12.
        BOOST_TEST(std::abs(r.deflection[k] / (4.0 * P * L * L * L / (b4 * EI)) - 1.0) < 1e-8);
    }
}

// The tip rotation's series at t = 0 is the static rotation under the tip force, PL²/(2EI) (shear
// adds none): a sum the construction does not contain (the deflection's tail is defined by δ, the
// rotation's is only bounded through Cauchy–Schwarz), checked within that bound, on the deep beam
// and on cases/free-vibration.yaml's slender one; the bounds fall with the modes kept.
BOOST_AUTO_TEST_CASE(release_starts_from_the_static_state_within_its_truncation_bound) {
    const double E = 2.1e11, G = E / 2.6, rho = 7850.0, L = 1.0;
    // L/h = 20 (its cut-off leaves 16 modes) and the free vibration's L/h = 100 (82 modes).
    for (const double h : {0.05, 0.01}) {
        const double A = h * h, I = h * h * h * h / 12.0;
        const TimoshenkoBeam beam{L, E * I, 5.0 / 6.0 * G * A, rho * A, rho * I};
        const double P = 1.0;
        double last_tail = std::numeric_limits<double>::infinity();
        for (const int modes : h > 0.02 ? std::vector<int>{4, 14} : std::vector<int>{10, 40}) {
            const TimoshenkoTipModes r = timoshenko_tip_modes(beam, P, modes);
            const double psi_static = P * L * L / (2.0 * E * I);
            BOOST_TEST_MESSAGE("h = " << h << ", " << modes << " modes: tails "
                                      << r.deflection_tail / timoshenko_tip_deflection(beam, P)
                                      << " (deflection), " << r.rotation_tail / psi_static
                                      << " (rotation), relative");
            BOOST_TEST(std::abs(release_tip_rotation(r, 0.0) - psi_static) <=
                       r.rotation_tail + 1e-12 * psi_static);
            BOOST_TEST(r.rotation_tail < last_tail);
            last_tail = r.rotation_tail;
            // 40 modes: the release's deflection to 1e-6 of δ, its rotation (a slower series,
            // Σ 1/β³) to 2e-4.
            if (modes == 40) {
                BOOST_TEST(r.deflection_tail < 1e-6 * timoshenko_tip_deflection(beam, P));
                BOOST_TEST(r.rotation_tail < 2e-4 * psi_static);
            }
        }
    }
}

// Driven by P sin Ωt from rest: the series starts at rest (every mode's response is O(t³), so
// w(0) = 0 and w(1 µs) is far below δ) and, for a slow Ω, is quasi-static, P sin Ωt · δ/P: the
// kept modes' dynamic part is at most Ω/(ω₁ − Ω) ≈ 2e-5 of it, the truncated modes' bounded by
// the tail.
BOOST_AUTO_TEST_CASE(sine_response_starts_at_rest_and_is_quasi_static_when_slow) {
    const double E = 2.1e11, G = E / 2.6, h = 0.01, rho = 7850.0, L = 1.0;
    const double A = h * h, I = h * h * h * h / 12.0;
    const TimoshenkoBeam beam{L, E * I, 5.0 / 6.0 * G * A, rho * A, rho * I};
    const TimoshenkoTipModes r = timoshenko_tip_modes(beam, 1.0, 40);
    const double delta = timoshenko_tip_deflection(beam, 1.0);
    BOOST_TEST(std::abs(sine_tip_deflection(r, 20.0, 0.0)) < 1e-15 * delta);
    // w(t) ≈ w‴(0) t³/6 near 0: at t = 1e-6 s, |w| ≤ 1e-12 δ for any ω_k (Ω ω_k² t³/6 · δ).
    BOOST_TEST(std::abs(sine_tip_deflection(r, 20.0, 1e-6)) < 1e-9 * delta);
    // Ω = 1e-3 rad/s, t = π/(2Ω): the load at its peak; the dynamic part is Ω/ω₁ ≈ 2e-5 of it.
    const double slow = 1e-3, t = 0.5 * std::acos(-1.0) / slow;
    BOOST_TEST(std::abs(sine_tip_deflection(r, slow, t) / delta - 1.0) <
               slow / (r.omegas.front() - slow) +
                   r.deflection_tail * sine_tail_factor(r, slow) / delta);
    const double psi_static = 1.0 / (2.0 * E * I);
    BOOST_TEST(std::abs(sine_tip_rotation(r, slow, t) / psi_static - 1.0) <
               slow / (r.omegas.front() - slow) +
                   r.rotation_tail * sine_tail_factor(r, slow) / psi_static);
}

BOOST_AUTO_TEST_CASE(asking_past_the_cutoff_is_refused) {
    const TimoshenkoBeam stubby{1.0, 1.0, 1.0, 1.0, 1.0};  // cut-off ω = 1 (β = 1)
    BOOST_CHECK_THROW(timoshenko_cantilever_frequencies(stubby, 1), SolverError);
}

BOOST_AUTO_TEST_SUITE_END()
