// Effectivity (estimated / true error) of the run's error estimate (docs/error-estimates.md) over
// refinement sequences, for both formulations with the quaternion and the rotation vector (a
// three-parameter chart), on the roll-up, whose exact solution is known at every load factor
// (core/oracles/rollup.hpp, docs/benchmarks.md §1), and on the 45° bend against the continuum
// reference (core/continuum, docs/reference-solutions.md). The runs go through run_case and
// add_run_estimate, the path of `rotbeam run`.
//
// What is asserted, and why the tolerance is what it is:
// - Where the true errors show the asymptotic regime, the effectivity of the tip displacement and
//   rotation lies in [0.5, 2] (docs/error-estimates.md). Asymptotic is decided from the exact
//   errors, independently of the estimator: for p+1, e_{p+1} ≤ e_p / 2 (then |e_p − e_{p+1}| lies
//   within [1/2, 3/2] e_p by the triangle inequality, so the band holds exactly when the estimator
//   compares the right states); for h/2, h/4, the true errors at h, h/2, h/4 fall monotonically
//   with observed orders within kOrderWindow of 2 (there Richardson's factor is off by at most
//   ~20 %), and the estimator must then also call its estimate reliable.
// - Everywhere the run was estimated and its true error is above the round-off floor, the true
//   error is at most 3 × the estimate (an estimator failure otherwise), unless the estimate says
//   it is not reliable.
// - Enough asymptotic points were checked (a test that checks nothing fails).
#include <algorithm>
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <functional>
#include <iomanip>
#include <sstream>

#include "cases/loader/case_loader.hpp"
#include "core/continuum/continuum.hpp"
#include "core/oracles/rollup.hpp"
#include "core/so3.hpp"
#include "core/static_driver.hpp"
#include "estimates/quantity_estimate.hpp"
#include "runs/run_case.hpp"
#include "tests/estimates/tip_states.hpp"

namespace rotbeam {

namespace {

using json = nlohmann::json;

// The tip state the runs are compared with, per reported step (index, load factor).
using Reference = test::TipStates;

struct TipError {
    double displacement = 0.0;
    double rotation = 0.0;
};

struct Run {
    json result;
    std::vector<TipError> true_errors;  // per reported step
};

Run run_against(const std::string& name, const std::vector<std::string>& overrides, bool estimate,
                const Reference& reference) {
    const std::string path = std::string(ROTBEAM_SOURCE_DIR) + "/cases/" + name + ".yaml";
    const RunRequest request{path, load_case(path, overrides, CaseParts::case_file)};
    Run run{run_case(request), {}};
    if (estimate) add_run_estimate(request, run.result);
    for (std::size_t k = 0; k < run.result["steps"].size(); ++k) {
        const json& step = run.result["steps"][k];
        const PointState exact = reference(k, step["load_factor"].get<double>());
        const PointState tip = test::point_state_of(step);
        run.true_errors.push_back({(tip.displacement - exact.displacement).norm(),
                                   so3::rotation_angle(tip.rotation.transpose() * exact.rotation)});
    }
    return run;
}

struct Checked {
    // True errors below this (length units, rad) measure round-off or the reference, not the
    // discretization.
    double floor = 0.0;
    int asymptotic = 0;                                   // points where the band was asserted
    int estimated = 0;                                    // points with an estimate above the floor
    double min_asymptotic = 1e300, max_asymptotic = 0.0;  // effectivity range, asymptotic
    double min_other = 1e300, max_other = 0.0;            // and elsewhere
    std::ostringstream table;
    std::string summary() const {
        std::ostringstream s;
        s << std::setprecision(3) << asymptotic << " asymptotic points, effectivity "
          << min_asymptotic << " … " << max_asymptotic << "; " << estimated - asymptotic
          << " others";
        if (estimated > asymptotic) s << ", effectivity " << min_other << " … " << max_other;
        return s.str();
    }
};

// One quantity at one step: the band where asymptotic, the failure criterion everywhere.
void check_quantity(const char* what, const json& q, double true_error, bool asymptotic,
                    Checked& c) {
    const double est = q["error"].get<double>();
    const double eff = est / true_error;
    c.table << "  " << what << " true " << std::setprecision(3) << true_error << " est " << est
            << " eff " << eff << (q["reliable"].get<bool>() ? "" : " (not reliable)")
            << (asymptotic ? " [asymptotic]" : "") << "\n";
    if (true_error <= c.floor) return;
    ++c.estimated;
    if (!asymptotic) {
        c.min_other = std::min(c.min_other, eff);
        c.max_other = std::max(c.max_other, eff);
    } else {
        ++c.asymptotic;
        c.min_asymptotic = std::min(c.min_asymptotic, eff);
        c.max_asymptotic = std::max(c.max_asymptotic, eff);
        BOOST_TEST(eff >= 0.5, what << ": effectivity " << eff);
        BOOST_TEST(eff <= 2.0, what << ": effectivity " << eff);
        BOOST_TEST(q["reliable"].get<bool>(), what << ": asymptotic but not reliable");
    }
    if (q["reliable"].get<bool>()) {
        BOOST_TEST(true_error <= 3.0 * est,
                   what << ": estimator failure, true " << true_error << " > 3 × estimate " << est);
    }
}

std::vector<std::string> combination(const std::string& formulation, const std::string& rotation) {
    return {"discretization.formulation=" + formulation, "discretization.rotation=" + rotation};
}

bool mixed_asymptotic(double e0, double e1, double e2, double floor) {
    if (!(e1 < e0 && e2 < e1) || e2 <= floor) return false;
    const double r1 = std::log2(e0 / e1);
    const double r2 = std::log2(e1 / e2);
    return std::abs(r1 - 2.0) <= estimate::kOrderWindow &&
           std::abs(r2 - 2.0) <= estimate::kOrderWindow;
}

// Displacement formulation, 2 elements, orders 2 … 8 (the p-sequence of docs/studies.md): each
// run's p+1 estimate (orders 2 … 7) against the true error; asymptotic where e_{p+1} ≤ e_p / 2.
void p_sequence(const std::string& name, const std::string& rotation, const Reference& reference,
                Checked& c) {
    std::vector<Run> runs;
    for (int p = 2; p <= 8; ++p) {
        std::vector<std::string> o = combination("displacement", rotation);
        o.push_back("members.*.elements=2");
        o.push_back("discretization.order=" + std::to_string(p));
        runs.push_back(run_against(name, o, p <= 7, reference));
    }
    for (std::size_t k = 0; k + 1 < runs.size(); ++k) {
        const json& r = runs[k].result;
        BOOST_TEST_REQUIRE(has_solution(r["status"].get<std::string>()));
        BOOST_TEST_REQUIRE(r["estimate"]["status"] == "estimated");
        for (std::size_t i = 0; i < r["steps"].size(); ++i) {
            const TipError& e = runs[k].true_errors[i];
            const TipError& next = runs[k + 1].true_errors.at(i);
            const json& est = r["steps"][i]["estimate"]["tip"];
            c.table << name << " " << rotation << " p=" << k + 2 << " load factor "
                    << r["steps"][i]["load_factor"].get<double>() << "\n";
            check_quantity("u", est["displacement"], e.displacement,
                           next.displacement <= 0.5 * e.displacement, c);
            check_quantity("rotation", est["rotation"], e.rotation,
                           next.rotation <= 0.5 * e.rotation, c);
        }
    }
    BOOST_TEST_MESSAGE(c.table.str());
    BOOST_TEST_MESSAGE(name << " displacement " << rotation << ": " << c.summary());
}

// Mixed formulation, 4 … 32 elements: each run's h/2, h/4 estimate against the true error;
// asymptotic where the true errors at N, 2N, 4N fall at order 2 ± kOrderWindow.
void h_sequence(const std::string& name, const std::string& rotation, const Reference& reference,
                Checked& c) {
    std::vector<Run> runs;
    for (int n = 4; n <= 128; n *= 2) {
        std::vector<std::string> o = combination("mixed", rotation);
        o.push_back("members.*.elements=" + std::to_string(n));
        runs.push_back(run_against(name, o, n <= 32, reference));
    }
    for (std::size_t k = 0; k + 2 < runs.size(); ++k) {
        const json& r = runs[k].result;
        c.table << name << " " << rotation << " N=" << (4 << k) << " "
                << r["status"].get<std::string>() << ", estimate "
                << r["estimate"]["status"].get<std::string>() << "\n";
        if (!has_solution(r["status"].get<std::string>())) continue;
        BOOST_TEST_REQUIRE(r["estimate"]["status"] != "not-estimated");
        for (std::size_t i = 0; i < r["steps"].size(); ++i) {
            const json& est = r["steps"][i]["estimate"];
            if (!est.contains("tip")) continue;
            const auto e = [&](std::size_t j) { return runs[k + j].true_errors.at(i); };
            c.table << name << " " << rotation << " N=" << (4 << k) << " load factor "
                    << r["steps"][i]["load_factor"].get<double>() << "\n";
            check_quantity(
                "u", est["tip"]["displacement"], e(0).displacement,
                mixed_asymptotic(e(0).displacement, e(1).displacement, e(2).displacement, c.floor),
                c);
            check_quantity("rotation", est["tip"]["rotation"], e(0).rotation,
                           mixed_asymptotic(e(0).rotation, e(1).rotation, e(2).rotation, c.floor),
                           c);
        }
    }
    BOOST_TEST_MESSAGE(c.table.str());
    BOOST_TEST_MESSAGE(name << " mixed " << rotation << ": " << c.summary());
}

// The exact roll-up tip (L = 12 in, cases/cantilever-moment.yaml).
PointState rollup_tip(std::size_t, double lambda) {
    const oracle::RollupState s = oracle::rollup_tip(12.0, lambda);
    return {s.displacement, s.rotation};
}

// Round-off floor of the roll-up: the solver's algebraic error is ~1e-14 L
// (docs/solver-convergence.md); 1e-9 keeps two solves' round-off a thousandth of what they
// estimate.
constexpr double kRollupFloor = 1e-9;

// 100 × the continuum reference's verified accuracy, 1.8e-11 L with L = 25π in the arc length
// (docs/reference-solutions.md; the convergence study's fit floor): below it the error measured
// is the reference's.
constexpr double kBendFloor = 100 * 1.8e-11 * 78.53981633974483;

using Sequence = void (*)(const std::string&, const std::string&, const Reference&, Checked&);

// The sequence on the case with the quaternion and the rotation vector, each with at least
// `min_points` points where the effectivity band was asserted.
void check_both_rotations(Sequence sequence, const std::string& name, const Reference& reference,
                          double floor, int min_points) {
    for (const char* rotation : {"quaternion", "rotation-vector"}) {
        Checked c;
        c.floor = floor;
        sequence(name, rotation, reference, c);
        BOOST_TEST(c.asymptotic >= min_points,
                   rotation << ": " << c.asymptotic << " asymptotic points");
    }
}

}  // namespace

BOOST_AUTO_TEST_SUITE(effectivity)

BOOST_AUTO_TEST_CASE(p_plus_one_on_the_rollup) {
    // 2 quantities × 7 load steps × orders 3 … 7, less those at round-off.
    check_both_rotations(p_sequence, "cantilever-moment", rollup_tip, kRollupFloor, 40);
}

BOOST_AUTO_TEST_CASE(h_refinement_on_the_rollup) {
    // The displacement at 7 load steps × 4 meshes, less λ = 2 where the closed circle is exact;
    // the tip rotation of the mixed roll-up with the rotation vector is exact to round-off
    // (constant curvature).
    check_both_rotations(h_sequence, "cantilever-moment", rollup_tip, kRollupFloor, 20);
}

BOOST_AUTO_TEST_CASE(p_plus_one_on_the_bend) {
    check_both_rotations(p_sequence, "bend-45", test::bend_tip_reference(), kBendFloor, 15);
}

BOOST_AUTO_TEST_CASE(h_refinement_on_the_bend) {
    check_both_rotations(h_sequence, "bend-45", test::bend_tip_reference(), kBendFloor, 15);
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace rotbeam
