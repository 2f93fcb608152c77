// The report's tables hold solvers' and the loader's messages as they are: a `|` or a backtick in
// a message stays inside its cell, in index.md (escaped, markdown_cell) and in index.html.
#define BOOST_TEST_MODULE report_markdown
#include <boost/test/unit_test.hpp>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "cases/loader/case_loader.hpp"
#include "core/continuum/continuum.hpp"
#include "reports/report.hpp"
#include "reports/report_estimator_failures.hpp"
#include "reports/report_summary.hpp"
#include "runs/catalog.hpp"
#include "studies/study_common.hpp"
#include "tests/reports/suite_run_files.hpp"

using namespace rotbeam::cli;
namespace fs = std::filesystem;

namespace {

// The cells of a Markdown table row, split at the `|` not escaped by a backslash (CommonMark's
// rule for pipe tables), each with its escapes left as they are.
std::vector<std::string> cells_of(const std::string& row) {
    std::vector<std::string> cells;
    std::string cell;
    for (size_t i = 1; i < row.size(); ++i) {
        if (row[i] == '\\' && i + 1 < row.size()) {
            cell += row.substr(i, 2);
            ++i;
        } else if (row[i] == '|') {
            cells.push_back(cell);
            cell.clear();
        } else {
            cell += row[i];
        }
    }
    return cells;
}

std::string text_of(const fs::path& file) {
    std::ifstream in(file);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

const std::string kMessage = "stopped at step 3: `det J` = 0 | see a\\b";

}  // namespace

BOOST_AUTO_TEST_CASE(markdown_cell_escapes_the_characters_that_end_a_cell_or_open_a_code_span) {
    BOOST_TEST(markdown_cell(kMessage) == "stopped at step 3: \\`det J\\` = 0 \\| see a\\\\b");
    BOOST_TEST(markdown_cell("two\nlines") == "two lines");
    BOOST_TEST(markdown_cell("plain text, 1.5e-3") == "plain text, 1.5e-3");
}

BOOST_AUTO_TEST_CASE(a_stop_message_with_a_pipe_and_backticks_stays_in_its_cell) {
    const fs::path dir = fs::temp_directory_path() / "rotbeam-test-report-markdown";
    fs::remove_all(dir);
    fs::create_directories(dir);
    const nlohmann::json run = {
        {"case", "tip-load-cantilever"},    {"elements", 4},        {"rotation", "quaternion"},
        {"formulation", "displacement"},    {"status", "diverged"}, {"message", kMessage},
        {"steps", nlohmann::json::array()}, {"wall_seconds", 0.5}};
    write_report(dir.string(), rotbeam::test::write_suite_run_files(dir, {run}), {});

    const std::string md = text_of(dir / "index.md");
    // The runs table's row (the summary's matrix has a row of the case too).
    const size_t anchor = md.find("<a id=\"run-1\"></a>tip-load-cantilever |");
    BOOST_TEST_REQUIRE(anchor != std::string::npos);
    const size_t at = md.rfind('\n', anchor) + 1;
    const std::string row = md.substr(at, md.find('\n', at) - at);
    const std::vector<std::string> cells = cells_of(row);
    BOOST_TEST_REQUIRE(cells.size() == 11u);  // the header's eleven columns
    BOOST_TEST(cells[4] == " diverged: " + markdown_cell(kMessage) + " ");

    // The HTML page: the whole message in one cell, as written (no character is special in HTML).
    const std::string html = text_of(dir / "index.html");
    BOOST_TEST(html.find("<td>diverged: " + kMessage + "</td>") != std::string::npos);
    fs::remove_all(dir);
}

namespace {

// A static run of the roll-up (case cantilever-moment: 16 elements of order 4, L = 12, stated
// accuracy 1e-7 for the displacement formulation) with one step, and optionally an estimate of its
// tip at that step.
nlohmann::json rollup_run(const std::string& rotation, const std::string& formulation,
                          const std::string& status, double estimate = -1.0) {
    nlohmann::json step = {
        {"load_factor", 2.0},
        {"newton_iterations", 3},
        // Two full turns: the tip back at the clamp, rotation vector zero.
        {"points",
         {{"tip",
           {{"displacement", {-12.0, 0.0, 1.2e-8}}, {"rotation_vector", {0.0, 0.0, 0.0}}}}}}};
    nlohmann::json run = {{"case", "cantilever-moment"},
                          {"elements", 16},
                          {"elements_per_member", {{"beam", 16}}},
                          {"order", 4},
                          {"options", {{"interpolation", "relative"}, {"wm_map", "plain"}}},
                          {"rotation", rotation},
                          {"formulation", formulation},
                          {"status", status},
                          {"message", "stopped at step 2 <why>"},
                          {"steps", nlohmann::json::array({step})},
                          {"wall_seconds", 0.1}};
    if (estimate >= 0.0) {
        run["estimate"] = {{"status", "estimated"}};
        run["steps"][0]["estimate"] = {
            {"tip",
             {{"displacement", {{"error", estimate}, {"reliable", true}}},
              {"rotation", {{"error", estimate / 120.0}, {"reliable", true}}}}}};
    }
    return run;
}

nlohmann::json check(const std::string& combination, const std::string& quantity,
                     const std::string& result) {
    return {{"case", "cantilever-moment"}, {"reference", "ref-" + result}, {"quantity", quantity},
            {"combination", combination},  {"difference", "1e-10"},        {"result", result}};
}

}  // namespace

// The summary's verdicts, each from hand-made runs and `verify` rows: a check at another
// discretization does not count, a missed one makes the combination inaccurate, an expected stop
// says so, an estimate is held against the case's stated accuracy (1e-7: half of it is 5e-8 of
// L = 12, i.e. 6e-7 in), and the front sentence counts them.
BOOST_AUTO_TEST_CASE(the_summary_says_which_combination_met_its_accuracy_and_links_to_its_run) {
    const fs::path dir = fs::temp_directory_path() / "rotbeam-test-report-summary";
    fs::remove_all(dir);
    fs::create_directories(dir);
    const std::vector<nlohmann::json> runs = {
        rollup_run("quaternion", "displacement", "converged"),
        rollup_run("rodrigues", "displacement", "singular"),
        rollup_run("quaternion", "mixed", "converged"),
        rollup_run("rotation-vector", "mixed", "converged"),
        rollup_run("euler-angles", "displacement", "converged", 1e-7),     // 8e-9 of L: met
        rollup_run("rotation-vector", "displacement", "converged", 1e-6),  // 8e-8 of L: above
        rollup_run("wiener-milenkovic", "displacement", "error")};
    const nlohmann::json checks = {
        check("displacement/quaternion/relative order=4", "displacement", "pass"),
        check("displacement/quaternion/direct order=4", "displacement", "FAIL"),  // not this run
        check("displacement/rodrigues/relative", "stop", "pass"),
        check("mixed/quaternion", "displacement", "FAIL"),
        check("mixed/rotation-vector elements=8", "displacement", "pass")};  // another mesh
    const std::vector<std::string> files = rotbeam::test::write_suite_run_files(dir, runs);
    write_report(dir.string(), files, {}, checks);
    const std::string md = text_of(dir / "index.md");
    // Columns in the order of the runs (the suite plans them in registry order).
    BOOST_TEST(md.find("| cantilever-moment | [met (1)](#run-1) | "
                       "[stopped: singular, expected](#run-2) | [met (estimate)](#run-5) | "
                       "[inaccurate: estimate](#run-6) | [not run](#run-7) |") !=
               std::string::npos);
    BOOST_TEST(md.find("| cantilever-moment | [inaccurate: misses ref-FAIL](#run-3) | "
                       "[unchecked](#run-4) |") != std::string::npos);
    BOOST_TEST(md.find("- **cantilever-moment**: 2 of 7 combinations met their accuracy; "
                       "unchecked: mixed/rotation-vector; stopped: displacement/rodrigues; "
                       "inaccurate: mixed/quaternion, displacement/rotation-vector; not run: "
                       "displacement/wiener-milenkovic.") != std::string::npos);
    // The runs table: the estimate relative to L, the true error against the exact roll-up
    // (λ = 2: the tip is back at the root, u = (−12, 0, 0) exactly; the runs' u₃ is 1.2e-8 off).
    BOOST_TEST(md.find("<a id=\"run-5\"></a>cantilever-moment") != std::string::npos);
    BOOST_TEST(
        md.find("| 8.3e-09 (tip at load factor 2 (displacement)) | 1.0e-09 (exact, ‖Δu‖/L) |") !=
        std::string::npos);
    // The page opens with the summary and the contents, and every heading has its id.
    const std::string html = text_of(dir / "index.html");
    const size_t summary = html.find("<h2><a id=\"summary\"></a>Summary</h2>");
    const size_t contents = html.find("<h2><a id=\"contents\"></a>Contents</h2>");
    const size_t table = html.find("<h2><a id=\"runs\"></a>Runs</h2>");
    BOOST_TEST_REQUIRE(summary != std::string::npos);
    BOOST_TEST(summary < contents);
    BOOST_TEST(contents < table);
    BOOST_TEST(html.find("<a href=\"#runs\">Runs</a>") != std::string::npos);
    BOOST_TEST(html.find("<a href=\"#run-2\">stopped: singular, expected</a>") !=
               std::string::npos);
    // A message is text: its `<` is not a tag.
    BOOST_TEST(html.find("stopped at step 2 &lt;why&gt;") != std::string::npos);
    fs::remove_all(dir);
}

// The 45° bend's true error is measured against its continuum reference (core/continuum, an
// independent solver), at every load step: a run whose tip sits 7.6537e-4 in off the reference at
// P = 450 only is 1.0e-5 off by ‖Δu‖/L (L = 76.537 in, the root–tip chord, the estimates' scale).
BOOST_AUTO_TEST_CASE(the_bend_true_error_is_against_the_continuum_reference_at_every_step) {
    const rotbeam::Model model = rotbeam::load_case(resolve_case_path("bend-45"), {});
    const rotbeam::ContinuumOutcome reference = rotbeam::solve_continuum(model);
    BOOST_TEST_REQUIRE(reference.status == "converged");
    const double chord = (model.points[1].position - model.points[0].position).norm();
    nlohmann::json run = {{"case", "bend-45"},
                          {"rotation", "quaternion"},
                          {"formulation", "displacement"},
                          {"status", "converged"},
                          {"steps", nlohmann::json::array()}};
    for (const rotbeam::ContinuumStep& step : reference.steps) {
        rotbeam::Vec3 u = step.points[1].displacement;
        if (step.load_factor == 450.0) u.z() += 1e-5 * chord;
        run["steps"].push_back({{"load_factor", step.load_factor},
                                {"points", {{"tip", {{"displacement", {u.x(), u.y(), u.z()}}}}}}});
    }
    BOOST_TEST(run["steps"].size() == 3u);
    BOOST_TEST(true_error_cell(run, nlohmann::json::array()) == "1.0e-05 (continuum, ‖Δu‖/L)");
}

// An estimator failure (docs/error-estimates.md) is listed where the true error against the
// continuum reference exceeds 3 × the estimate, and only there: the bend's tip 1e-6 L off the
// reference at P = 450 (L the root–tip chord, the estimates' scale; 1000 × the floor) with a
// reliable estimate of a fifth of that (listed) or of a half (not).
BOOST_AUTO_TEST_CASE(an_estimate_below_a_third_of_the_true_error_is_an_estimator_failure) {
    const rotbeam::Model model = rotbeam::load_case(resolve_case_path("bend-45"), {});
    const rotbeam::ContinuumOutcome reference = rotbeam::solve_continuum(model);
    BOOST_TEST_REQUIRE(reference.status == "converged");
    const double chord = (model.points[1].position - model.points[0].position).norm();
    const auto run_with = [&](double estimate) {
        nlohmann::json run = {{"case", "bend-45"},
                              {"rotation", "quaternion"},
                              {"formulation", "displacement"},
                              {"status", "converged"},
                              {"estimate", {{"status", "estimated"}}},
                              {"steps", nlohmann::json::array()}};
        for (const rotbeam::ContinuumStep& step : reference.steps) {
            rotbeam::Vec3 u = step.points[1].displacement;
            const bool off = step.load_factor == 450.0;
            if (off) u.z() += 1e-6 * chord;
            const nlohmann::json q = {{"error", off ? estimate : 1e-12}, {"reliable", true}};
            run["steps"].push_back(
                {{"load_factor", step.load_factor},
                 {"points", {{"tip", {{"displacement", {u.x(), u.y(), u.z()}}}}}},
                 {"estimate", {{"tip", {{"displacement", q}}}}}});
        }
        return run;
    };
    const std::vector<std::string> missed = estimator_failures(run_with(0.2e-6 * chord));
    BOOST_TEST_REQUIRE(missed.size() == 1u);
    BOOST_TEST(missed[0].find("tip displacement at load factor 450") != std::string::npos,
               missed[0]);
    BOOST_TEST(missed[0].find("(reliable)") != std::string::npos, missed[0]);
    BOOST_TEST(estimator_failures(run_with(0.5e-6 * chord)).empty());
    const std::string listed = estimator_failures_section({run_with(0.2e-6 * chord)});
    BOOST_TEST(listed.find("Runs checked: 1.") != std::string::npos, listed);
    BOOST_TEST(
        listed.find("- bend-45 displacement/quaternion, tip displacement") != std::string::npos,
        listed);
    BOOST_TEST(estimator_failures_section({run_with(0.5e-6 * chord)}).find("None.") !=
               std::string::npos);
}

// A formulation a deck case states it refuses (cases/loader/deck_case.hpp; no catalog deck refuses
// one now, so a deck case written here: the mixed formulation, in stated words) is "refused as
// stated", with the stated words, only when the run was refused in those words; another refusal
// stays "not run", a hole. A solved run of a formulation the case states no accuracy for
// (helix-precessing: none for the mixed) shows its worst estimate beside "unchecked".
BOOST_AUTO_TEST_CASE(a_stated_refusal_is_not_a_hole_and_an_unstated_accuracy_shows_the_estimate) {
    const fs::path dir = fs::temp_directory_path() / "rotbeam-stated-refusal";
    fs::create_directories(dir);
    const std::string deck = (dir / "deck-refused.yaml").string();
    std::ofstream(deck) << "beamdyn:\n  driver: bd_driver.inp\n  refused:\n"
                           "    mixed: \"no stated refusal words here\"\n";
    const auto refused = [&](const std::string& rotation, const std::string& message) {
        return nlohmann::json{{"case", deck},         {"formulation", "mixed"},
                              {"rotation", rotation}, {"status", "error"},
                              {"message", message},   {"steps", nlohmann::json::array()},
                              {"wall_seconds", 0.0}};
    };
    nlohmann::json helix = {{"case", "helix-precessing"},
                            {"formulation", "mixed"},
                            {"rotation", "quaternion"},
                            {"status", "converged"},
                            {"message", ""},
                            {"estimate", {{"status", "estimated"}}},
                            {"steps",
                             {{{"load_factor", 1.0},
                               {"points", {{"tip", {{"displacement", {0.0, 0.0, 0.0}}}}}},
                               {"estimate",
                                {{"tip",
                                  {{"displacement", {{"error", 0.25}, {"reliable", true}}},
                                   {"rotation", {{"error", 1e-3}, {"reliable", true}}}}}}}}}}};
    const std::string md = summary_section(
        {refused("quaternion", "deck-refused.yaml: no stated refusal words here (a test)"),
         refused("rodrigues", "some other refusal"), helix},
        nlohmann::json::array());
    BOOST_TEST(md.find("| " + deck + " | [refused as stated](#run-1) | [not run](#run-2) |") !=
                   std::string::npos,
               md);
    BOOST_TEST(md.find("- **" + deck +
                       "**: 0 of 2 combinations met their accuracy; refused as stated (no stated "
                       "refusal words here): mixed/quaternion; not run: mixed/rodrigues.") !=
                   std::string::npos,
               md);
    BOOST_TEST(md.find("[unchecked: none stated, estimate ") != std::string::npos, md);
}
