// The reader of result files read back (runs/run_file.hpp): real results accepted, damaged ones
// refused with one line naming the file and the JSON key. The real results are the seed corpus
// of the reader's fuzz target (tests/fuzz/corpus/fuzz_run_file, docs/fuzzing.md): `quick-*`
// written by `rotbeam suite --quick`, `dynamic-*` and `modal-*` by the whole suite (cut to their
// first steps); `crash-*` are inputs the fuzzer found that once ended in a crash, a sanitizer
// report or an escaped exception.
#define BOOST_TEST_MODULE rotbeam run file
#include <boost/test/unit_test.hpp>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>

#include "core/errors.hpp"
#include "runs/run_file.hpp"

using namespace rotbeam;
using json = nlohmann::json;
namespace fs = std::filesystem;

namespace {

const fs::path kCorpus = fs::path(ROTBEAM_SOURCE_DIR) / "tests/fuzz/corpus/fuzz_run_file";
const std::string kFile = "out/runs/r.json";

std::string read(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

bool real(const fs::path& p) {
    const std::string name = p.filename().string();
    return name.rfind("quick-", 0) == 0 || name.rfind("dynamic-", 0) == 0 ||
           name.rfind("modal-", 0) == 0;
}

// The refusal of `text` (empty when it is accepted).
std::string refusal(const std::string& text, RunFileKind kind = RunFileKind::case_run) {
    try {
        (void)parse_run_file(text, kFile, kind, std::nullopt);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

json good() { return json::parse(read(kCorpus / "quick-cantilever-moment_rodrigues_mixed.json")); }

json damaged(const std::function<void(json&)>& change) {
    json j = good();
    change(j);
    return j;
}

void check_refused(const std::string& text, const std::string& key,
                   RunFileKind kind = RunFileKind::case_run) {
    const std::string message = refusal(text, kind);
    BOOST_TEST_INFO("refusal: " << message);
    BOOST_TEST(message.rfind(kFile + ": " + key, 0) == 0);
    BOOST_TEST(message.find('\n') == std::string::npos);
}

}  // namespace

BOOST_AUTO_TEST_CASE(real_results_are_read_back) {
    int n = 0;
    for (const auto& entry : fs::directory_iterator(kCorpus)) {
        if (!real(entry.path())) continue;
        BOOST_TEST_INFO(entry.path().filename().string());
        BOOST_TEST(refusal(read(entry.path())).empty());
        ++n;
    }
    BOOST_TEST(n >= 4);
}

BOOST_AUTO_TEST_CASE(a_damaged_result_is_refused_naming_the_key) {
    using J = json&;
    check_refused(damaged([](J j) { j["status"] = 5; }).dump(), "status: expected a string");
    check_refused(damaged([](J j) { j.erase("steps"); }).dump(), "steps: missing");
    check_refused(damaged([](J j) { j["steps"][1]["load_factor"] = "a"; }).dump(),
                  "steps[1].load_factor: expected a finite number");
    check_refused(damaged([](J j) { j["steps"][0].erase("load_factor"); }).dump(),
                  "steps[0].load_factor: missing (nor time)");
    check_refused(
        damaged([](J j) { j["steps"][0]["points"]["tip"]["displacement"][2] = nullptr; }).dump(),
        "steps[0].points.tip.displacement[2]: expected a finite number");
    check_refused(
        damaged([](J j) { j["steps"][0]["points"]["tip"].erase("rotation_vector"); }).dump(),
        "steps[0].points.tip.rotation_vector: missing");
    check_refused(damaged([](J j) { j["steps"][0]["newton_iterations"] = -1; }).dump(),
                  "steps[0].newton_iterations: expected a whole number");
    check_refused(damaged([](J j) { j["schema_version"] = 2; }).dump(), "schema_version: ");
    check_refused(damaged([](J j) { j["schema_version"] = "3"; }).dump(),
                  "schema_version: expected a whole number");
    check_refused(damaged([](J j) { j.erase("input_key"); }).dump(), "input_key: missing");
    check_refused(damaged([](J j) { j["options"] = json::array(); }).dump(),
                  "options: expected an object");
    // The report's Table III reads a modal run's options without looking.
    check_refused(damaged([](J j) {
                      j["frequencies_hz"] = {1.0};
                      j.erase("options");
                  }).dump(),
                  "options: missing (required with frequencies_hz)");
    // A key of another name is shown quoted, so that the line stays one line.
    check_refused(damaged([](J j) { j["steps"][0]["points"]["a\nb"] = 1; }).dump(),
                  "steps[0].points[\"a\\nb\"]: expected an object");
    check_refused("[1, 2]", "(top level): expected a JSON object");
}

BOOST_AUTO_TEST_CASE(text_that_is_not_a_result_is_refused) {
    const std::string text = good().dump(1);
    check_refused(text.substr(0, text.size() / 2), "not complete JSON");
    check_refused("", "not complete JSON");
    // Beyond the double range: no infinity is read into a result.
    std::string huge = text;
    huge.replace(huge.find("\"load_factor\": ") + 15, 1, "1e999,\"x\":");
    check_refused(huge, "not valid JSON");
    check_refused(std::string(100, '[') + std::string(100, ']'), "(top level): expected a JSON");
    // Nesting beyond any result's, under a key no reader uses: refused, not walked into.
    const std::string deep =
        "{\"x\": " + std::string(40, '[') + std::string(40, ']') + ", " + good().dump().substr(1);
    check_refused(deep, "x[0][0]");
    BOOST_TEST(refusal(deep).find("nested deeper than") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(a_file_of_other_inputs_is_not_checked_further) {
    // Another input key (another version's file, perhaps another schema): not current, not damaged.
    json j = good();
    j["schema_version"] = 2;
    j.erase("steps");
    BOOST_TEST(!parse_run_file(j.dump(), kFile, RunFileKind::case_run, std::string("other")));
    // The plan's key: checked, and refused.
    BOOST_CHECK_THROW(
        parse_run_file(j.dump(), kFile, RunFileKind::case_run, j["input_key"].get<std::string>()),
        InputError);
    BOOST_TEST(parse_run_file(good().dump(), kFile, RunFileKind::case_run,
                              good()["input_key"].get<std::string>())
                   .has_value());
}

BOOST_AUTO_TEST_CASE(study_records_are_checked) {
    const json run = {{"study", "convergence"},
                      {"key", "k"},
                      {"input_key", "i"},
                      {"seconds", 0.5},
                      {"result", json::object()}};
    BOOST_TEST(refusal(run.dump(), RunFileKind::study_run).empty());
    json no_result = run;
    no_result.erase("result");
    check_refused(no_result.dump(), "result: missing", RunFileKind::study_run);
    json text_result = run;
    text_result["result"] = "x";
    check_refused(text_result.dump(), "result: expected an object", RunFileKind::study_run);
    const json whole = {{"study", "extremes"},
                        {"input_key", "i"},
                        {"seconds", 2},
                        {"files", {"study-extremes.md"}}};
    BOOST_TEST(refusal(whole.dump(), RunFileKind::whole_study).empty());
    json numbers = whole;
    numbers["files"] = {1};
    check_refused(numbers.dump(), "files[0]: expected a string", RunFileKind::whole_study);
}

BOOST_AUTO_TEST_CASE(the_fuzzers_crash_inputs_are_refused_on_one_line) {
    for (const auto& entry : fs::directory_iterator(kCorpus)) {
        if (entry.path().filename().string().rfind("crash-", 0) != 0) continue;
        for (const RunFileKind kind :
             {RunFileKind::case_run, RunFileKind::study_run, RunFileKind::whole_study}) {
            const std::string message = refusal(read(entry.path()), kind);
            BOOST_TEST_INFO(entry.path().filename().string() << ": " << message);
            BOOST_TEST((message.empty() ||
                        (message.rfind(kFile, 0) == 0 && message.find('\n') == std::string::npos)));
        }
    }
}
