// Accuracy control of a dynamic run (docs/accuracy-control.md, "Dynamics") against an independent
// reference: a run asked for accuracy TOL that says it reached it has a true error ≤ TOL in every
// history, relative to the history's amplitude (estimates/accuracy_scale.hpp).
//
// The case: tests/data/cantilever-sine-tip-force.yaml, the free-vibration cantilever driven from
// rest by a tip force 1 N × sin(20 t) over 0–0.25 s. The reference: the linear Timoshenko
// cantilever's modal series (core/oracles/timoshenko.hpp, 40 modes), the tip deflection w(L, t)
// against the run's u_z and the section rotation ψ(L, t) against its rotation about −y. What
// separates it from the continuum model the runs converge to, each far below the smallest TOL here
// (1e-3): the truncated modes, bounded by the oracle's tails (asserted below 1e-5 of the
// amplitudes); the geometric nonlinearity at a deflection of 2e-3 L, O((δ/L)²) ≈ 4e-6 relative
// in the transverse motion; the axial shortening (≈ 2e-6 m, 1e-3 of the deflection), a
// second-order effect the comparison leaves out (u_z only).
//
// Not the free vibration itself (cases/free-vibration.yaml): its release from the discrete static
// state puts every mesh mode into the motion, and resolving their phases is minutes of CPU at any
// TOL (measured: docs/accuracy-control.md, "Dynamics").
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

#include "cases/loader/case_loader.hpp"
#include "core/oracles/timoshenko.hpp"
#include "runs/accuracy_run.hpp"

namespace rotbeam {

namespace {

using json = nlohmann::json;

// The beam of the case: L = 1 m, square h = 0.01 m, E = 2.1e11 Pa, ν = 0.3, κ = 5/6,
// ρ = 7850 kg/m³; the load 1 N × sin(Ω t).
constexpr double kOmega = 20.0;

oracle::TimoshenkoBeam case_beam() {
    const double E = 2.1e11, G = E / 2.6, h = 0.01, rho = 7850.0;
    const double A = h * h, I = h * h * h * h / 12.0;
    return {1.0, E * I, 5.0 / 6.0 * G * A, rho * A, rho * I};
}

struct DrivenRun {
    const char* formulation;
    const char* integrator;
    double tolerance;
};

// The largest error of each history over the largest |reference|.
struct TrueError {
    double deflection = 0.0, rotation = 0.0;
};

TrueError true_error(const json& result, const oracle::TimoshenkoTipModes& modes) {
    double dw = 0.0, dpsi = 0.0, w_max = 0.0, psi_max = 0.0;
    for (const json& step : result["steps"]) {
        const double t = step["time"].get<double>();
        const json& tip = step["points"]["tip"];
        const double w = oracle::sine_tip_deflection(modes, kOmega, t);
        const double psi = oracle::sine_tip_rotation(modes, kOmega, t);
        dw = std::max(dw, std::abs(tip["displacement"][2].get<double>() - w));
        dpsi = std::max(dpsi, std::abs(-tip["rotation_vector"][1].get<double>() - psi));
        w_max = std::max(w_max, std::abs(w));
        psi_max = std::max(psi_max, std::abs(psi));
    }
    return {dw / w_max, dpsi / psi_max};
}

}  // namespace

BOOST_AUTO_TEST_SUITE(dynamic_accuracy_control)

// One row per formulation and kind of scheme (Gauss–Legendre, generalized-α, Radau IIA), measured
// (about 4.5 s of CPU in all): Gauss–Legendre 3 reaches 1e-3 at once (true errors 4.4e-5 and
// 1.6e-4); generalized-α tightens its time tolerance twice (2.5e-3 → 3.6e-5; true 6.4e-4 and
// 1.2e-3 against TOL 1e-2); the mixed formulation refines its elements 8 → 32 → 64 → 128 (its
// tip rotation's space error is 2.2e-2 of the amplitude on 8 elements, and its h/2, h/4 estimate
// stays not reliable, the observed order outside 2 ± 0.5, until 128; true 1.6e-4 and 4.8e-4).
BOOST_AUTO_TEST_CASE(
    a_driven_cantilever_asked_for_an_accuracy_reaches_it_against_the_modal_series) {
    const oracle::TimoshenkoTipModes modes = oracle::timoshenko_tip_modes(case_beam(), 1.0, 40);
    const double factor = oracle::sine_tail_factor(modes, kOmega);
    const double delta = oracle::timoshenko_tip_deflection(case_beam(), 1.0);
    BOOST_TEST_MESSAGE("modal series: truncation <= "
                       << factor * modes.deflection_tail / delta << " (deflection), "
                       << factor * modes.rotation_tail / modes.static_rotation
                       << " (rotation), of the static values");
    // The amplitudes are ≈ δ and ≈ 1.5 δ/L rad (the static tip rotation PL²/2EI is 1.5 δ/L).
    BOOST_TEST(factor * modes.deflection_tail < 1e-5 * delta);
    BOOST_TEST(factor * modes.rotation_tail < 1e-5 * modes.static_rotation);
    const DrivenRun rows[] = {{"displacement", "gauss-legendre-3", 1e-3},
                              {"displacement", "generalized-alpha", 1e-2},
                              {"mixed", "radau-iia-3", 1e-2}};
    const std::string path =
        std::string(ROTBEAM_SOURCE_DIR) + "/tests/data/cantilever-sine-tip-force.yaml";
    for (const DrivenRun& row : rows) {
        std::ostringstream tol;
        tol << std::setprecision(17) << row.tolerance;
        const std::vector<std::string> o = {
            std::string("discretization.formulation=") + row.formulation,
            std::string("analysis.integrator=") + row.integrator, "analysis.accuracy=" + tol.str()};
        const json r = run_to_accuracy(RunRequest{path, load_case(path, o, CaseParts::case_file)});
        const json& a = r["accuracy"];
        const TrueError e = true_error(r, modes);
        std::ostringstream label;
        label << row.formulation << " " << row.integrator << " TOL " << row.tolerance;
        BOOST_TEST_MESSAGE(label.str()
                           << ": " << a["status"].get<std::string>() << ", " << a["chosen"].dump()
                           << ", " << a["attempts"].size() << " attempts, estimates space "
                           << a.value("space_estimate", -1.0) << ", time "
                           << a.value("time_estimate", -1.0) << "; true errors " << e.deflection
                           << " (deflection), " << e.rotation << " (rotation); "
                           << a["wall_seconds"].get<double>() << " s");
        BOOST_TEST(a["status"] == "reached", label.str());
        BOOST_TEST(e.deflection <= row.tolerance, label.str());
        BOOST_TEST(e.rotation <= row.tolerance, label.str());
    }
}

// The budget's time bounds the whole control, not each run: asked for 1e-4, the mixed formulation
// moves from 8 to 128 elements after its first attempt (0.2–0.6 s measured), and that attempt
// (its run 4.3 s, then h/2 and h/4 companions on 256 and 512 elements) takes far longer than
// 5 s, so a 5 s budget must stop inside it, name the budget as the reason and
// answer with the first attempt (8 elements, its histories and estimates), status
// accuracy-not-reached. The whole control within the budget + 1 s: a run checks its limit between
// time steps (a few ms here), but a companion started just before the deadline first builds its
// model and initial state, which is not interrupted (the h/2 companion on 256 elements: 0.16 s
// measured), and the result's bookkeeping follows. Measured: 0.56 s first attempt, the 128-element
// run 4.3 s, 5.16 s in all. A run given the whole budget as its own limit (as before the budget
// was passed to the runs) would let that run converge and each companion run up to 5 s more
// (measured: 18.9 s in all, the check fails). 5 s, not less: the first attempt must finish
// inside the budget also on a slow build (the sanitized tree runs this test
// several times slower).
BOOST_AUTO_TEST_CASE(the_time_budget_stops_an_attempt_that_would_outlast_it) {
    const std::string path =
        std::string(ROTBEAM_SOURCE_DIR) + "/tests/data/cantilever-sine-tip-force.yaml";
    const std::vector<std::string> o = {"discretization.formulation=mixed",
                                        "analysis.integrator=radau-iia-3",
                                        "analysis.accuracy=1e-4"};
    constexpr double kBudget = 5.0;
    RunRequest request{path, load_case(path, o, CaseParts::case_file)};
    request.time_limit_seconds = kBudget;
    const json r = run_to_accuracy(request);
    const json& a = r["accuracy"];
    const std::string reason = a.value("reason", std::string());
    BOOST_TEST_MESSAGE("budget " << kBudget << " s: " << a["attempts"].size() << " attempts, "
                                 << a["wall_seconds"].get<double>() << " s; " << reason);
    BOOST_TEST(r["status"] == "accuracy-not-reached");
    BOOST_TEST(reason.rfind("budget: ", 0) == 0, reason);
    BOOST_TEST(reason.find("the result is the attempt before it") != std::string::npos, reason);
    BOOST_TEST(a["wall_seconds"].get<double>() < kBudget + 1.0);
    BOOST_TEST(a["chosen"]["elements"] == 8);
    BOOST_TEST(r["steps"].size() > 1);
    BOOST_TEST(r["estimate"]["status"] == "estimated");
    BOOST_TEST(a["attempts"].size() == 2);  // the stopped attempt stays in the record
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace rotbeam
