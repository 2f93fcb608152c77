// The dynamic estimate of a run whose supports turn at constant angular velocity measures the
// motion relative to the turning frame (estimates/history_estimate.hpp): its amplitudes are the
// relative motion's, not the rigid turn's, so its verdict is that of the elastic error.
//
// The case: a uniform beam (L = 1, m = 1, EA = 576, EI = GJ = 1) turning at Ω = 12 about z with a
// hub radius R0 = 0.5, released at its spinning equilibrium (initial_state: static), one element.
// The exact relative motion is the centrifugal stretch at rest in the frame, closed form
// u(1) = −(R0 + 1) + C sin k + R0 cos k, k = Ω/√EA (docs/rotating-frame.md), with no rotation.
// In inertial axes the tip turns by Ω t = 1.2 rad over the run, so its inertial displacement
// amplitude (1.79) is eleven times the relative one (0.162): an error relative to it looks small.
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <string>

#include "cases/loader/case_loader.hpp"
#include "core/so3.hpp"
#include "estimates/history_estimate.hpp"
#include "runs/history_csv.hpp"
#include "runs/run_case.hpp"
#include "tests/cases/spinning_beam.hpp"

namespace rotbeam {

namespace {

using json = nlohmann::json;

constexpr double kOmega = 12.0, kR0 = 0.5, kEA = 576.0;

double stretch_tip() {
    const double k = kOmega / std::sqrt(kEA);
    const double C = (1.0 + kR0 * k * std::sin(k)) / (k * std::cos(k));
    return -(kR0 + 1.0) + C * std::sin(k) + kR0 * std::cos(k);
}

json estimated_spinning_beam(int order) {
    test::SpinningBeam b;
    b.stiffness = {kEA, kEA, kEA, 1.0, 1.0, 1.0};
    b.angular_velocity = Vec3(0, 0, kOmega);
    b.center = Vec3(-kR0, 0, 0);
    b.order = order;
    const std::string text = test::spinning_beam_case(
        "  type: dynamic\n  time_step: 0.01\n  end_time: 0.1\n  initial_state: static\n", b);
    RunRequest request;
    request.case_path = "spinning-beam.yaml";
    request.model = load_case_text(text, "spinning-beam.yaml", {});
    json result = run_case(request);
    add_run_estimate(request, result);
    return result;
}

Vec3 vec(const json& j) { return {j[0].get<double>(), j[1].get<double>(), j[2].get<double>()}; }

// The largest ‖u_rel − u_exact‖ and ‖u_rel‖ of the tip over the history.
std::pair<double, double> true_error_and_amplitude(const json& r) {
    const Vec3 exact(stretch_tip(), 0, 0);
    double error = 0.0, amplitude = 0.0;
    for (const json& s : r["steps"]) {
        const Vec3 u = vec(s["rotating_frame"]["points"]["tip"]["displacement"]);
        error = std::max(error, (u - exact).norm());
        amplitude = std::max(amplitude, u.norm());
    }
    return {error, amplitude};
}

}  // namespace

BOOST_AUTO_TEST_SUITE(turning_estimate)

// Order 1: the tip's relative displacement is up to 0.050 off the closed form (29 % of its
// amplitude 0.174) and the section turns by 0.086 rad where the exact beam does not turn at all
// (its rotation history is all error). Against the inertial amplitudes (1.75, and the 1.2 rad
// turn) these errors were 3 % and 7 % and the run said `converged`; relative to the frame the
// rotation's estimated error is its whole amplitude, far past half of it: `inaccurate`, naming the
// rotation history.
BOOST_AUTO_TEST_CASE(a_coarse_turning_run_is_inaccurate) {
    const json r = estimated_spinning_beam(1);
    const auto [error, amplitude] = true_error_and_amplitude(r);
    BOOST_TEST_MESSAGE("order 1: true tip error " << error << " of amplitude " << amplitude << "; "
                                                  << r["message"].get<std::string>());
    BOOST_TEST(r["status"].get<std::string>() == estimate::kInaccurate);
    BOOST_TEST(r["message"].get<std::string>().find("tip rotation history") != std::string::npos);
    BOOST_TEST(r["estimate"]["motion"].get<std::string>() == "relative to the turning frame");
    // The amplitude is the relative motion's: the largest ‖u_rel‖ (the same maximum, to the bit).
    const json& h = r["estimate"]["history"]["tip"]["displacement"];
    BOOST_TEST(h["amplitude"].get<double>() == amplitude);
    // The true relative error is one a user must be warned of: above 10 % of the amplitude.
    BOOST_TEST(error > 0.1 * amplitude);
    // The CSV history carries the relative motion the estimate columns refer to.
    const std::string csv = history_csv(r);
    const std::string header = csv.substr(0, csv.find('\n'));
    BOOST_TEST(header.find(",tip_angle,") != std::string::npos);
    BOOST_TEST(header.find(",tip_rel_ux,tip_rel_uy,tip_rel_uz,tip_rel_rx,tip_rel_ry,tip_rel_rz,"
                           "tip_rel_angle,") != std::string::npos);
}

// Orders 2, 3, 4: true errors 3.1e-4, 2.4e-8, 2.0e-10 (each under half the one before: the
// p-sequence is asymptotic, the criterion of docs/error-estimates.md). Orders 3 and 4 are
// `converged` (order 2 keeps a spurious tip rotation of 6e-4 rad, its whole amplitude, and is
// `inaccurate`, rightly), and the p+1 estimate of the relative tip displacement against the closed
// form has an effectivity in [0.5, 2] (measured 0.992 and 0.999). Order 5 (true error 1.6e-13)
// is at the floor where the released state is held only to the Newton tolerance: not asymptotic.
BOOST_AUTO_TEST_CASE(a_fine_turning_run_is_converged_with_effectivity_near_one) {
    for (int order : {3, 4}) {
        const json r = estimated_spinning_beam(order);
        const auto [error, amplitude] = true_error_and_amplitude(r);
        const json& h = r["estimate"]["history"]["tip"]["displacement"];
        const double effectivity = h["max_error"].get<double>() / error;
        BOOST_TEST_MESSAGE("order " << order << ": " << r["status"].get<std::string>() << ", true "
                                    << error << ", estimated " << h["max_error"].get<double>()
                                    << ", effectivity " << effectivity);
        BOOST_TEST(r["status"].get<std::string>() == "converged", r["message"].get<std::string>());
        BOOST_TEST(h["amplitude"].get<double>() == amplitude);
        BOOST_TEST(effectivity >= 0.5);
        BOOST_TEST(effectivity <= 2.0);
    }
}

// BeamDyn's rotating-cantilever deck (tests/data/beamdyn/rotating-cantilever: the twisted
// cantilever under gravity, its root turning at 1 rad/s about x for 0.2 s). Its relative tip
// rotation is small (2.2e-4 rad at convergence) beside the 0.2 rad turn.
//  - At the deck's own discretization (1 element of order 5, Δt = 0.01 s) the run shows a relative
//    tip rotation of 0.021 rad, a hundred times the converged one: its error is its whole
//    amplitude. Measured against the inertial amplitude (the turn) it was 0.12 and the run said
//    `converged`; now `inaccurate`.
//  - Refined (8 elements of order 6, Δt = 0.002 s) it is `converged`, and its estimate is compared
//    with a reference of 16 elements of order 8 at Δt = 0.0005 s, itself `converged` with an
//    estimated error at most a tenth of the refined run's true error (so the "true" error is known
//    to 10 %). The sequence 2, 4, 8 elements of order 6 at Δt = 0.002 s has true tip rotation
//    errors 1.2e-3, 1.4e-4, 1.7e-6 rad (each under half the one before: asymptotic), and at 8
//    elements the effectivities are 1.07 (displacement) and 0.99 (rotation): asserted in [0.5, 2].
json estimated_deck(const std::vector<std::string>& overrides) {
    const std::string path =
        std::string(ROTBEAM_SOURCE_DIR) + "/tests/data/beamdyn/rotating-cantilever/bd_driver.inp";
    RunRequest request;
    request.case_path = path;
    request.model = load_case(path, overrides);
    json result = run_case(request);
    add_run_estimate(request, result);
    return result;
}

// The largest distance and rotation angle between the tip's relative motions of two runs at their
// common output times.
std::pair<double, double> tip_difference(const json& a, const json& b) {
    double du = 0.0, dr = 0.0;
    for (const json& s : a["steps"]) {
        for (const json& t : b["steps"]) {
            if (std::abs(s["time"].get<double>() - t["time"].get<double>()) > 1e-9) continue;
            const json& p = s["rotating_frame"]["points"]["tip"];
            const json& q = t["rotating_frame"]["points"]["tip"];
            du = std::max(du, (vec(p["displacement"]) - vec(q["displacement"])).norm());
            Mat3 Rp, Rq;
            for (int i = 0; i < 3; ++i) {
                Rp.row(i) = vec(p["rotation_matrix"][static_cast<std::size_t>(i)]).transpose();
                Rq.row(i) = vec(q["rotation_matrix"][static_cast<std::size_t>(i)]).transpose();
            }
            dr = std::max(dr, so3::rotation_angle(Rp.transpose() * Rq));
        }
    }
    return {du, dr};
}

BOOST_AUTO_TEST_CASE(the_beamdyn_turning_deck_coarse_is_inaccurate_refined_is_converged) {
    const json coarse = estimated_deck({});
    BOOST_TEST_MESSAGE("deck as given: " << coarse["message"].get<std::string>());
    BOOST_TEST(coarse["status"].get<std::string>() == estimate::kInaccurate);
    BOOST_TEST(coarse["message"].get<std::string>().find("tip rotation history") !=
               std::string::npos);

    const json fine = estimated_deck(
        {"members.*.elements=8", "discretization.order=6", "analysis.time_step=0.002"});
    const json reference =
        estimated_deck({"members.*.elements=16", "discretization.order=8",
                        "analysis.time_step=0.0005", "analysis.output_interval=0.002"});
    BOOST_TEST(fine["status"].get<std::string>() == "converged",
               fine["message"].get<std::string>());
    BOOST_TEST(reference["status"].get<std::string>() == "converged",
               reference["message"].get<std::string>());
    const auto [true_u, true_r] = tip_difference(fine, reference);
    const json& h = fine["estimate"]["history"]["tip"];
    const json& hr = reference["estimate"]["history"]["tip"];
    const double eff_u = h["displacement"]["max_error"].get<double>() / true_u;
    const double eff_r = h["rotation"]["max_error"].get<double>() / true_r;
    BOOST_TEST_MESSAGE("refined: true " << true_u << " m, " << true_r << " rad; effectivity "
                                        << eff_u << ", " << eff_r << "; reference estimate "
                                        << hr["displacement"]["max_error"].get<double>() << " m, "
                                        << hr["rotation"]["max_error"].get<double>() << " rad");
    BOOST_TEST(hr["displacement"]["max_error"].get<double>() <= 0.1 * true_u);
    BOOST_TEST(hr["rotation"]["max_error"].get<double>() <= 0.1 * true_r);
    BOOST_TEST(eff_u >= 0.5);
    BOOST_TEST(eff_u <= 2.0);
    BOOST_TEST(eff_r >= 0.5);
    BOOST_TEST(eff_r <= 2.0);
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace rotbeam
