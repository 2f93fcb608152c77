// The manufactured solution of the semi-discrete equations (studies/semi_discrete_forcing.hpp,
// studies/manufactured_semi_discrete.hpp): the manufactured motion's mesh trajectory y_h(t) made
// exact by the forcing −R_h(t, y_h, ẏ_h, ÿ_h) and started at y_h(0), so the error against y_h(t_n)
// is the time scheme's alone and the start is consistent. Observed orders per component (u, R, v;
// mixed also F) of every scheme for every combination, Newton tolerance ≤ 1e-12, against the
// schemes' orders. docs/studies.md "Manufactured motion" has the table.
#include <algorithm>
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "combinations/registry.hpp"
#include "parameterizations/registry.hpp"
#include "studies/manufactured_motion_runs.hpp"
#include "studies/manufactured_semi_discrete.hpp"

using namespace rotbeam;

namespace {

// The components a formulation's runs have (ComponentDifferences' table order; the displacement
// formulation has no internal forces F).
std::vector<int> components_of(const cli::MotionRunSpec& spec) {
    if (spec.formulation == Formulation::mixed) return {0, 1, 2, 3, 4, 5};
    return {0, 1, 2, 4, 5};
}

// The series of spec's scheme with its table printed.
cli::SemiDiscreteResult series_of(const cli::MotionRunSpec& spec) {
    const cli::SemiDiscreteResult r = cli::run_semi_discrete_series(spec);
    for (size_t i = 0; i < r.dt.size(); ++i) {
        std::printf("%-44s dt %.5f:", spec.label().c_str(), r.dt[i]);
        for (const int k : components_of(spec)) {
            std::printf(" %s %.3e", cli::component_name(k), cli::component(r.error[i], k));
            if (i > 0) std::printf(" (%.2f)", cli::component(r.pair[i - 1], k));
        }
        std::printf("\n");
    }
    std::printf("%-44s order (LS):", spec.label().c_str());
    for (const int k : components_of(spec)) std::printf(" %.3f", cli::component(r.order, k));
    std::printf("\n");
    return r;
}

// Every step ran, and each component's least-squares order over the series lies within 0.2 of
// the scheme's order, except the components `skipped` (documented exceptions) and `last_pair`,
// whose last pair alone is asserted within 0.2 (a component pre-asymptotic at the coarse steps
// whose finer step would reach the round-off floor).
void check_orders(const cli::MotionRunSpec& spec, const std::vector<int>& skipped = {},
                  const std::vector<int>& last_pair = {}) {
    const cli::SemiDiscreteResult r = series_of(spec);
    const cli::SemiDiscreteSeries series = cli::semi_discrete_series(spec);
    BOOST_TEST_REQUIRE(r.dt.size() == series.steps.size(), spec.label() << ": " << r.note);
    const auto in = [](const std::vector<int>& v, int k) {
        return std::find(v.begin(), v.end(), k) != v.end();
    };
    for (const int k : components_of(spec)) {
        if (in(skipped, k)) continue;
        if (in(last_pair, k)) {
            const double q = cli::component(r.pair.back(), k);
            BOOST_TEST(std::abs(q - series.order) < 0.2,
                       spec.label() << " " << cli::component_name(k) << ": last pair " << q);
            continue;
        }
        BOOST_TEST(std::abs(cli::component(r.order, k) - series.order) < 0.2,
                   spec.label() << " " << cli::component_name(k) << ": order "
                                << cli::component(r.order, k) << " against " << series.order);
    }
}

cli::MotionRunSpec displacement_spec(ParameterizationId rotation, Integrator integrator) {
    cli::MotionRunSpec spec;
    spec.rotation = rotation;
    spec.integrator = integrator;
    spec.order = 3;
    spec.elements = 2;
    spec.motion = cli::motion_within_reach(Formulation::displacement, rotation);
    return spec;
}

std::vector<cli::MotionRunSpec> mixed_specs(Integrator integrator) {
    std::vector<cli::MotionRunSpec> out;
    for (const comb::Combination& c : comb::all_combinations(false, true)) {
        if (c.formulation != Formulation::mixed) continue;
        cli::MotionRunSpec spec;
        spec.formulation = Formulation::mixed;
        spec.rotation = c.rotation;
        spec.wm_map = c.wm_map.value_or(WmMap::plain);
        spec.integrator = integrator;
        spec.elements = 8;
        spec.motion = cli::motion_within_reach(Formulation::mixed, c.rotation);
        out.push_back(spec);
    }
    return out;
}
// The schemes' checks over a set of combinations (the verification suite: one per formulation
// and scheme; the long suite: every one).

// Lie-group generalized-α, ρ∞ = 0.5 and 1, Δt = 0.025 … 0.00625 (p = 3, 2 elements per member).
// Second order in u, R and v with the consistent start (a_0 = v˙_0, here v˙_h(0) from the forced
// initial acceleration); measured 1.99–2.02 (docs/studies.md). ± 0.2 fails on a first-order start
// or scheme.
void check_generalized_alpha(const std::vector<ParameterizationId>& rotations) {
    for (const ParameterizationId r : rotations) {
        for (double rho : {0.5, 1.0}) {
            cli::MotionRunSpec spec = displacement_spec(r, Integrator::generalized_alpha);
            spec.rho_infinity = rho;
            check_orders(spec);
        }
    }
}

// Gauss–Legendre collocation (RKMK), 2 stages: order 4 in u, R, v over Δt = 0.05 … 0.0125
// (measured 3.92–4.02). From the continuum's exact start a floor of ~1e-3 in v stopped it at 0.4.
void check_gauss_legendre_2(const std::vector<ParameterizationId>& rotations) {
    for (const ParameterizationId r : rotations) {
        check_orders(displacement_spec(r, Integrator::gauss_legendre_2));
    }
}

// Gauss–Legendre, 3 stages, Δt = 0.1 … 0.0125, Newton tolerance 1e-14: no clean order 6 on this
// motion (measured pairs, quaternion, u: 4.21, 7.65, 6.46; R 3.75, 7.94, 6.36; v 2.44, 8.29, 6.98).
// The rod's own modes (ω ≈ 10–40 rad/s and up: the first axial and bending modes of the free rod)
// are unresolved at the coarse steps, where the scheme's stage order 3 sets the error (order ≈ s +
// 1 = 4); once they resolve the error falls faster than h⁶, and below Δt ≈ 0.0125 it reaches the
// floor the stage iteration's tolerance leaves. Asserted one-sidedly, not within 0.2: the last two
// pairs of every component reach 6 − 0.2 (a drop of the order, e.g. to 4, fails it), a pair left
// out when its finer run is at that floor: its error moves by more than a tenth of itself when the
// Newton tolerance is loosened tenfold (1e-13). Measured 2026-11-28 at 0.0125: the quaternion's u
// 6.9e-12 → 7.4e-11, Rodrigues' 2.9e-11 → 5.3e-11 (pairs 6.04 and 3.90: both at the floor, which
// for Rodrigues' chart and motion lies ~4× higher; a fixed threshold of 1e-11 missed it); at 0.025
// 4.33e-10 → 4.34e-10 (above the floor).
void check_gauss_legendre_3(const std::vector<ParameterizationId>& rotations) {
    for (const ParameterizationId r : rotations) {
        const cli::MotionRunSpec spec = displacement_spec(r, Integrator::gauss_legendre_3);
        const cli::SemiDiscreteResult res = series_of(spec);
        BOOST_TEST_REQUIRE(res.pair.size() == 3u, spec.label() << ": " << res.note);
        for (size_t i = 1; i < res.pair.size(); ++i) {
            cli::MotionRunSpec looser = spec;
            looser.semi_discrete = true;
            looser.dt = res.dt[i + 1];
            looser.newton_tolerance = 1e-13;
            const cli::MotionRunResult loose = cli::run_manufactured_motion(looser);
            BOOST_TEST_REQUIRE(loose.ok(), looser.label() << ": " << loose.message);
            for (const int k : components_of(spec)) {
                const double tight = cli::component(res.error[i + 1], k);
                const double moved = std::abs(cli::component(loose.semi_discrete_error, k) - tight);
                if (moved > 0.1 * tight) {
                    std::printf(
                        "%-44s pair %zu, %s: at the stage iteration's floor (%.3e at 1e-14, "
                        "%.3e at 1e-13)\n",
                        spec.label().c_str(), i, cli::component_name(k), tight,
                        cli::component(loose.semi_discrete_error, k));
                    continue;
                }
                BOOST_TEST(cli::component(res.pair[i], k) > 5.8,
                           spec.label() << " " << cli::component_name(k) << " pair " << i);
            }
        }
    }
}

// Gauss–Legendre 3 where order 6 is observable: the same mesh and motion with every rate ×8 (the
// motion at 8t: ω₁ = 16, ω₂ = 24 rad/s, spin rate ×8, spin acceleration ×64) over 0–0.25 s (the
// default motion's 0–2 s), Rodrigues over 0–0.125 s (its motion within reach over 0–1 s: largest
// angle 2.7 rad; over 0.25 s it reaches π). The motion's time error grows as (8Δt)⁶ while the rod's
// own modes (ω ≈ 40 rad/s, its first bending mode, and up) keep their frequencies, so at Δt =
// 0.0125 → 0.00625 (ωΔt ≤ 0.5 for that mode) the error lies far above the round-off floor (u
// 9.4e-10 at 0.00625 against 5e-12 on the default motion) and the unresolved higher mesh modes,
// which enter at the Prothero–Robinson order s + 1 = 4 (docs/studies.md), stay below it. That pair
// must lie within 0.2 of 6 in u, R and v; measured 5.96–6.00 for every parameterization
// (docs/studies.md). With rates ×4 over 0–0.5 s the same pair gave v 5.80–5.82 (Euler angles 5.797,
// outside 0.2): those modes' share in the momenta, ∝ 1/ω rather than 1/ω², is not yet negligible.
void check_gauss_legendre_3_fast_motion(const std::vector<ParameterizationId>& rotations) {
    const double k = 8.0;
    for (const ParameterizationId rotation : rotations) {
        cli::MotionRunSpec spec = displacement_spec(rotation, Integrator::gauss_legendre_3);
        spec.motion.omega1 *= k;
        spec.motion.omega2 *= k;
        spec.motion.spin_rate *= k;
        spec.motion.spin_acceleration *= k * k;
        spec.end_time = rotation == param::id_of<param::Rodrigues>() ? 1.0 / k : 2.0 / k;
        spec.semi_discrete = true;
        spec.newton_tolerance = 1e-14;
        cli::ComponentDifferences e[2];
        const double steps[2] = {0.0125, 0.00625};
        for (int i = 0; i < 2; ++i) {
            spec.dt = steps[i];
            const cli::MotionRunResult r = cli::run_manufactured_motion(spec);
            BOOST_TEST_REQUIRE(r.ok(), spec.label() << " Δt " << steps[i] << ": " << r.message);
            e[i] = r.semi_discrete_error;
        }
        for (const int c : components_of(spec)) {
            const double q = std::log2(cli::component(e[0], c) / cli::component(e[1], c));
            std::printf("%-44s fast motion, Δt 0.0125 → 0.00625: %s %.3e → %.3e (%.3f)\n",
                        spec.label().c_str(), cli::component_name(c), cli::component(e[0], c),
                        cli::component(e[1], c), q);
            BOOST_TEST(std::abs(q - 6.0) < 0.2, spec.label()
                                                    << " fast motion " << cli::component_name(c)
                                                    << ": order " << q);
        }
    }
}

// Mixed formulation, 8 elements per member, Δt = 0.05 … 0.0125: the trapezoidal rule second order
// and Radau IIA (3 stages) fifth order in every component, the internal forces F, M (algebraic)
// included: the free rod's DAE is index 1 (docs/mixed-dynamics.md "Index"), for which Radau IIA
// keeps order 2s − 1 = 5 in the algebraic components too (Hairer & Wanner II §VI.1). From the
// continuum's exact start Radau showed no order at all. The momenta are asserted whole (v) and by
// halves, P (vt) and H (vr), each relative to its own largest value: a half whose values are
// smaller than the other's can depart from the order while v, set by the larger, does not.
// Exceptions (measured 2026-11-28, docs/studies.md):
//  - WM with the continuous map is C¹ only where the angle passes π (its map θ ↦ c,
//    parameterizations/wiener_milenkovic_continuous.hpp), which this motion does: Radau shows no
//    order (4.4, then 0.0 in u) and is not checked; the trapezoidal rule keeps 2 in u, R, v, F but
//    its H reads 1.70, 1.70 (not pre-asymptotic: the map's defect), left out;
//  - Radau, half pre-asymptotic at the coarse step, asserted by its last pair: WM's H 3.92, 5.05;
//    Rodrigues' P 4.36, 4.82 (its steps 0.025 … 0.00625) and its forces 6.15 (0.05 → 0.025),
//    5.73, 5.06, their excess over 5 falling towards 0, the next halving (0.003125) at the
//    round-off floor (F 4.7e-12, pair 2.67, u 6.9e-13); the Euler angles' H 3.83, 4.96;
//  - Radau, the Euler angles' P 4.92, 4.33 (4.60 at 0.0125 → 0.00625, the same digits at a Newton
//    tolerance of 1e-14, so not the stage iteration's floor; not the start either: at t = 0.025,
//    after 1, 2, 4 steps, the momenta error keeps 5.0), and with it v: left out here, the order
//    shown where every mode of the mesh is resolved (check_mixed_euler_momenta_resolved).
void check_mixed(const std::vector<cli::MotionRunSpec>& specs) {
    constexpr int v = 2, F = 3, P = 4, H = 5;
    for (const cli::MotionRunSpec& spec : specs) {
        const bool radau = spec.integrator == Integrator::radau_iia_3;
        if (radau && spec.wm_map == WmMap::continuous) continue;
        std::vector<int> skipped, last_pair;
        if (spec.wm_map == WmMap::continuous) skipped = {H};
        if (radau && spec.rotation == param::id_of<param::WienerMilenkovic>()) last_pair = {H};
        if (radau && spec.rotation == param::id_of<param::Rodrigues>()) last_pair = {F, P};
        if (radau && spec.rotation == param::id_of<param::EulerAngles>()) {
            skipped = {v, P};
            last_pair = {H};
        }
        check_orders(spec, skipped, last_pair);
    }
}

// The mixed runs of one scheme: every combination, or those of `rotations` (plain WM map).
std::vector<cli::MotionRunSpec> mixed_of(Integrator scheme,
                                         const std::vector<ParameterizationId>& rotations) {
    std::vector<cli::MotionRunSpec> out;
    for (const cli::MotionRunSpec& spec : mixed_specs(scheme)) {
        for (const ParameterizationId r : rotations) {
            if (spec.rotation == r && spec.wm_map == WmMap::plain) out.push_back(spec);
        }
    }
    return out;
}

// The Euler angles' momenta under Radau IIA where every mode of the mesh is resolved: 2 elements
// per member and the section stiffness × 0.01, which puts every mesh mode at ωΔt ≤ 0.25 over the
// steps 0.05 … 0.00625 (docs/studies.md, "The Euler angles' Radau momenta"), Newton tolerance
// 1e-14 so that the finest step's errors stay above the stage iteration's floor. Measured
// (2026-11-28), pairs: u 5.10, 4.94, 4.98; R 5.40, 4.87, 4.95; F 5.92, 4.88, 4.93; P 4.94, 4.98,
// 4.99; H 4.38, 4.63, 4.87, rising monotonically towards 5: a higher-order term of the opposite
// sign dying out, where an O(h⁴) term would pull them down towards 4. Asserted: the last two pairs
// of u, R, F and P within 0.2 of 5 (the first pair from 0.05 is pre-asymptotic in R and F), H's
// pairs increasing and its last within 0.2 of 5.
void check_mixed_euler_momenta_resolved() {
    cli::MotionRunSpec spec =
        mixed_of(Integrator::radau_iia_3, {param::id_of<param::EulerAngles>()}).front();
    spec.elements = 2;
    spec.motion.stiffness *= 0.01;
    spec.semi_discrete = true;
    spec.newton_tolerance = 1e-14;
    const std::vector<double> steps = {0.05, 0.025, 0.0125, 0.00625};
    std::vector<cli::ComponentDifferences> e;
    for (const double dt : steps) {
        spec.dt = dt;
        const cli::MotionRunResult r = cli::run_manufactured_motion(spec);
        BOOST_TEST_REQUIRE(r.ok(), spec.label() << " Δt " << dt << ": " << r.message);
        e.push_back(r.semi_discrete_error);
    }
    constexpr int v = 2, H = 5;
    for (const int k : components_of(spec)) {
        if (k == v) continue;  // the larger of P and H, asserted through them
        std::printf("%-44s section × 0.01, %s:", spec.label().c_str(), cli::component_name(k));
        double previous = 0.0;
        for (size_t i = 1; i < steps.size(); ++i) {
            const double q = std::log2(cli::component(e[i - 1], k) / cli::component(e[i], k));
            std::printf(" %.3e → %.3e (%.2f)", cli::component(e[i - 1], k), cli::component(e[i], k),
                        q);
            const bool last = i + 1 == steps.size();
            if (k == H) {
                BOOST_TEST(q > previous, spec.label() << " H: pair " << i << " " << q
                                                      << " not above the previous " << previous);
                if (last)
                    BOOST_TEST(std::abs(q - 5.0) < 0.2, spec.label() << " H: last pair " << q);
            } else if (i >= 2) {
                BOOST_TEST(std::abs(q - 5.0) < 0.2, spec.label() << " " << cli::component_name(k)
                                                                 << ": pair " << i << " " << q);
            }
            previous = q;
        }
        std::printf("\n");
    }
}

const std::vector<ParameterizationId> kSample = {param::id_of<param::Quaternion>(),
                                                 param::id_of<param::WienerMilenkovic>()};

}  // namespace

// One combination per formulation and scheme (the quaternion; mixed also plain WM): 4 CPU-s.
BOOST_AUTO_TEST_SUITE(semi_discrete_motion)

BOOST_AUTO_TEST_CASE(generalized_alpha_is_second_order) {
    check_generalized_alpha({param::id_of<param::Quaternion>()});
}
BOOST_AUTO_TEST_CASE(gauss_legendre_2_is_fourth_order) {
    check_gauss_legendre_2({param::id_of<param::Quaternion>()});
}
BOOST_AUTO_TEST_CASE(gauss_legendre_3_reaches_order_six_after_the_rods_modes_resolve) {
    check_gauss_legendre_3({param::id_of<param::Quaternion>()});
}
BOOST_AUTO_TEST_CASE(gauss_legendre_3_is_sixth_order_on_a_fast_motion) {
    check_gauss_legendre_3_fast_motion({param::id_of<param::Quaternion>()});
}
BOOST_AUTO_TEST_CASE(mixed_trapezoidal_is_second_order_in_every_component) {
    check_mixed(mixed_of(Integrator::trapezoidal, kSample));
}
BOOST_AUTO_TEST_CASE(mixed_radau_iia_is_fifth_order_in_every_component) {
    check_mixed(mixed_of(Integrator::radau_iia_3, kSample));
}
BOOST_AUTO_TEST_CASE(mixed_radau_iia_euler_angles_momenta_reach_order_five_once_resolved) {
    check_mixed_euler_momenta_resolved();
}

BOOST_AUTO_TEST_SUITE_END()

// Every combination (16 CPU-s, over 120 s wall at load 10): run by the `long` registration
// test_semi_discrete_motion_every_combination (tests/agreement/CMakeLists.txt), disabled here.
BOOST_AUTO_TEST_SUITE(semi_discrete_motion_every_combination, *boost::unit_test::disabled())

BOOST_AUTO_TEST_CASE(every_displacement_combination) {
    const std::vector<ParameterizationId> all = param::parameterization_ids();
    check_generalized_alpha(all);
    check_gauss_legendre_2(all);
    check_gauss_legendre_3(all);
    check_gauss_legendre_3_fast_motion(all);
}
BOOST_AUTO_TEST_CASE(every_mixed_combination) {
    check_mixed(mixed_specs(Integrator::trapezoidal));
    check_mixed(mixed_specs(Integrator::radau_iia_3));
}

BOOST_AUTO_TEST_SUITE_END()
