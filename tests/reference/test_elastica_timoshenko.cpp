// The elastica and linear Timoshenko oracles against published tables and their limits.
#include <boost/test/unit_test.hpp>
#include <cmath>

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

BOOST_AUTO_TEST_CASE(asking_past_the_cutoff_is_refused) {
    const TimoshenkoBeam stubby{1.0, 1.0, 1.0, 1.0, 1.0};  // cut-off ω = 1 (β = 1)
    BOOST_CHECK_THROW(timoshenko_cantilever_frequencies(stubby, 1), SolverError);
}

BOOST_AUTO_TEST_SUITE_END()
