// Modes of the displacement formulation about a spinning state with the Coriolis (gyroscopic)
// coupling (formulations/displacement/displacement_modal.hpp, docs/rotating-frame.md), against
//  - a closed form: a beam spinning about its own axis at Ω, whose rotating-frame bending
//    frequencies are ω_n ± Ω (ω_n those of the beam at rest): without the Coriolis terms the
//    spin softening alone gives √(ω_n² − Ω²), and past Ω = ω_n a divergence;
//  - a closed form with a genuine instability: the asymmetric shaft (unequal bending stiffnesses)
//    diverges between its two critical speeds and is gyroscopically stable above them;
//  - the mixed formulation at convergence (its modal analysis linearizes its dynamics, frame
//    terms included): flap and lead-lag of a spinning cantilever soft enough in tension that the
//    Coriolis coupling of lead-lag to the axial motion moves the lag frequency by percents.
#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>
#include <gsl/gsl_roots.h>

#include <algorithm>
#include <array>
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <initializer_list>
#include <iomanip>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "combinations/registry.hpp"
#include "tests/cases/spinning_beam.hpp"

using namespace rotbeam;

namespace {

// The angular frequencies ω = 2π f of a modal result, in its order.
std::vector<double> angular_frequencies(const nlohmann::json& r) {
    std::vector<double> w;
    for (const auto& m : r["modes"]) {
        w.push_back(2.0 * std::numbers::pi * m["frequency_hz"].get<double>());
    }
    return w;
}

// The beam spinning about its own axis of the tests below (L = 1, m = 1, EA = GA = 1e6, GJ = 1,
// rotary inertias 1e-6), EI = 1 about y and `ei_z` about z, 4 elements of order 8.
test::SpinningBeam beam_along_its_spin(double ei_z) {
    test::SpinningBeam b;
    b.stiffness = {1e6, 1e6, 1e6, 1.0, 1.0, ei_z};
    b.mass = {1.0, 1.0, 1.0, 1e-6, 1e-6, 1e-6};
    b.elements = 4;
    b.order = 8;
    return b;
}

// What a modal run of a conservative system must say: no mode counted as flutter or divergence,
// and every growth rate within its eigenvalue's error estimate (the verdict's threshold,
// runs/modal_checks.cpp), that estimate at most 1e-6 |s|: the finest comparison made of these
// frequencies (the mixed reference below); a larger one would leave it unsupported. Measured
// (core/quadratic_eigenpair.hpp, the floor of the stiff matrices' round-off, GA/ρ = 1e12):
// ≤ 1.8e-7 |s| on the spinning beams, ≤ 3.2e-11 |s| on the cantilever soft in tension.
// A system found conservative (`modal.refinement`) has each stable s refined onto the imaginary
// axis: Re s exactly 0 (core/quadratic_eigenpair.hpp).
// The mixed formulation's linearized DAE has no such structure (`expect_conservative` false):
// its Re s is round-off within the estimate.
void check_no_growth(const nlohmann::json& r, bool expect_conservative = true) {
    BOOST_TEST(r["message"].get<std::string>().find("flutter") == std::string::npos);
    // A missing field (an unrefined run) reads as "" or −1: a failed check, not an exception.
    const bool conservative =
        r["modal"].value("refinement", std::string()).starts_with("conservative");
    BOOST_TEST(conservative == expect_conservative);
    for (const auto& m : r["modes"]) {
        BOOST_TEST(m.value(nlohmann::json::json_pointer("/refinement/steps"), -1) >= 1);
        if (conservative) BOOST_TEST(m["growth_rate"].get<double>() == 0.0);
        const double s = std::hypot(m["s"][0].get<double>(), m["s"][1].get<double>());
        const double estimate = m["check"].value("error_estimate", -1.0);
        BOOST_TEST(std::abs(m["growth_rate"].get<double>()) <= estimate * s);
        BOOST_TEST(estimate <= 1e-6);
    }
}

// The asymmetric shaft's closed form (the test below) at Ω from the frequencies at rest w0
// (ω_y1, ω_z1, ω_y2, ω_z2): per mode pair s⁴ + (a + b + 4Ω²) s² + ab = 0, a = ω_y² − Ω²,
// b = ω_z² − Ω²; `growth` the real s > 0 (divergence), `frequencies` the |s| of the imaginary
// ones, ascending.
struct ShaftSpectrum {
    std::vector<double> growth, frequencies;
};
ShaftSpectrum asymmetric_shaft(const std::vector<double>& w0, double Omega) {
    ShaftSpectrum out;
    for (int n = 0; n < 2; ++n) {
        const double a = w0[2 * n] * w0[2 * n] - Omega * Omega;
        const double bb = w0[2 * n + 1] * w0[2 * n + 1] - Omega * Omega;
        const double p = a + bb + 4.0 * Omega * Omega;
        const double t1 = -0.5 * (p + std::sqrt(p * p - 4.0 * a * bb)), t2 = a * bb / t1;
        for (const double t : {t1, t2}) {
            (t > 0.0 ? out.growth : out.frequencies).push_back(std::sqrt(std::abs(t)));
        }
    }
    std::sort(out.frequencies.begin(), out.frequencies.end());
    return out;
}

// A modal run of the shaft against its closed form, each s to `tolerance` of `scale`: the
// divergences first (f = 0, growth rate s), then the frequencies; a stable run must report no
// growth (check_no_growth), a divergent one count its divergences in the message.
void check_shaft_modes(const nlohmann::json& r, const ShaftSpectrum& e, double scale,
                       double tolerance, bool expect_conservative) {
    size_t i = 0;
    for (const double g : e.growth) {  // divergences come first (f = 0)
        const auto& m = r["modes"][i++];
        BOOST_TEST(m["frequency_hz"].get<double>() == 0.0);
        BOOST_CHECK_SMALL((m["growth_rate"].get<double>() - g) / scale, tolerance);
    }
    for (size_t k = 0; i < 4; ++i, ++k) {
        const auto& m = r["modes"][i];
        BOOST_CHECK_SMALL(
            (2.0 * std::numbers::pi * m["frequency_hz"].get<double>() - e.frequencies[k]) / scale,
            tolerance);
    }
    if (e.growth.empty()) {
        check_no_growth(r, expect_conservative);
    } else {
        BOOST_TEST(r["message"].get<std::string>().find(
                       std::to_string(e.growth.size()) +
                       " with a growth rate above round-off (complex s: flutter or divergence)") !=
                   std::string::npos);
    }
}

// The mixed formulation on the two beams of the tests below (every parameterization, kMixedElements
// elements): its modal analysis about the spinning state linearizes its DAE with the turning
// frame's terms (formulations/mixed/mixed_modal.hpp) and refines each pair on A + sB. The closed
// forms are taken, as above, with the frequencies at rest of the same model and mesh: the two
// planes' discrete bending modes have the same shape (the section differs by a factor on EI, the
// shear compliance's share is EI/(GA L²) = 1e-6), so the discrete spinning beam obeys them to the
// same 1e-6 whatever the mesh, and the same tolerance 1e-5 applies: the element's
// discretization error (second order, 1e-4 on ω₁ at 32 elements) cancels out of the comparison.
constexpr int kMixedElements = 32;

// Runs `b` in `formulation` (the mixed one on kMixedElements elements), every parameterization,
// at rest and at each Ω of `speeds` (about x), and calls check(r, w0, Ω) with each spinning run r
// (solved) and the angular frequencies w0 at rest of the same model and mesh.
template <class Check>
void for_each_spin(Formulation formulation, test::SpinningBeam b,
                   std::initializer_list<double> speeds, const Check& check) {
    if (formulation == Formulation::mixed) {
        b.mixed = true;
        b.elements = kMixedElements;
    }
    const std::string analysis = "  type: modal\n  modes: 4\n";
    for (const comb::Combination& c : comb::all_combinations(false)) {
        if (c.formulation != formulation) continue;
        const std::vector<std::string> o = {"discretization.rotation=" + c.rotation_name()};
        b.angular_velocity = Vec3::Zero();
        const nlohmann::json rest =
            test::run_spinning_case(test::spinning_beam_case(analysis, b), o);
        BOOST_REQUIRE(test::solved(rest));
        const std::vector<double> w0 = angular_frequencies(rest);
        for (const double Omega : speeds) {
            b.angular_velocity = Vec3(Omega, 0.0, 0.0);
            const nlohmann::json r =
                test::run_spinning_case(test::spinning_beam_case(analysis, b), o);
            BOOST_TEST_CONTEXT(c.label() << ", Omega " << Omega << ": " << r["status"] << " "
                                         << r.value("message", "")) {
                BOOST_REQUIRE(test::solved(r));
                BOOST_TEST_MESSAGE(c.label() << ", Omega " << Omega << ": first s "
                                             << r["modes"][0]["s"] << ", " << r["message"]);
                check(r, w0, Omega);
            }
        }
    }
}

// Euler–Bernoulli cantilever (L = 1, EI = 1, m = 1) under a dead compressive tip force P along its
// axis: small motions w(x) e^{st} obey w'''' + P w'' + s² w = 0 with w = w' = 0 at the root and, at
// the free tip, w'' = 0 and w''' + P w' = 0 (no moment; the dead force keeps its direction, so the
// transverse shear balances its component along the turned section). The characteristic
// determinant, shot from the root with GSL's Runge–Kutta–Prince–Dormand (8, 9) at 1e-13: the two
// solutions that start with (w'', w''') = (1, 0) and (0, 1) span those meeting the root's
// conditions; D(μ) = 0 at μ = s² (μ > 0: divergence, s real; μ < 0: a vibration at ω = √−μ).
struct ColumnParams {
    double P, mu;
};
int column_rhs(double, const double y[], double dydx[], void* p) {
    const auto* c = static_cast<const ColumnParams*>(p);
    dydx[0] = y[1];
    dydx[1] = y[2];
    dydx[2] = y[3];
    dydx[3] = -c->P * y[2] - c->mu * y[0];
    return GSL_SUCCESS;
}
double cantilever_column_determinant(double mu, double P) {
    ColumnParams params{P, mu};
    gsl_odeiv2_system sys{column_rhs, nullptr, 4, &params};
    std::array<std::array<double, 4>, 2> tip{{{0, 0, 1, 0}, {0, 0, 0, 1}}};
    for (auto& y : tip) {
        gsl_odeiv2_driver* d =
            gsl_odeiv2_driver_alloc_y_new(&sys, gsl_odeiv2_step_rk8pd, 1e-3, 1e-13, 1e-13);
        double x = 0.0;
        const int status = gsl_odeiv2_driver_apply(d, &x, 1.0, y.data());
        gsl_odeiv2_driver_free(d);
        BOOST_REQUIRE(status == GSL_SUCCESS);
    }
    const auto& a = tip[0];
    const auto& b = tip[1];
    return a[2] * (b[3] + P * b[1]) - b[2] * (a[3] + P * a[1]);
}
double column_determinant_of_mu(double mu, void* p) {
    return cantilever_column_determinant(mu, static_cast<ColumnParams*>(p)->P);
}

// The root μ = s² of that determinant in [lo, hi] (one sign change there), by Brent's method.
double cantilever_column_mu(double P, double lo, double hi) {
    ColumnParams params{P, 0.0};
    gsl_function f{column_determinant_of_mu, &params};
    gsl_root_fsolver* solver = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
    gsl_root_fsolver_set(solver, &f, lo, hi);
    double mu = 0.5 * (lo + hi);
    for (int i = 0; i < 200; ++i) {
        gsl_root_fsolver_iterate(solver);
        mu = gsl_root_fsolver_root(solver);
        if (gsl_root_test_interval(gsl_root_fsolver_x_lower(solver),
                                   gsl_root_fsolver_x_upper(solver), 0.0, 1e-14) == GSL_SUCCESS)
            break;
    }
    gsl_root_fsolver_free(solver);
    return mu;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(gyroscopic_modes)

// A uniform beam (L = 1, m = 1, EI = 1 about both lateral axes, GA = EA = 1e6, GJ = 1) spinning
// about its own axis (Ω along x through the origin) is not loaded by the spin (every point is on
// the axis), and its section stiffness and rotary inertia (ρ = 1e-6 I) are symmetric about that
// axis: the spin changes nothing in inertial axes (a material rotation about the axis leaves the
// strains' energy and the kinetic energy alike), so the inertial modes are those at rest, each
// bending frequency ω_n a pair (y and z). Seen in the frame turning with the beam, that pair is a
// forward and a backward whirl at ω_n + Ω and |ω_n − Ω|. The one effect the argument drops is the
// rotary inertia's own gyroscopic term, ρ Ω ψ × ψ̇ (the material spin's share of ½ ρ |ω|²): a
// relative change of order ρ/(m L²) = 1e-6. Tolerance 1e-5 relative to ω_n + Ω: ten times that,
// three orders below what the Coriolis coupling changes (at Ω = 1 the lowest frequency is 2.516
// with it and √(3.516² − 1) = 3.371 without; at Ω = 5 > ω₁ the beam without it diverges).
// ω_n: the same model and mesh at Ω = 0 (4 elements of order 8), every parameterization.
BOOST_AUTO_TEST_CASE(a_beam_spinning_about_its_axis_whirls_at_omega_n_plus_and_minus_omega) {
    constexpr double kTolerance = 1e-5;
    test::SpinningBeam b = beam_along_its_spin(1.0);
    for (const comb::Combination& c : comb::all_combinations(false)) {
        if (c.formulation != Formulation::displacement) continue;
        const std::vector<std::string> o = {"discretization.rotation=" + c.rotation_name()};
        b.angular_velocity = Vec3::Zero();
        const nlohmann::json rest =
            test::run_spinning_case(test::spinning_beam_case("  type: modal\n  modes: 4\n", b), o);
        BOOST_REQUIRE(test::solved(rest));
        const std::vector<double> w0 = angular_frequencies(rest);
        // The bending pairs at rest: ω₁ twice, then ω₂ twice.
        BOOST_REQUIRE_CLOSE(w0[0], w0[1], 1e-8);
        BOOST_REQUIRE_CLOSE(w0[2], w0[3], 1e-8);
        for (const double Omega : {1.0, 2.5, 5.0}) {
            b.angular_velocity = Vec3(Omega, 0.0, 0.0);
            const nlohmann::json r = test::run_spinning_case(
                test::spinning_beam_case("  type: modal\n  modes: 4\n", b), o);
            BOOST_TEST_CONTEXT(c.label() << ", Omega " << Omega << ": " << r["status"] << " "
                                         << r.value("message", "")) {
                BOOST_REQUIRE(test::solved(r));
                const std::vector<double> w = angular_frequencies(r);
                std::vector<double> expected = {std::abs(w0[0] - Omega), w0[0] + Omega,
                                                std::abs(w0[2] - Omega), w0[2] + Omega};
                std::sort(expected.begin(), expected.end());
                double worst = 0.0;
                for (size_t i = 0; i < 4; ++i) {
                    worst = std::max(worst, std::abs(w[i] - expected[i]) / (w0[i] + Omega));
                    BOOST_CHECK_SMALL((w[i] - expected[i]) / (w0[i] + Omega), kTolerance);
                }
                BOOST_TEST_MESSAGE(c.label() << ", Omega " << Omega << ": " << std::setprecision(10)
                                             << w[0] << ", " << w[1] << ", " << w[2] << ", " << w[3]
                                             << " against omega_n -+ Omega: worst " << worst);
                // Re s is zero for this conservative system. The Arnoldi iteration alone left it
                // at its tolerance times the spectrum's spread (1e-12 relative Ritz values of
                // 1/(s − σ), |s| up to ~1e6 for GA/ρ = 1e12): up to 1.8e-6 1/s, counted as
                // flutter by the status message; refined on the quadratic problem it is within
                // the eigenvalue's own error estimate. A non-skew part of G (one block with a
                // wrong sign) damps or drives the whirls at a rate of order Ω.
                check_no_growth(r);
            }
        }
    }
}

// The same beam with unequal bending stiffnesses, EI = 1 (bending in x–z) and 2 (x–y), spinning
// about its own axis: the asymmetric shaft. Each bending mode shape is the same in both planes
// (a uniform clamped–free beam), so the modes in the turning frame pair the n-th frequencies ω_y,
// ω_z at rest as the two-degree-of-freedom shaft does (Meirovitch, "Methods of Analytical
// Dynamics", 1970, §6.8; tests/runs/test_quadratic_eigenpair.cpp): with a = ω_y² − Ω²,
// b = ω_z² − Ω², s⁴ + (a + b + 4Ω²) s² + ab = 0. Between the two critical speeds, ω_y < Ω < ω_z,
// one pair is real: divergence, s = √(s²) > 0 with f = 0. Outside it every s is imaginary — at
// Ω = 6 > ω_z too, where the spin softening makes K indefinite and the Coriolis coupling alone
// stabilizes (gyroscopic stabilization). Neglected, as above: the rotary inertia's own terms and
// the planes' different shear corrections, of relative order 1e-6 (ρ/(m L²), EI/(GA L²)); the
// tolerance 1e-5 of ω₂ + Ω as above. The frequencies at rest: the same model at Ω = 0.
// Ω = 2: all stable (ω_y1 = 3.516, ω_z1 = 4.972); Ω = 4.2: mode pair 1 diverges at s = 0.717 1/s;
// Ω = 6: stable, K indefinite.
// The mixed formulation (below) alike: before, its Arnoldi selection dropped the real s and the
// run at Ω = 4.2 read "converged" with four whirls; its stable s are within their estimates of
// the imaginary axis, not on it (the linearized DAE has no structure the refinement could use).
BOOST_AUTO_TEST_CASE(an_asymmetric_shaft_diverges_between_its_critical_speeds_only) {
    constexpr double kTolerance = 1e-5;
    for (const Formulation f : {Formulation::displacement, Formulation::mixed}) {
        // w0: ω_y1 < ω_z1 < ω_y2 < ω_z2 (the ratio √2 per mode).
        for_each_spin(f, beam_along_its_spin(2.0), {2.0, 4.2, 6.0},
                      [&](const nlohmann::json& r, const std::vector<double>& w0, double Omega) {
                          check_shaft_modes(r, asymmetric_shaft(w0, Omega), w0[3] + Omega,
                                            kTolerance, f == Formulation::displacement);
                      });
    }
}

// The spinning cantilever of test_rotating_frame.cpp (L = 1, m = 1, EI = 1 flap, 4 lag, rotary
// inertias 1e-6, Ω = 12 about z through (−0.5, 0, 0)) made soft in tension and shear,
// EA = GA = 1e4 (m Ω² L²/EA = 0.0144): the Coriolis force couples lead-lag to the axial motion
// and lowers the first lag frequency by 1.1 % (13.428 without it). The mixed formulation at
// convergence is the reference: its first four frequencies at 64, 128, 256 elements (quaternion)
// converge at its second order (lag 1: differences 3.56e-4, 8.91e-5, ratio 4.00), and the
// Richardson values from 64/128 and 128/256 agree to 1e-8 relative; the reference is the
// latter, f_256 + (f_256 − f_128)/3. The displacement formulation at 4 elements of order 8 (its
// discretization error on these modes is below 1e-9: order 10 changes them by less) must meet it
// to 1e-6 relative: a hundred times the Richardson values' spread, four orders below the
// Coriolis effect on lag 1 (1.1e-2) and three below that on lag 2 (1.8e-3). Flap has no Coriolis
// force: it agrees without it too, and is checked alike.
BOOST_AUTO_TEST_CASE(flap_and_lag_frequencies_meet_the_mixed_formulation_at_convergence) {
    constexpr double kTolerance = 1e-6;
    test::SpinningBeam b;
    b.stiffness = {1e4, 1e4, 1e4, 1.0, 1.0, 4.0};
    b.angular_velocity = Vec3(0.0, 0.0, 12.0);
    b.center = Vec3(-0.5, 0.0, 0.0);
    b.mixed = true;
    const std::string analysis = "  type: modal\n  modes: 4\n";
    std::vector<std::vector<double>> mixed;
    for (const int elements : {128, 256}) {
        b.elements = elements;
        const nlohmann::json r = test::run_spinning_case(test::spinning_beam_case(analysis, b));
        BOOST_REQUIRE(test::solved(r));
        mixed.push_back(angular_frequencies(r));
    }
    b.mixed = false;
    b.elements = 4;
    b.order = 8;
    for (const comb::Combination& c : comb::all_combinations(false)) {
        if (c.formulation != Formulation::displacement) continue;
        const nlohmann::json r =
            test::run_spinning_case(test::spinning_beam_case(analysis, b),
                                    {"discretization.rotation=" + c.rotation_name()});
        BOOST_TEST_CONTEXT(c.label() << ": " << r["status"] << " " << r.value("message", "")) {
            BOOST_REQUIRE(test::solved(r));
            check_no_growth(r);
            const std::vector<double> w = angular_frequencies(r);
            for (size_t i = 0; i < 4; ++i) {
                const double reference = mixed[1][i] + (mixed[1][i] - mixed[0][i]) / 3.0;
                BOOST_TEST_MESSAGE(c.label()
                                   << ", mode " << i + 1 << ": " << std::setprecision(12) << w[i]
                                   << " against the mixed formulation's " << reference
                                   << " (relative " << (w[i] - reference) / reference << ")");
                BOOST_CHECK_SMALL((w[i] - reference) / reference, kTolerance);
            }
        }
    }
}

// The own-axis beam (a conservative system): whirls at |ω_n ∓ Ω| and no growth — every Re s
// within its error estimate (the linearized DAE gives the refinement no structure that would put
// it at 0 exactly), the estimate ≤ 1e-6 |s|, no flutter in the message. Before the refinement
// the modes carried no error estimate.
BOOST_AUTO_TEST_CASE(the_mixed_formulation_whirls_at_omega_n_plus_and_minus_omega_without_growth) {
    constexpr double kTolerance = 1e-5;
    for_each_spin(Formulation::mixed, beam_along_its_spin(1.0), {1.0, 2.5, 5.0},
                  [&](const nlohmann::json& r, const std::vector<double>& w0, double Omega) {
                      const std::vector<double> w = angular_frequencies(r);
                      std::vector<double> expected = {std::abs(w0[0] - Omega), w0[0] + Omega,
                                                      std::abs(w0[2] - Omega), w0[2] + Omega};
                      std::sort(expected.begin(), expected.end());
                      for (size_t i = 0; i < 4; ++i) {
                          BOOST_CHECK_SMALL((w[i] - expected[i]) / (w0[3] + Omega), kTolerance);
                      }
                      check_no_growth(r, false);
                  });
}

// The two formulations' eigenvalues of the asymmetric shaft at Ω = 4.2 (the divergence and three
// whirls, Re s of the divergence, Im s of the whirls) agree within their error estimates:
// - the displacement formulation (4 elements of order 8, rotation vector): its discretization
//   error on these modes is below 1e-9 (order 10 changes them by less, the cantilever above), so
//   its eigenvalue's own first-order estimate δ_d (check.error_estimate |s|) is its error: 7.4e-7
//   relative on the divergence (5.3e-7 1/s), ≤ 1.7e-8 on the whirls (measured);
// - the mixed formulation (every parameterization) converges at order 2 (successive differences
//   at 32, 64, 128 elements fall by 3.97–4.01, measured), so its Richardson value from 64/128,
//   R = s₁₂₈ + (s₁₂₈ − s₆₄)/3, carries an h⁴ remainder, which the change from the 32/64 value
//   bounds (16 times over, for an h⁴ term): E = |R₆₄,₁₂₈ − R₃₂,₆₄|; plus its eigenvalue estimate
//   δ_m (≤ 1.5e-13 relative, measured).
// Required: |R − s_d| ≤ E + δ_d + δ_m. Measured: 4.2e-7 against 8.0e-7 on the divergence, ≤ 5.5e-6
// against ≥ 4.9e-8 … 8.3e-5 on the whirls. Before, the mixed formulation reported no divergence
// (its first mode was the lowest whirl).
BOOST_AUTO_TEST_CASE(mixed_and_displacement_shaft_eigenvalues_agree_within_their_estimates) {
    test::SpinningBeam b = beam_along_its_spin(2.0);
    b.angular_velocity = Vec3(4.2, 0.0, 0.0);
    const std::string analysis = "  type: modal\n  modes: 4\n";
    const nlohmann::json d = test::run_spinning_case(test::spinning_beam_case(analysis, b),
                                                     {"discretization.rotation=rotation-vector"});
    BOOST_REQUIRE(test::solved(d));
    // The part of s compared (Re s of the divergence, Im s of a whirl) and its estimate.
    const auto part = [](const nlohmann::json& m, size_t i) {
        return m["modes"][i]["s"][i == 0 ? 0 : 1].get<double>();
    };
    const auto estimate = [](const nlohmann::json& m, size_t i) {
        const auto& mode = m["modes"][i];
        return mode["check"].value("error_estimate", 0.0) *
               std::hypot(mode["s"][0].get<double>(), mode["s"][1].get<double>());
    };
    BOOST_REQUIRE(d["modes"][0]["frequency_hz"].get<double>() == 0.0);  // the divergence
    b.mixed = true;
    for (const comb::Combination& c : comb::all_combinations(false)) {
        if (c.formulation != Formulation::mixed) continue;
        std::vector<nlohmann::json> m;
        for (const int elements : {32, 64, 128}) {
            b.elements = elements;
            m.push_back(test::run_spinning_case(test::spinning_beam_case(analysis, b),
                                                {"discretization.rotation=" + c.rotation_name()}));
            BOOST_REQUIRE(test::solved(m.back()));
        }
        for (size_t i = 0; i < 4; ++i) {
            BOOST_TEST_CONTEXT(c.label() << ", mode " << i + 1 << ": " << m[2]["message"]) {
                BOOST_REQUIRE(m[2]["modes"][i]["check"]["accepted"].get<bool>());
                const double r1 = part(m[1], i) + (part(m[1], i) - part(m[0], i)) / 3.0;
                const double r2 = part(m[2], i) + (part(m[2], i) - part(m[1], i)) / 3.0;
                const double allowed = std::abs(r2 - r1) + estimate(d, i) + estimate(m[2], i);
                BOOST_TEST_MESSAGE(c.label()
                                   << ", mode " << i + 1 << ": mixed " << std::setprecision(10)
                                   << r2 << " against " << part(d, i) << ", difference "
                                   << r2 - part(d, i) << ", allowed " << allowed);
                BOOST_TEST(std::abs(r2 - part(d, i)) <= allowed);
            }
        }
    }
}

// Modes about a loaded static state are a growth question too: a column compressed past its
// buckling load stands straight (the straight state solves the static equations at any load) but
// diverges, s real and positive. The mixed formulation used to keep only oscillatory eigenvalues
// about a non-spinning state, so its first mode there was the next vibration, `converged`, and the
// divergence went unreported. Below and above P_E = π²EI/(4L²), every combination of both
// formulations against the closed form (above: s² the root of the shooting determinant; below:
// the lowest vibration ω). The beam: EI = 1 about both axes, EA = GA = 1e6, m = 1, rotary inertia
// 1e-6: shear and axial compliance and rotary inertia move the closed form by a relative ~1e-5
// (EI/(GA L²) = 1e-6, P/EA ≈ 4e-6 of the length in P_E ∝ 1/L², ρI/(m L²) = 1e-6), and at 0.5 or
// 1.5 P_E, s² ∝ P/P_E − 1 amplifies them at most 3×. Tolerances: displacement (4 elements of
// order 8, spectral: its mesh error is far below) 1e-4 relative; mixed (kMixedElements elements,
// second order) 1e-3 relative: its mesh error on P_E, amplified in s by P/(2(P − P_E)), measured
// 5.1e-4 (s = 2.65533 against 2.65669) and 4.5e-4 on ω at 0.5 P_E. Measured displacement: s and ω
// equal to the closed form's 6 printed digits. The mixed run of 63e469b reports 3.053 Hz as the
// first mode above P_E: no divergence.
BOOST_AUTO_TEST_CASE(a_column_past_its_buckling_load_diverges_in_both_formulations) {
    const double P_E = std::numbers::pi * std::numbers::pi / 4.0;
    for (const double factor : {0.5, 1.5}) {
        const double P = factor * P_E;
        const bool buckled = factor > 1.0;
        // μ = s²: for 1.5 P_E the divergence μ = 7.058 (s = 2.657), for 0.5 P_E the vibration
        // μ = −6.424 (ω = 2.535), each the only root in its bracket (a scan of D over [−20, 20]).
        const double mu =
            buckled ? cantilever_column_mu(P, 0.5, 20.0) : cantilever_column_mu(P, -20.0, -0.5);
        const double exact = std::sqrt(std::abs(mu));
        for (const comb::Combination& c : comb::all_combinations(false)) {
            test::SpinningBeam b = beam_along_its_spin(1.0);
            b.mixed = c.formulation == Formulation::mixed;
            if (b.mixed) b.elements = kMixedElements;
            std::ostringstream load;
            load << std::setprecision(17) << "  compression: {point: tip, force: [" << -P
                 << ", 0, 0], frame: dead}\n";
            b.loads = load.str();
            const nlohmann::json r = test::run_spinning_case(
                test::spinning_beam_case("  type: modal\n  modes: 4\n  load_factors: [1.0]\n", b),
                {"discretization.rotation=" + c.rotation_name()});
            BOOST_TEST_CONTEXT(c.label() << ", P/P_E " << factor << ": " << r["status"] << " "
                                         << r.value("message", "")) {
                BOOST_REQUIRE(test::solved(r));
                const nlohmann::json& first = r["modes"][0];
                const double growth = first["growth_rate"].get<double>();
                const double omega = 2.0 * std::numbers::pi * first.value("frequency_hz", -1.0);
                BOOST_TEST_MESSAGE(c.label() << ", P/P_E " << factor << ": first s = (" << growth
                                             << ", " << omega << "), closed form "
                                             << (buckled ? "s = " : "ω = ") << exact);
                const double tolerance = b.mixed ? 1e-3 : 1e-4;
                const bool flutter_said =
                    r["message"].get<std::string>().find("flutter") != std::string::npos;
                if (buckled) {
                    BOOST_TEST(std::abs(growth - exact) <= tolerance * exact);
                    BOOST_TEST(std::abs(omega) <= tolerance * exact);
                    BOOST_TEST(flutter_said);
                } else {
                    BOOST_TEST(std::abs(omega - exact) <= tolerance * exact);
                    BOOST_TEST(std::abs(growth) <= tolerance * exact);
                    BOOST_TEST(!flutter_said);
                }
            }
        }
    }
}

// A cantilever turning about x with gravity in its plane of rotation (L = 10, EI = 1e6 and 2e6,
// one element of order 5): its loads have a potential (gravity, the centrifugal load), so the
// model's modes neither grow nor decay. The deformed state's K is not symmetric (the displacement
// formulation's Petrov–Galerkin weak form: a discretization error, docs/rotating-frame.md), and
// its skew part through the Coriolis coupling gave mode 2 Re s = 1.7e-10 1/s against an estimate
// of 4e-15 |s|: "flutter or divergence". The skew part's first-order move now joins the estimate:
// no growth counted, each |Re s| within it, the estimate still ≤ 1e-6 |s| (check_no_growth).
BOOST_AUTO_TEST_CASE(gravity_in_the_plane_of_rotation_is_no_flutter) {
    const std::string text = R"(name: gravity-spin
points: {root: [0, 0, 0], tip: [0, 0, 10]}
sections:
  s:
    stiffness: [[1e9, 0, 0, 0, 0, 0], [0, 1e8, 0, 0, 0, 0], [0, 0, 1e8, 0, 0, 0],
                [0, 0, 0, 1e6, 0, 0], [0, 0, 0, 0, 2e6, 0], [0, 0, 0, 0, 0, 1e6]]
    mass: [[10, 0, 0, 0, 0, 0], [0, 10, 0, 0, 0, 0], [0, 0, 10, 0, 0, 0],
           [0, 0, 0, 2, 0, 0], [0, 0, 0, 0, 1, 0], [0, 0, 0, 0, 0, 1]]
members:
  beam: {from: root, to: tip, section: s, elements: 1}
constraints: {root: clamped}
gravity: [0, -9.8, 0]
rotating_frame: {angular_velocity: [1, 0, 0], center: [0, 0, 0]}
analysis: {type: modal, modes: 4, about_static_state: true}
discretization: {formulation: displacement, order: 5}
)";
    const nlohmann::json r = test::run_spinning_case(text);
    BOOST_TEST_CONTEXT(r["status"] << " " << r.value("message", "")) {
        BOOST_TEST(test::solved(r));
        BOOST_TEST(r["modal"].value("stiffness_asymmetry", 0.0) > 0.0);
        check_no_growth(r, false);
    }
}

BOOST_AUTO_TEST_SUITE_END()
