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

#include "reports/report.hpp"
#include "studies/study_common.hpp"

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
    std::ofstream((dir / "run.json").string()) << run.dump();
    write_report(dir.string(), {(dir / "run.json").string()}, {});

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
