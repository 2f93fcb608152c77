// What the loader reads before the case format: the text (strict UTF-8, one YAML document), the
// place a --set value is reported at, and the names that become parts of file names
// (cases/loader/file_name_part.hpp). The fixtures of cases/bad/ cover the same rules as whole
// files; these tests cover their edges.
#include <boost/test/unit_test.hpp>
#include <string>
#include <vector>

#include "cases/loader/case_loader.hpp"
#include "cases/loader/file_name_part.hpp"
#include "cases/loader/yaml_file.hpp"
#include "core/errors.hpp"
#include "tests/cases/input_error.hpp"

using namespace rotbeam;

namespace {

const std::string kMoment = std::string(ROTBEAM_SOURCE_DIR) + "/cases/cantilever-moment.yaml";

// A valid case without a `name` key: it is named after its file.
const std::string kUnnamed =
    "points: {root: [0, 0, 0], tip: [10, 0, 0]}\n"
    "sections: {square: {isotropic: {E: 1.0e7, nu: 0.3, A: 1.0, I2: 0.0833, I3: 0.0833, "
    "J: 0.14}}}\n"
    "members: {beam: {from: root, to: tip, section: square, elements: 4}}\n"
    "constraints: {root: clamped}\n"
    "loads: {tip-force: {point: tip, force: [0, 0, 1]}}\n"
    "analysis: {type: static, load_factors: [1.0]}\n";

using test::input_error;

bool starts_with(const std::string& text, const std::string& prefix) {
    return text.rfind(prefix, 0) == 0;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(input_text_and_names)

// The well-formed UTF-8 byte sequences are those of RFC 3629, section 4 (the Unicode Standard's
// table 3-7): the boundary characters of each row are accepted, the sequences just outside them
// refused at their first byte.
BOOST_AUTO_TEST_CASE(utf8_is_checked_against_the_table_of_rfc_3629) {
    const std::vector<std::string> accepted = {
        "\x7e",              // U+007E, the last printable ASCII
        "\xc2\x80",          // U+0080, the first of two bytes
        "\xdf\xbf",          // U+07FF
        "\xe0\xa0\x80",      // U+0800, the first of three bytes
        "\xed\x9f\xbf",      // U+D7FF, just below the surrogates
        "\xee\x80\x80",      // U+E000, just above them
        "\xef\xbf\xbf",      // U+FFFF
        "\xf0\x90\x80\x80",  // U+10000, the first of four bytes
        "\xf4\x8f\xbf\xbf",  // U+10FFFF, the last code point
        "\t\r\n"};
    for (const std::string& s : accepted) {
        BOOST_TEST(cases::first_non_text_byte("a" + s + "b") == std::string::npos, s);
    }
    const std::vector<std::string> refused = {
        "\xc0\xaf",          // overlong '/'
        "\xc1\xbf",          // overlong U+007F
        "\xe0\x9f\xbf",      // overlong U+07FF
        "\xf0\x8f\xbf\xbf",  // overlong U+FFFF
        "\xed\xa0\x80",      // U+D800, the first surrogate
        "\xed\xbf\xbf",      // U+DFFF, the last one
        "\xf4\x90\x80\x80",  // U+110000, past the last code point
        "\xf5\x80\x80\x80",  // a lead byte past F4
        "\xff",              // never in UTF-8
        "\x80",              // a continuation byte alone
        "\xe2\x82",          // the euro sign without its third byte, at the end
        "\xe2\x82z",         // ... followed by ASCII
        "\xf0\x90\x80",      // four bytes cut to three
        "\x7f",              // DEL, a control character
        std::string(1, '\0')};
    for (const std::string& s : refused) {
        BOOST_TEST(cases::first_non_text_byte("ab" + s) == 2u, s);
    }
}

// yaml-cpp reads the first document and drops the rest: a second is refused wherever it starts
// (a marker, or a line less indented than an indented first document, or after a flow mapping),
// and only then: an explicit start and end of the one document are fine.
BOOST_AUTO_TEST_CASE(a_second_yaml_document_is_refused_with_its_line) {
    const std::string second = ": (yaml): a second YAML document starts here";
    BOOST_TEST(starts_with(input_error([&] { load_case_text(kUnnamed + "---\n", "t.yaml"); }),
                           "t.yaml:7" + second));
    BOOST_TEST(starts_with(
        input_error([&] { load_case_text(kUnnamed + "...\n# note\n---\n{a: 1}\n", "t.yaml"); }),
        "t.yaml:9" + second));
    const std::string flow = "{points: {root: [0, 0, 0], tip: [10, 0, 0]}}\nsections: {}\n";
    BOOST_TEST(
        starts_with(input_error([&] { load_case_text(flow, "t.yaml"); }), "t.yaml:2" + second));
    BOOST_TEST(input_error([&] {
                   load_case_text("---\n" + kUnnamed + "...\n# end\n", "t.yaml");
               }).empty());
    // A --set value is one document too.
    const std::string value =
        input_error([&] { load_case(kMoment, {"description=first\n---\nsecond"}); });
    BOOST_TEST(starts_with(value, kMoment + ":--set: description: the value: a second YAML "
                                            "document starts here; a --set value holds one "
                                            "document"),
               value);
}

// A value from --set is reported at `:--set:`, a list item too (the tree's marks of a value
// parsed from the command line are those of its own one-line text, not of the file).
BOOST_AUTO_TEST_CASE(a_bad_list_item_from_set_is_reported_at_set) {
    const std::string list =
        input_error([&] { load_case(kMoment, {"analysis.load_factors=[nan]"}); });
    BOOST_TEST(starts_with(list, kMoment + ":--set: analysis.load_factors[0]: "), list);
    const std::string item = input_error([&] { load_case(kMoment, {"points.tip.1=.nan"}); });
    BOOST_TEST(starts_with(item, kMoment + ":--set: points.tip[1]: must be finite"), item);
    // An item of the file keeps its line.
    std::string text = kUnnamed;
    text.replace(text.find("[1.0]"), 5, "[1.0, nan]");
    const std::string file = input_error([&] { load_case_text(text, "t.yaml"); });
    BOOST_TEST(starts_with(file, "t.yaml:6: analysis.load_factors[1]: "), file);
}

BOOST_AUTO_TEST_CASE(a_file_name_part_has_a_documented_character_set_and_length) {
    const std::vector<std::string> names = {"a",
                                            "cantilever-moment",
                                            "NREL_5MW.v2",
                                            "x-",
                                            "_x",
                                            "1",
                                            std::string(cases::kMaxFileNamePart, 'z')};
    for (const std::string& ok : names) {
        BOOST_TEST(cases::file_name_part_problem(ok).empty(), ok);
    }
    for (const std::string& bad : std::vector<std::string>{
             std::string(), std::string(cases::kMaxFileNamePart + 1, 'z'), std::string("a/b"),
             std::string(".."), std::string("../x"), std::string(".x"), std::string("a..b"),
             std::string("a b"), std::string("a\\b"), std::string("a:b"),
             std::string("caf\xc3\xa9"), std::string("a\nb")}) {
        const std::string problem = cases::file_name_part_problem(bad);
        BOOST_TEST(starts_with(problem, "'"), bad);
        BOOST_TEST(problem.find('\n') == std::string::npos, problem);
    }
}

// The name names the run's files (`OUT/NAME_ROTATION_FORMULATION.json`): from the file, from
// --set, or from the file's own name when it has none, it is checked the same way.
BOOST_AUTO_TEST_CASE(the_case_name_is_a_file_name_part_wherever_it_comes_from) {
    const std::string set = input_error([&] { load_case(kMoment, {"name=../../etc/x"}); });
    BOOST_TEST(starts_with(set, kMoment + ":--set: name: '../../etc/x' cannot be part of a file "
                                          "name: it holds '/'"),
               set);
    BOOST_TEST(input_error([&] { load_case(kMoment, {"name=beam-2.v1"}); }).empty());
    BOOST_TEST(load_case(kMoment, {"name=beam-2.v1"}).name == "beam-2.v1");
    BOOST_TEST(load_case_text(kUnnamed, "dir/my-beam.yaml").name == "my-beam");
    const std::string stem = input_error([&] { load_case_text(kUnnamed, "dir/my beam.yaml"); });
    BOOST_TEST(starts_with(stem,
                           "dir/my beam.yaml:1: name: missing, so the case is named after "
                           "its file, but 'my beam' cannot be part of a file name"),
               stem);
    BOOST_TEST(load_case_text(kUnnamed, "dir/my beam.yaml", {"name=my-beam"}).name == "my-beam");
}

BOOST_AUTO_TEST_SUITE_END()
