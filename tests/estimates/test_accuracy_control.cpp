// Accuracy control (docs/accuracy-control.md) against independent references: a run asked for
// accuracy TOL that says it reached it has a true error ≤ TOL, relative to the scales of
// estimates/accuracy_scale.hpp (the reference length for displacements, 1 rad for rotations, the
// frequency for frequencies), at every step or mode the reference covers; one that cannot reach
// it says `accuracy-not-reached` with a reason, never its solver's status.
//
// References: the roll-up, exact at every load factor (core/oracles/rollup.hpp); the 45° bend,
// the continuum reference (core/continuum, verified to 1.8e-11 L, docs/reference-solutions.md);
// the helix, exact at every load factor (core/oracles/helix.hpp); the joined beam's frequencies
// about the undeformed state, the displacement formulation at order 8 on 10 elements per member
// (orders 7 and 8 agree to 1e-7 relative, test_effectivity_modal.cpp), so only TOL ≥ 1e-5 is
// checked there (100 × the reference's own error).
//
// Coverage within the CI budget (~60 s on 2 cores): not every combination × tolerance, but every
// combination (formulation × parameterization) at least once, every tolerance 1e-3 … 1e-8 at
// least once, and every referenced case with both formulations (the table kRuns). Each row says
// whether the target is expected to be reached; a row expected not to be reached must say why
// in its status (and that is asserted too), so the test fails on a regression either way.
#include <Eigen/Geometry>
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <functional>
#include <iomanip>
#include <sstream>

#include "cases/loader/case_loader.hpp"
#include "core/continuum/continuum.hpp"
#include "core/oracles/helix.hpp"
#include "core/oracles/rollup.hpp"
#include "core/so3.hpp"
#include "core/static_driver.hpp"
#include "estimates/accuracy_scale.hpp"
#include "runs/accuracy_run.hpp"
#include "runs/mode_matching.hpp"
#include "tests/estimates/tip_states.hpp"

namespace rotbeam {

namespace {

using json = nlohmann::json;

std::string case_path(const std::string& name) {
    return std::string(ROTBEAM_SOURCE_DIR) + "/cases/" + name + ".yaml";
}

// The exact or reference tip state at a reported step (index, load factor).
using TipReference = test::TipStates;

PointState rollup_tip(std::size_t, double lambda) {
    const oracle::RollupState s = oracle::rollup_tip(12.0, lambda);  // L = 12 in
    return {s.displacement, s.rotation};
}

// cases/helix.yaml: L = 10, EI = 100, tip moment λ (6, 0, 8): κ = λ/10 about n = (0.6, 0, 0.8).
PointState helix_tip(std::size_t, double lambda) {
    const oracle::HelixState s = oracle::helix_state(lambda / 10.0, Vec3(0.6, 0.0, 0.8), 10.0);
    return {s.displacement, s.rotation};
}

struct Row {
    const char* case_name;
    const char* formulation;
    const char* rotation;
    double tolerance;
    bool reachable;  // expected outcome
};

json run_row(const Row& row, std::vector<std::string> extra = {}) {
    std::ostringstream tol;
    tol << std::setprecision(17) << row.tolerance;
    std::vector<std::string> o = {std::string("discretization.formulation=") + row.formulation,
                                  std::string("discretization.rotation=") + row.rotation,
                                  "analysis.accuracy=" + tol.str()};
    o.insert(o.end(), extra.begin(), extra.end());
    const std::string path = case_path(row.case_name);
    const RunRequest request{path, load_case(path, o, CaseParts::case_file)};
    return run_to_accuracy(request);
}

std::string label(const Row& row) {
    std::ostringstream s;
    s << row.case_name << " " << row.formulation << " " << row.rotation << " TOL " << row.tolerance;
    return s.str();
}

// The outcome is what the row expects, and stated as such; returns true when reached.
bool check_outcome(const Row& row, const json& r) {
    const json& a = r["accuracy"];
    const bool reached = a["status"] == "reached";
    BOOST_TEST_MESSAGE(label(row) << ": " << a["status"].get<std::string>() << ", "
                                  << a["chosen"].dump() << ", " << a["attempts"].size()
                                  << " attempts, " << a["wall_seconds"].get<double>() << " s"
                                  << (reached ? "" : " — " + a["reason"].get<std::string>()));
    if (reached) {
        BOOST_TEST(has_solution(r["status"].get<std::string>()), label(row));
    } else {
        BOOST_TEST(r["status"] == "accuracy-not-reached", label(row));
        BOOST_TEST(!a["reason"].get<std::string>().empty(), label(row));
    }
    BOOST_TEST(reached == row.reachable, label(row) << ": " << a.dump());
    return reached;
}

// Static rows: the true tip error at every step, relative to the scales. Returns the result.
json check_static(const Row& row, const TipReference& reference, double length,
                  const std::vector<std::string>& extra = {}) {
    json r = run_row(row, extra);
    if (!check_outcome(row, r)) return r;
    for (std::size_t k = 0; k < r["steps"].size(); ++k) {
        const json& step = r["steps"][k];
        const PointState exact = reference(k, step["load_factor"].get<double>());
        const PointState tip = test::point_state_of(step);
        const double eu = (tip.displacement - exact.displacement).norm() / length;
        const double er = so3::rotation_angle(tip.rotation.transpose() * exact.rotation);
        BOOST_TEST(eu <= row.tolerance, label(row) << " step " << k << ": displacement " << eu);
        BOOST_TEST(er <= row.tolerance, label(row) << " step " << k << ": rotation " << er);
    }
    return r;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(accuracy_control)

// Every displacement-formulation parameterization and every mixed one appears below at least
// once; every tolerance 1e-3 … 1e-8 at least once.
BOOST_AUTO_TEST_CASE(rollup_true_error_within_tolerance) {
    for (const Row& row : {Row{"cantilever-moment", "displacement", "quaternion", 1e-6, true},
                           Row{"cantilever-moment", "displacement", "rotation-vector", 1e-8, true},
                           Row{"cantilever-moment", "mixed", "quaternion", 1e-3, true},
                           // Rodrigues parameters are singular at π: the mixed roll-up's Newton
                           // fails near λ = 0.94 (tip angle 3.0 rad) with any load step, and the
                           // control must say so instead of refining.
                           Row{"cantilever-moment", "mixed", "rodrigues", 1e-3, false}}) {
        check_static(row, rollup_tip, 12.0);
    }
}

BOOST_AUTO_TEST_CASE(bend_true_error_within_tolerance) {
    const TipReference reference = test::bend_tip_reference();
    // The scale: the distance root–tip of the arc, 100 · 2 sin 22.5°.
    const double chord = 200.0 * std::sin(M_PI / 8.0);
    for (const Row& row : {Row{"bend-45", "displacement", "rodrigues", 1e-7, true},
                           Row{"bend-45", "displacement", "euler-angles", 1e-5, true},
                           Row{"bend-45", "mixed", "wiener-milenkovic", 1e-4, true},
                           Row{"bend-45", "mixed", "rotation-vector", 1e-4, true},
                           Row{"bend-45", "mixed", "rodrigues", 1e-3, true},
                           Row{"bend-45", "mixed", "euler-angles", 1e-3, true}}) {
        check_static(row, reference, chord);
    }
}

// The mixed formulation's coarser companions (2h, 4h; docs/error-estimates.md): the control
// rounds its element counts up to multiples of 4 and the true error stays within TOL, on the exact
// roll-up and the continuum bend, at the tolerances the finer companions reach above.
BOOST_AUTO_TEST_CASE(coarser_companions_true_error_within_tolerance) {
    const std::vector<std::string> coarser = {"analysis.estimate_companions=coarser"};
    check_static(Row{"cantilever-moment", "mixed", "quaternion", 1e-3, true}, rollup_tip, 12.0,
                 coarser);
    const double chord = 200.0 * std::sin(M_PI / 8.0);
    for (const Row& row : {Row{"bend-45", "mixed", "wiener-milenkovic", 1e-4, true},
                           Row{"bend-45", "mixed", "quaternion", 1e-5, true}}) {
        const json r = check_static(row, test::bend_tip_reference(), chord, coarser);
        BOOST_TEST(r["estimate"]["method"] == "2h,4h");
        for (const json& attempt : r["accuracy"]["attempts"]) {
            for (const auto& [member, n] : attempt["elements_per_member"].items()) {
                BOOST_TEST(n.get<int>() % 4 == 0, label(row) << ": " << member << " " << n);
            }
        }
    }
}

BOOST_AUTO_TEST_CASE(helix_true_error_within_tolerance) {
    for (const Row& row : {Row{"helix", "displacement", "wiener-milenkovic", 1e-8, true},
                           // The mixed quaternion needs 512 elements here (its tip rotation at
                           // 4π: 0.16 rad on 16), 71 s on the loaded CI machine: left out.
                           Row{"helix", "mixed", "rotation-vector", 1e-3, true}}) {
        check_static(row, helix_tip, 10.0);
    }
}

BOOST_AUTO_TEST_CASE(joined_beam_frequencies_within_tolerance) {
    const std::string path = case_path("joined-beam");
    const RunRequest ref_request{
        path, load_case(path,
                        {"discretization.formulation=displacement", "discretization.order=8",
                         "discretization.mass_rule=consistent", "analysis.modes=8"},
                        CaseParts::case_file)};
    const json ref = run_case(ref_request);
    BOOST_TEST_REQUIRE(ref["status"] == "converged");
    std::vector<std::vector<double>> ref_stations;
    for (const json& m : ref["modes"]) ref_stations.push_back(m["stations"]);
    for (const Row& row : {Row{"joined-beam", "mixed", "quaternion", 1e-3, true},
                           Row{"joined-beam", "displacement", "euler-angles", 1e-5, true}}) {
        const json r =
            run_row(row, std::string(row.formulation) == "displacement"
                             ? std::vector<std::string>{"discretization.mass_rule=consistent"}
                             : std::vector<std::string>{});
        if (!check_outcome(row, r)) continue;
        std::vector<std::vector<double>> stations;
        for (const json& m : r["modes"]) stations.push_back(m["stations"]);
        const std::vector<int> pair = match_modes(stations, ref_stations, kMatchMac);
        for (std::size_t i = 0; i < pair.size(); ++i) {
            BOOST_TEST_REQUIRE(pair[i] >= 0, label(row) << " mode " << i + 1 << " unpaired");
            const double f = r["modes"][i]["frequency_hz"].get<double>();
            const double f_ref =
                ref["modes"][static_cast<std::size_t>(pair[i])]["frequency_hz"].get<double>();
            BOOST_TEST(std::abs(f - f_ref) / f_ref <= row.tolerance,
                       label(row) << " mode " << i + 1 << ": " << f << " vs " << f_ref);
        }
    }
}

// The imported BeamDyn roll-up deck (tests/data/beamdyn/bd_isotropic_rollup: M = 12.5664 N·m on
// EI = 100 N·m², L = 10 m, a circular arc of radius EI/M about −x, exact for any EA and GA) with
// BeamDyn's trapezoidal quadrature (`quadrature = 2`) instead of the deck's Gauss, at refine 15,
// the fewest points its order 15 accepts: the control chooses refine with the order and the
// elements (docs/accuracy-control.md, "Trapezoidal quadrature"). The true error is mostly the
// rule's (≈ 0.12 r⁻² of L once asymptotic; the arc's rotation field is linear in s, which the
// high orders interpolate exactly); the estimate, whose companion doubles refine, sees 3/4 of it
// there, inside the factor 2 of TOL/2. TOL = 1e-6 is not reachable within refine 500 (its
// companion's 1000): measured, 8 × order 16 at refine 480 estimates 6.1e-7 > 5e-7 and the next
// step needs 960; the control must say so by the refine budget. Before, the loader refused
// --accuracy with this quadrature (exit 2).
BOOST_AUTO_TEST_CASE(trapezoidal_rollup_deck_true_error_within_tolerance) {
    const std::string path =
        std::string(ROTBEAM_SOURCE_DIR) + "/tests/data/beamdyn/bd_isotropic_rollup/bd_driver.inp";
    const double rho = 100.0 / 12.5664, theta = 10.0 / rho;
    const Vec3 exact_u(0.0, rho * (1.0 - std::cos(theta)), rho * std::sin(theta) - 10.0);
    const Mat3 exact_r = Eigen::AngleAxisd(-theta, Vec3::UnitX()).toRotationMatrix();
    for (const Row& row :
         {Row{"bd_isotropic_rollup trapezoidal", "displacement", "quaternion", 1e-3, true},
          Row{"bd_isotropic_rollup trapezoidal", "displacement", "wiener-milenkovic", 1e-5, true},
          Row{"bd_isotropic_rollup trapezoidal", "displacement", "quaternion", 1e-6, false}}) {
        std::ostringstream tol;
        tol << std::setprecision(17) << row.tolerance;
        const Model model =
            load_case(path, {"discretization.quadrature=trapezoidal", "discretization.refine=15",
                             std::string("discretization.rotation=") + row.rotation,
                             "analysis.accuracy=" + tol.str()});
        const json r = run_to_accuracy(RunRequest{path, model});
        for (const json& a : r["accuracy"]["attempts"]) {
            BOOST_TEST_MESSAGE("  " << a["elements"] << " x order " << a["order"] << ", refine "
                                    << a["refine"] << ": worst estimate "
                                    << a.value("worst_relative", -1.0) << ", "
                                    << a.value("next", std::string("(last)")));
        }
        BOOST_TEST(r["accuracy"]["strategy"] ==
                   "p while spectral, else h; refine doubled per step");
        if (!check_outcome(row, r)) {
            BOOST_TEST(
                r["accuracy"]["reason"].get<std::string>().find("refine") != std::string::npos,
                label(row));
            continue;
        }
        const double length = estimate::reference_length(model);
        for (const json& step : r["steps"]) {
            const PointState tip = test::point_state_of(step);
            const double eu = (tip.displacement - exact_u).norm() / length;
            const double er = so3::rotation_angle(tip.rotation.transpose() * exact_r);
            BOOST_TEST_MESSAGE("  true error: displacement " << eu << ", rotation " << er);
            BOOST_TEST(eu <= row.tolerance, label(row) << ": displacement " << eu);
            BOOST_TEST(er <= row.tolerance, label(row) << ": rotation " << er);
        }
    }
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace rotbeam
