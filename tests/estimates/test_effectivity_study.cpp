// The effectivity study's quick form (studies/study_effectivity.cpp, docs/error-estimates.md): the
// roll-up and the static manufactured rod against their exact solutions and the 45° bend against
// the continuum reference, the
// displacement formulation's p+1 estimate over orders 3 … 6 on two elements and the mixed one's
// h/2, h/4 and 2h, 4h estimates over 4, 8, 16 elements, each level a `rotbeam run` with its
// estimate.
//
// What is asserted, and why:
// - Every row's effectivity is its estimate over its true error, as stored.
// - Where the true errors alone show the asymptotic regime, the effectivity lies in [0.5, 2]. The
//   regime is decided here again from the stored true errors of the row's level and the next two,
//   not from the study's flag, which must agree: p+1, each next order's error below half the one
//   before (a p+2 error at the floor counts as below), so that |e_p − e_{p+1}| lies within
//   [1/2, 3/2] e_p by the triangle inequality; h/2, h/4, monotone with both observed orders within
//   0.5 of the mixed formulation's 2, where Richardson's factor is off by at most ~20 % (2h, 4h:
//   the same over the level and the two below it, whose meshes are its companions').
// - No reliable estimate has a true error above 3 × its estimate (an estimator failure nothing
//   explains); the study lists failures of estimates that say they are not reliable with that
//   reason, and none are expected on these levels either.
// - Enough asymptotic rows per sequence, so that the band is actually checked.
// A halved estimate (effectivity ~0.43 … 0.5 on the p rows) fails the band: checked by halving the
// error of estimates/quantity_estimate.cpp's p and h estimates. The dynamic rows are checked by
// check_dynamic_rows (below).
#include <algorithm>
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <filesystem>

#include "core/static_driver.hpp"
#include "studies/effectivity_sequences.hpp"
#include "studies/manufactured_rod_case.hpp"
#include "studies/studies.hpp"

namespace rotbeam {

namespace {

using json = nlohmann::json;

// Asymptotic rows per sequence at least: 2 quantities × the load steps (roll-up 7, bend 3; the
// manufactured rod 3 points × 20) at the classifiable levels (p: orders 3 and 4; h: 4 elements),
// less those at the floor.
constexpr int kMinAsymptoticRows = 4;

bool regime_shown(const std::string& strategy, const json& row) {
    const double e0 = row["true_error"].get<double>();
    const double floor = row["floor"].get<double>();
    const json& next = row["next_true_errors"];
    if (next[0].is_null() || next[1].is_null() || e0 <= floor) return false;
    const double e1 = next[0].get<double>(), e2 = next[1].get<double>();
    if (strategy == "p+1") return e1 < 0.5 * e0 && (e2 <= floor || e2 < 0.5 * e1);
    // h/2, h/4 (mixed, order 2 per doubling) and dt/2 (the generalized-α and the trapezoidal
    // rule, order 2 per halved step): the same rate 2 per level. 2h, 4h: the companions' levels
    // are the two below, so e2 is the coarsest and e0 the finest.
    const bool coarser = strategy == "2h,4h";
    const double a = coarser ? e2 : e0, c = coarser ? e0 : e2;
    if (!(c < e1 && e1 < a) || c <= floor) return false;
    return std::abs(std::log2(a / e1) - 2.0) <= 0.5 && std::abs(std::log2(e1 / c) - 2.0) <= 0.5;
}

// The Richardson factor of the Δt/2 companion for a second-order scheme: 1 / (1 − 2⁻²).
constexpr double kRichardsonOrder2 = 4.0 / 3.0;

// The dynamic rows of the quick form (studies/effectivity_motion.hpp): the manufactured motion,
// displacement formulation, quaternion, generalized-α on its time sequence Δt = 0.025, 0.0125,
// 0.00625, against the exact motion (space + time) and against the same mesh at Δt = 0.00625 / 8
// (the time part). Asserted:
// - as for the static rows: the asymptotic flag as the true errors show it (rate 2 per halved
//   step), the band there, no estimate a third of its true error or less unless it says it is not
//   reliable, and every failure listed with its cause;
// - the time part against the true time errors of the level and the next, e0 and e1, both against
//   the same fine-step run: the estimate is 4/3 max_t ‖u_Δt − u_Δt/2‖ and the level's Δt/2
//   companion is the next level's run, so by the triangle inequality (at the time of e0's maximum,
//   and at every time) it lies within [4/3 (e0 − e1), 4/3 (e0 + e1)] — no tolerance beyond
//   round-off. Asymptotic (e1 ≈ e0/4) that is [1.0, 1.67] e0: a doubled time estimate (2.0 e0)
//   or a dropped one (0) fails it, where the band [0.5, 2] alone would let the doubled one pass.
// - enough rows checked: both tip quantities, total and time part, at the asymptotic level.
void check_dynamic_rows(const json& dynamic) {
    BOOST_TEST_REQUIRE(dynamic["sequences"].size() == 1u);
    int asymptotic = 0, richardson = 0;
    for (const json& s : dynamic["sequences"]) {
        const std::string label = s["combination"].get<std::string>();
        BOOST_TEST(s["strategy"] == "dt/2");
        for (const json& status : s["statuses"]) BOOST_TEST(status == "converged", label);
        for (const json& row : s["rows"]) {
            const std::string what = label + " level " + std::to_string(row["level"].get<int>()) +
                                     " " + row["quantity"].get<std::string>();
            const double est = row["estimate"]["error"].get<double>();
            const double e0 = row["true_error"].get<double>();
            const bool shown = regime_shown("dt/2", row);
            BOOST_TEST(row["asymptotic"].get<bool>() == shown, what);
            if (shown) {
                ++asymptotic;
                BOOST_TEST(est >= 0.5 * e0, what << ": effectivity " << est / e0);
                BOOST_TEST(est <= 2.0 * e0, what << ": effectivity " << est / e0);
            }
            const bool missed = e0 > row["floor"].get<double>() && e0 > 3.0 * est;
            BOOST_TEST(missed == !row["failure"].is_null(), what);
            if (missed && !row["failure"].is_null()) {
                BOOST_TEST(row["failure"].get<std::string>().find('(') != std::string::npos,
                           what << ": no cause: " << row["failure"]);
                BOOST_TEST(!(row["estimate"]["reliable"].get<bool>() && !row["other_state"]),
                           what << ": an unexplained estimator failure");
            }
            const std::string q = row["quantity"].get<std::string>();
            if (!q.ends_with("time part") || row["next_true_errors"][0].is_null()) continue;
            const double e1 = row["next_true_errors"][0].get<double>();
            const double round_off = 1e-12 * e0;
            BOOST_TEST(est >= kRichardsonOrder2 * (e0 - e1) - round_off,
                       what << ": time part " << est << " below 4/3 (e0 − e1), e0 " << e0 << ", e1 "
                            << e1);
            BOOST_TEST(est <= kRichardsonOrder2 * (e0 + e1) + round_off,
                       what << ": time part " << est << " above 4/3 (e0 + e1), e0 " << e0 << ", e1 "
                            << e1);
            ++richardson;
        }
    }
    BOOST_TEST(asymptotic >= 4, asymptotic);  // 2 quantities × (total, time part) at Δt = 0.025
    BOOST_TEST(richardson >= 4, richardson);  // the same at Δt = 0.025 and 0.0125
    BOOST_TEST(dynamic["unexplained_failures"] == 0);
    BOOST_TEST(dynamic["band_violations"] == 0);
}

}  // namespace

BOOST_AUTO_TEST_CASE(effectivity_study_quick_form_meets_the_band_without_estimator_failures) {
    cli::StudyOptions o;
    o.quick = true;
    o.out_dir = (std::filesystem::temp_directory_path() / "rotbeam-test-effectivity").string();
    std::filesystem::remove_all(o.out_dir);
    const json out = cli::run_split_study(cli::effectivity_study(), o, 2);
    // 3 cases × (displacement p+1, mixed h/2, h/4, mixed 2h, 4h)
    BOOST_TEST_REQUIRE(out["sequences"].size() == 9u);
    int band_checked = 0, manufactured = 0;
    for (const json& s : out["sequences"]) {
        // The manufactured rod's rows are its interior points against the exact state: the three
        // named points q1, mid, q3 (root and tip are exact by construction, at the floor).
        if (s["case"] == cli::kManufacturedRodCase) {
            ++manufactured;
            for (const char* point : {"q1 ", "mid ", "q3 "}) {
                BOOST_TEST(std::any_of(s["rows"].begin(), s["rows"].end(),
                                       [&](const json& row) {
                                           return row["quantity"].get<std::string>().rfind(
                                                      point, 0) == 0 &&
                                                  row["asymptotic"].get<bool>();
                                       }),
                           "manufactured rod: no asymptotic row at " << point);
            }
        }
        const std::string label =
            s["case"].get<std::string>() + " " + s["combination"].get<std::string>();
        for (const json& status : s["statuses"]) {
            BOOST_TEST(has_solution(status.get<std::string>()),
                       label << ": a level did not solve: " << status);
        }
        int asymptotic = 0;
        for (const json& row : s["rows"]) {
            const std::string what = label + " level " + std::to_string(row["level"].get<int>()) +
                                     " " + row["quantity"].get<std::string>();
            const double est = row["estimate"]["error"].get<double>();
            const double true_error = row["true_error"].get<double>();
            const bool shown = regime_shown(s["strategy"], row);
            BOOST_TEST(row["asymptotic"].get<bool>() == shown, what);
            if (!row["effectivity"].is_null()) {
                BOOST_TEST(row["effectivity"].get<double>() == est / true_error,
                           boost::test_tools::tolerance(1e-12));
            }
            if (shown) {
                ++asymptotic;
                BOOST_TEST(est >= 0.5 * true_error, what << ": effectivity " << est / true_error);
                BOOST_TEST(est <= 2.0 * true_error, what << ": effectivity " << est / true_error);
            }
            if (row["estimate"]["reliable"].get<bool>() &&
                true_error > row["floor"].get<double>()) {
                BOOST_TEST(true_error <= 3.0 * est, what << ": estimator failure, true "
                                                         << true_error << ", estimate " << est);
            }
        }
        BOOST_TEST(asymptotic >= kMinAsymptoticRows, label << ": " << asymptotic);
        band_checked += asymptotic;
    }
    BOOST_TEST(manufactured == 3);  // both formulations, the mixed one with both companions
    check_dynamic_rows(out["dynamic"]);
    BOOST_TEST_MESSAGE("effectivity study (quick): " << band_checked << " asymptotic rows");
    BOOST_TEST(out["unexplained_failures"] == 0);
    BOOST_TEST(out["band_violations"] == 0);
    BOOST_TEST(std::filesystem::exists(std::filesystem::path(o.out_dir) / "effectivity.png"));
    std::filesystem::remove_all(o.out_dir);
}

}  // namespace rotbeam

namespace rotbeam {

// The static manufactured rod (exact at its quarter points, its tip prescribed to a twist of 2.5π
// about a varying axis) with the mixed formulation and Euler angles on 4, 8 and 16 elements per
// member, each level a `rotbeam run` with its h/2, h/4 estimate. With the support's parameters
// taken as principal values (formulations/mixed/mixed_support_rotation.hpp) every mesh left the
// exact state at λ = 0.45, where the tip's twist passes π, for one a turn away (π rad at the mid
// point, up to 0.16 L) and reported `converged`; the meshes agreed with each other at order 2, so
// the estimates were "reliable" and 1e3 … 1e6 times short: 360 estimator failures in the study's
// full form (docs/studies.md). Asserted: every level solves, no estimator failure, and every
// quantity's true error falls under refinement by at least 4 from 4 to 16 elements (order 2
// gives 16; the failed runs' stayed at the same value). Without the continued support rotation
// the same three runs have 216 failing rows (12 load steps × 3 points × 2 quantities × 3 levels,
// counted on the build before it), each of which fails the first assertion.
BOOST_AUTO_TEST_CASE(mixed_euler_angles_follow_a_prescribed_rotation_past_pi) {
    cli::EffectivitySequence s;
    s.case_name = cli::kManufacturedRodCase;
    for (const cli::Combination& c : cli::all_combinations(false)) {
        if (c.formulation == Formulation::mixed && c.rotation_name() == "euler-angles")
            s.combination = c;
    }
    BOOST_TEST_REQUIRE(s.combination.rotation_name() == "euler-angles");
    s.kind = cli::RefinementKind::h;
    s.reference = cli::ReferenceKind::manufactured_exact;
    s.levels = {4, 8, 16};
    std::vector<cli::LevelQuantities> levels;
    for (size_t k = 0; k < s.levels.size(); ++k) {
        const json r = cli::run_spec(s.spec(k), true);
        BOOST_TEST_REQUIRE(has_solution(r["status"].get<std::string>()), r["status"]);
        levels.push_back(cli::level_quantities(s, r, {}));
    }
    int checked = 0;
    for (const cli::EffectivityRow& row : cli::effectivity_rows(levels, s.kind, 2.0)) {
        BOOST_TEST(!row.failure.has_value(), row.q.quantity << ": " << row.failure.value_or(""));
        if (row.level != 0 || !(row.q.true_error > row.q.floor)) continue;
        ++checked;
        BOOST_TEST(row.next_true[1] < row.q.true_error / 4,
                   row.q.quantity << ": true " << row.q.true_error << " at 4, " << row.next_true[1]
                                  << " at 16 elements per member");
    }
    // 20 load steps × 3 points × 2 quantities, less those at the floor.
    BOOST_TEST(checked >= 100, checked);
}

// The cause of a failure whose true error does not fall under refinement: the rows of the run
// above as they were measured before the support rotation was continued (mid rotation at
// λ = 0.5 on 4, 16 and 64 elements per member: true errors 3.1402, 3.1406, 3.1406 rad, reliable
// estimates 7.3e-4, 4.6e-5, 2.9e-6 at observed orders 1.99 … 2.00). Such a true error is no
// discretization error (one at order 2 falls by 16 over two doublings, it cannot stay within a
// factor 2), so the failure says "other state" and is not counted as unexplained. Without the
// classification (true_error_stalls false) the cause reads "reliable" and this test fails.
BOOST_AUTO_TEST_CASE(effectivity_failures_on_another_state_say_so) {
    std::vector<cli::LevelQuantities> levels;
    const double true_errors[] = {3.1402, 3.1406, 3.1406}, estimates[] = {7.3e-4, 4.6e-5, 2.9e-6};
    for (size_t k = 0; k < 3; ++k) {
        levels.push_back(
            {{"mid rotation at load factor 0.5", json{{"error", estimates[k]}, {"reliable", true}},
              true_errors[k], 1e-9}});
    }
    const auto rows = cli::effectivity_rows(levels, cli::RefinementKind::h, 2.0);
    BOOST_TEST_REQUIRE(rows.size() == 3u);
    for (const cli::EffectivityRow& row : rows) {
        BOOST_TEST_REQUIRE(row.failure.has_value());
        BOOST_TEST(row.other_state);
        BOOST_TEST(row.failure->find("other state") != std::string::npos, *row.failure);
    }
}

// A true error that falls under refinement is a discretization error: a miss there keeps the
// estimate's own verdict. True errors at order 2 (4 per doubling), an estimate 10 × too small.
BOOST_AUTO_TEST_CASE(effectivity_failures_of_a_falling_error_keep_the_estimates_verdict) {
    std::vector<cli::LevelQuantities> levels;
    for (const double e : {1e-2, 2.5e-3, 6.25e-4}) {
        levels.push_back({{"tip displacement at load factor 1",
                           json{{"error", e / 10}, {"reliable", true}}, e, 1e-9}});
    }
    const auto rows = cli::effectivity_rows(levels, cli::RefinementKind::h, 2.0);
    BOOST_TEST_REQUIRE(rows.size() == 3u);
    for (const cli::EffectivityRow& row : rows) {
        BOOST_TEST_REQUIRE(row.failure.has_value());
        BOOST_TEST(!row.other_state);
        BOOST_TEST(row.failure->find("(reliable)") != std::string::npos, *row.failure);
    }
}

// The coarser sequence's rows take their companions' true errors from the two levels below: only
// the finest of three order-2 levels (4 per doubling) is classified, and its rows say which levels
// they rest on (nearer first). Estimates exact: no failure.
BOOST_AUTO_TEST_CASE(coarser_rows_are_classified_from_the_levels_below) {
    std::vector<cli::LevelQuantities> levels;
    for (const double e : {1e-2, 2.5e-3, 6.25e-4}) {
        levels.push_back({{"tip displacement at load factor 1",
                           json{{"error", e}, {"reliable", true}}, e, 1e-9}});
    }
    const auto rows = cli::effectivity_rows(levels, cli::RefinementKind::h_coarser, 2.0);
    BOOST_TEST_REQUIRE(rows.size() == 3u);
    BOOST_TEST(!rows[0].asymptotic);
    BOOST_TEST(!rows[1].asymptotic);
    BOOST_TEST(rows[2].asymptotic);
    BOOST_TEST(rows[2].next_true[0] == 2.5e-3);
    BOOST_TEST(rows[2].next_true[1] == 1e-2);
    BOOST_TEST(std::isnan(rows[0].next_true[0]));
    for (const cli::EffectivityRow& row : rows) BOOST_TEST(!row.failure.has_value());
}

}  // namespace rotbeam
