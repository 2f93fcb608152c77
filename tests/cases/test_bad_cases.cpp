// The bad-input corpus (cases/bad/): every file is refused with ONE line
// `FILE:LINE: KEY: problem` carrying the expected fragment, as an InputError — never a crash,
// never another exception type.
#include <boost/test/unit_test.hpp>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <utility>
#include <vector>

#include "cases/loader/case_loader.hpp"
#include "cases/loader/limits.hpp"
#include "core/errors.hpp"

using namespace rotbeam;

namespace {

const std::string kBadDir = std::string(ROTBEAM_SOURCE_DIR) + "/cases/bad/";

// expected.txt: `file | fragment` per line, '#' comments.
std::map<std::string, std::string> expected_fragments() {
    std::map<std::string, std::string> out;
    std::ifstream in(kBadDir + "expected.txt");
    BOOST_REQUIRE(in.good());
    for (std::string line; std::getline(in, line);) {
        if (line.empty() || line[0] == '#') continue;
        const size_t bar = line.find(" | ");
        BOOST_REQUIRE(bar != std::string::npos);
        out[line.substr(0, bar)] = line.substr(bar + 3);
    }
    return out;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(bad_input_corpus)

BOOST_AUTO_TEST_CASE(corpus_has_at_least_twenty_files_all_listed) {
    const auto expected = expected_fragments();
    BOOST_TEST(expected.size() >= 20u);
    std::set<std::string> on_disk;
    for (const auto& e : std::filesystem::directory_iterator(kBadDir)) {
        const std::string name = e.path().filename().string();
        if (name != "expected.txt") on_disk.insert(name);
    }
    for (const std::string& name : on_disk) {
        BOOST_TEST(expected.count(name) == 1u, name << " has no expected message");
    }
    for (const auto& [name, fragment] : expected) {
        BOOST_TEST(on_disk.count(name) == 1u, name << " is listed but missing");
    }
}

BOOST_AUTO_TEST_CASE(every_bad_file_gives_one_line_naming_file_line_key_and_problem) {
    for (const auto& [name, fragment] : expected_fragments()) {
        BOOST_TEST_CONTEXT(name) {
            const std::string path = kBadDir + name;
            std::string message;
            bool input_error = false;
            try {
                load_case(path);
            } catch (const InputError& e) {
                input_error = true;
                message = e.what();
            } catch (const std::exception& e) {
                message = std::string("wrong exception type: ") + e.what();
            }
            BOOST_TEST(input_error, message);
            BOOST_TEST(message.rfind(path + ":", 0) == 0u, message);
            BOOST_TEST(message.find(fragment) != std::string::npos,
                       "'" << message << "' lacks '" << fragment << "'");
            BOOST_TEST(message.find('\n') == std::string::npos, message);
        }
    }
}

BOOST_AUTO_TEST_CASE(missing_file_and_directory_are_input_errors) {
    BOOST_CHECK_THROW(load_case(kBadDir + "does-not-exist.yaml"), InputError);
    BOOST_CHECK_THROW(load_case(kBadDir), InputError);
}

// Text past the size limit is refused before it is parsed, and an override's value gets the
// shape checks of a file (a recursive alias in `--set` would otherwise loop like one in a file).
BOOST_AUTO_TEST_CASE(oversized_text_and_recursive_override_values_are_one_line_input_errors) {
    const std::string huge(cases::kMaxFileBytes + 1, '#');
    try {
        load_case_text(huge, "huge.yaml");
        BOOST_FAIL("oversized text accepted");
    } catch (const InputError& e) {
        BOOST_TEST(std::string(e.what()) ==
                   "huge.yaml:1: (file): larger than 1048576 bytes (a limit of the case format)");
    }
    const std::string path = std::string(ROTBEAM_SOURCE_DIR) + "/cases/cantilever-moment.yaml";
    try {
        load_case(path, {"points.tip=&a [*a]"});
        BOOST_FAIL("recursive override accepted");
    } catch (const InputError& e) {
        const std::string m = e.what();
        BOOST_TEST(m.rfind(path + ":--set: points.tip: the value: alias *a is inside", 0) == 0u, m);
    }
}

// The limits admit the whole catalog: each size key at its limit is accepted (the limit is
// inclusive), one past it is refused.
BOOST_AUTO_TEST_CASE(each_size_limit_is_inclusive) {
    const std::string path = std::string(ROTBEAM_SOURCE_DIR) + "/cases/cantilever-moment.yaml";
    const std::vector<std::pair<std::string, long>> keys = {
        {"discretization.order", cases::kMaxOrder},
        {"discretization.quadrature_points", cases::kMaxQuadraturePoints},
        {"analysis.max_step_cuts", cases::kMaxStepCuts},
        {"solver.max_iterations", cases::kMaxNewtonIterations}};
    for (const auto& [key, limit] : keys) {
        BOOST_TEST_CONTEXT(key) {
            BOOST_CHECK_NO_THROW(load_case(path, {key + "=" + std::to_string(limit)}));
            BOOST_CHECK_THROW(load_case(path, {key + "=" + std::to_string(limit + 1)}), InputError);
        }
    }
    // analysis.load_factors limits a list's length: kMaxLoadFactors increasing factors are
    // accepted, one more is refused by that limit (not by the sub-step product, which with one
    // sub-step per factor stays far below its own).
    const auto factors = [](long count) {
        std::string list = "analysis.load_factors=[";
        for (long i = 1; i <= count; ++i) {
            if (i > 1) list += ',';
            list += std::to_string(i);
        }
        return list + "]";
    };
    BOOST_CHECK_NO_THROW(load_case(path, {factors(cases::kMaxLoadFactors)}));
    try {
        load_case(path, {factors(cases::kMaxLoadFactors + 1)});
        BOOST_FAIL("one load factor past the limit accepted");
    } catch (const InputError& e) {
        const std::string m = e.what();
        BOOST_TEST(m.find(":--set: analysis.load_factors: has 10001 entries, more than 10000") !=
                       std::string::npos,
                   m);
    }
    // refine belongs to the trapezoidal rule: its limit is checked with it.
    const std::string trapezoidal = "discretization.quadrature=trapezoidal";
    const std::string refine = "discretization.refine=";
    BOOST_CHECK_NO_THROW(
        load_case(path, {trapezoidal, refine + std::to_string(cases::kMaxRefine)}));
    BOOST_CHECK_THROW(
        load_case(path, {trapezoidal, refine + std::to_string(cases::kMaxRefine + 1)}), InputError);
}

BOOST_AUTO_TEST_SUITE_END()
