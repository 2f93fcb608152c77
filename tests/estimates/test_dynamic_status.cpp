// The status `inaccurate` of a dynamic run whose time step is far beyond what its estimate can
// vouch for (estimates/history_estimate.hpp), and the estimate columns of the CSV files
// (runs/estimate_columns.hpp), on the free-vibration cantilever (cases/free-vibration.yaml) through
// run_case and add_run_estimate, the path of `rotbeam run`.
//
// Why the steps are what they are, independently of the estimator: the first bending mode is at
// 8.36 Hz (the case's Timoshenko reference, ω₁ = 52.5 rad/s) and the second near 52 Hz (ω₂ ≈ 329
// rad/s); the trapezoidal rule (generalized-α at ρ∞ = 1, and the mixed formulation's scheme)
// lengthens a period by (ωΔt)²/12, so over T = 0.5 s a mode accumulates a phase error
// ω³Δt²T/12. At Δt = 0.02 the first mode's is 2.4 rad (its period is 6 steps): far beyond 1 rad,
// the run must be `inaccurate`. At Δt = 2.5e-4 the second mode's is 0.09 rad and the first's 6e-4:
// the run must keep its solver status and its time estimate be reliable.
#include <boost/test/unit_test.hpp>
#include <sstream>
#include <string>

#include "cases/loader/case_loader.hpp"
#include "core/static_driver.hpp"
#include "estimates/history_estimate.hpp"
#include "runs/history_csv.hpp"
#include "runs/run_case.hpp"
#include "runs/steps_csv.hpp"

namespace rotbeam {

namespace {

using json = nlohmann::json;

json estimated(const std::string& name, const std::vector<std::string>& overrides, bool estimate) {
    const std::string path = std::string(ROTBEAM_SOURCE_DIR) + "/cases/" + name + ".yaml";
    const RunRequest request{path, load_case(path, overrides, CaseParts::case_file)};
    json result = run_case(request);
    if (estimate) {
        add_run_estimate(request, result);
    } else {
        result["estimate"] = estimate_off();
    }
    return result;
}

std::string first_line(const std::string& csv) { return csv.substr(0, csv.find('\n')); }

}  // namespace

BOOST_AUTO_TEST_SUITE(dynamic_status)

BOOST_AUTO_TEST_CASE(inaccurate_is_not_a_solution) {
    // verify, the suite's gate and the estimate itself count only has_solution statuses as passed.
    BOOST_TEST(!has_solution(std::string(estimate::kInaccurate)));
}

BOOST_AUTO_TEST_CASE(a_far_too_large_step_is_inaccurate) {
    for (const char* formulation : {"displacement", "mixed"}) {
        const json r = estimated(
            "free-vibration",
            {"analysis.time_step=0.02", std::string("discretization.formulation=") + formulation},
            true);
        const std::string message = r["message"].get<std::string>();
        BOOST_TEST(r["status"].get<std::string>() == "inaccurate", formulation << ": " << message);
        // One line naming the quantity, the estimate and the criterion.
        BOOST_TEST(message.find('\n') == std::string::npos);
        BOOST_TEST(message.find("tip") != std::string::npos, message);
        BOOST_TEST(message.find("criterion") != std::string::npos, message);
        BOOST_TEST(r["estimate"]["phase_error_rad"].get<double>() > 1.0);
    }
}

BOOST_AUTO_TEST_CASE(a_sane_step_keeps_its_status_and_a_reliable_time_estimate) {
    for (const char* formulation : {"displacement", "mixed"}) {
        const json r = estimated("free-vibration",
                                 {"analysis.time_step=2.5e-4", "analysis.end_time=0.25",
                                  std::string("discretization.formulation=") + formulation},
                                 true);
        BOOST_TEST(has_solution(r["status"].get<std::string>()),
                   formulation << ": " << r["status"] << " " << r["message"]);
        BOOST_TEST(r["estimate"]["status"].get<std::string>() == "estimated");
        BOOST_TEST(r["estimate"]["time_reliable"].get<bool>(), r["estimate"].dump());
        BOOST_TEST(r["estimate"]["phase_error_rad"].get<double>() <= estimate::kPhaseReliable);
        // The cost is reported: companions' wall time and work against the run's.
        BOOST_TEST(r["estimate"]["cost"]["wall_ratio"].get<double>() > 0.0);
        BOOST_TEST(r["estimate"]["cost"]["work_ratio"].get<double>() > 1.0);
    }
}

// Coarser companions (2h, 4h and 2dt; docs/error-estimates.md) on the mixed free vibration, Δt =
// 1 ms over 0.1 s: the second mode accumulates ω₂³Δt²T/12 ≈ 0.30 rad, its 2dt companion four
// times that, 1.2 rad, where the Richardson estimate is no longer linear in the phase. The time
// estimate must say it is not reliable and name the companion's phase; the run keeps its status
// (the run's own phase is below 1 rad). The companions cost about 1/2 + 1/4 + 1/2 of the run's
// work (each Newton iteration × unknowns), against 2 + 4 + 2 for the finer ones: asserted below 2
// and above 6.
BOOST_AUTO_TEST_CASE(a_coarser_time_companion_is_judged_by_its_own_phase) {
    const std::vector<std::string> common = {"discretization.formulation=mixed",
                                             "analysis.end_time=0.1",
                                             "analysis.output_interval=0.002"};
    std::vector<std::string> coarser = common;
    coarser.emplace_back("analysis.estimate_companions=coarser");
    const json c = estimated("free-vibration", coarser, true);
    const json f = estimated("free-vibration", common, true);
    BOOST_TEST(has_solution(c["status"].get<std::string>()), c["message"]);
    BOOST_TEST(c["estimate"]["method"] == "2h,4h & 2dt");
    BOOST_TEST(!c["estimate"]["time_reliable"].get<bool>());
    BOOST_TEST(c["estimate"]["time_reason"].get<std::string>().find("2dt companion's") !=
                   std::string::npos,
               c["estimate"]["time_reason"]);
    BOOST_TEST(c["estimate"]["cost"]["work_ratio"].get<double>() < 2.0);
    BOOST_TEST(f["estimate"]["cost"]["work_ratio"].get<double>() > 6.0);
}

BOOST_AUTO_TEST_CASE(history_csv_has_estimate_columns_only_when_estimated) {
    const std::vector<std::string> o = {"analysis.end_time=0.05"};
    const json on = estimated("free-vibration", o, true);
    const json off = estimated("free-vibration", o, false);
    const std::string header_on = first_line(history_csv(on));
    const std::string header_off = first_line(history_csv(off));
    BOOST_TEST(header_on.rfind(header_off + ",", 0) == 0, header_on);
    BOOST_TEST(header_on.substr(header_off.size()) ==
               ",root_u_err_p+1[length],root_u_err_dt/2[length],root_u_err[length],"
               "root_angle_err_p+1[rad],root_angle_err_dt/2[rad],root_angle_err[rad],"
               "tip_u_err_p+1[length],tip_u_err_dt/2[length],tip_u_err[length],"
               "tip_angle_err_p+1[rad],tip_angle_err_dt/2[rad],tip_angle_err[rad]");
    BOOST_TEST(header_off.find("err") == std::string::npos);
    // The last row's tip columns are the JSON's estimate (space, time, combined).
    const std::string csv = history_csv(on);
    const std::string last = csv.substr(csv.rfind('\n', csv.size() - 2) + 1);
    std::istringstream cells(last);
    std::vector<double> v;
    for (std::string c; std::getline(cells, c, ',');) v.push_back(std::stod(c));
    const json& tip = on["steps"].back()["estimate"]["tip"]["rotation"];
    BOOST_TEST(v.back() == tip["error"].get<double>());
    BOOST_TEST(v[v.size() - 2] == tip["time"]["error"].get<double>());
    BOOST_TEST(v[v.size() - 3] == tip["space"]["error"].get<double>());
}

BOOST_AUTO_TEST_CASE(steps_csv_has_estimate_columns_only_when_estimated) {
    const json on = estimated("cantilever-moment", {}, true);
    const json off = estimated("cantilever-moment", {}, false);
    BOOST_TEST(has_load_steps(on));
    const std::string header_off = first_line(steps_csv(off));
    BOOST_TEST(header_off.find("err") == std::string::npos);
    BOOST_TEST(first_line(steps_csv(on)) ==
               header_off +
                   ",root_u_err_p+1[length],root_angle_err_p+1[rad],tip_u_err_p+1[length],"
                   "tip_angle_err_p+1[rad]");
    const json mixed = estimated("cantilever-moment", {"discretization.formulation=mixed"}, true);
    BOOST_TEST(first_line(steps_csv(mixed)).find("tip_u_err_h/2+h/4[length]") != std::string::npos);
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace rotbeam
