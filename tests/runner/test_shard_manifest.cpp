// The shard manifest reader (distribution/shard_manifest.hpp): real manifests read back, damaged
// ones refused with one line naming the file and the key. The inputs are the seed corpus of the
// manifest's fuzz target (tests/fuzz/corpus/fuzz_shard_manifest, docs/fuzzing.md): `real-*`
// written by `rotbeam suite|study --shard`, `damaged-*` made from them by hand, and `crash-*` the
// inputs the fuzzer found that once ended in a crash, a sanitizer report or an escaped exception.
#define BOOST_TEST_MODULE rotbeam shard manifest
#include <boost/test/unit_test.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/errors.hpp"
#include "distribution/shard_manifest.hpp"

using namespace rotbeam;
using namespace rotbeam::cli;
namespace fs = std::filesystem;

namespace {

const fs::path kCorpus = fs::path(ROTBEAM_SOURCE_DIR) / "tests/fuzz/corpus/fuzz_shard_manifest";

std::string read(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

// The refusal of `text` read from `file` (empty when it is accepted).
std::string refusal(const std::string& text, const std::string& file = "d/shard.json") {
    try {
        (void)parse_shard_manifest(text, file);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

std::string with(const std::string& key, const std::string& value) {
    return R"({"format": "rotbeam-shard", "version": "v", "job": {"command": "suite", "study": "",
        "cases": "*", "quick": true, "studies": false, "reduced_follower": false,
        "estimate": true, "sweep": ""},
        "shard": 1, "of": 3, "units": ["runs/a.json"], )" +
           ("\"" + key + "\": " + value + "}");
}

}  // namespace

BOOST_AUTO_TEST_CASE(real_manifests_are_read_back) {
    int n = 0;
    for (const auto& entry : fs::directory_iterator(kCorpus)) {
        if (entry.path().filename().string().rfind("real-", 0) != 0) continue;
        const ShardManifest m = parse_shard_manifest(read(entry.path()), "shard.json");
        BOOST_TEST(
            (m.job.command == "suite" || m.job.command == "study" || m.job.command == "sweep"));
        BOOST_TEST(m.shard.index >= 1);
        BOOST_TEST(m.shard.index <= m.shard.count);
        ++n;
    }
    BOOST_TEST(n >= 5);
}

// Every damaged manifest and every input the fuzzer once crashed on: refused, on one line that
// starts with the file's name (or, for a crash input that happens to be a valid manifest, read).
BOOST_AUTO_TEST_CASE(damaged_manifests_are_refused_on_one_line_naming_the_file) {
    int damaged = 0;
    for (const auto& entry : fs::directory_iterator(kCorpus)) {
        const std::string name = entry.path().filename().string();
        const bool is_damaged = name.rfind("damaged-", 0) == 0;
        if (!is_damaged && name.rfind("crash-", 0) != 0) continue;
        const std::string why = refusal(read(entry.path()), "x/shard.json");
        BOOST_TEST_CONTEXT(name) {
            if (is_damaged) BOOST_TEST(!why.empty());
            if (!why.empty()) {
                BOOST_TEST(why.rfind("x/shard.json: ", 0) == 0u);
                BOOST_TEST(why.find('\n') == std::string::npos);
            }
        }
        damaged += is_damaged;
    }
    BOOST_TEST(damaged >= 20);
}

// The numbers that size merge's work (the shard count it lists missing folders up to) are whole
// numbers in 1 ≤ shard ≤ of ≤ kMaxShards, checked before they are converted: 1e300 or 2^64 − 1
// was once converted to int (undefined behaviour) and a shard of 0 or past `of` accepted.
BOOST_AUTO_TEST_CASE(shard_and_of_are_whole_numbers_in_range) {
    BOOST_TEST(refusal(with("timed_by", "[]")).empty());
    for (const char* of : {"1e300", "18446744073709551615", "-3", "0", "2.5", "100001", "\"3\""}) {
        BOOST_TEST_CONTEXT(of) {
            BOOST_TEST(refusal(with("of", of)).find("d/shard.json: of: ") == 0u);
        }
    }
    for (const char* shard : {"0", "4", "-1", "1e300", "true"}) {
        BOOST_TEST_CONTEXT(shard) {
            BOOST_TEST(refusal(with("shard", shard)).find("d/shard.json: shard: ") == 0u);
        }
    }
    BOOST_TEST(refusal(with("of", "100000")).empty());
}

// A key of another type is refused by name, not as an escaped library exception (a number for
// `format` once ended in "internal error", exit 3).
BOOST_AUTO_TEST_CASE(keys_of_another_type_are_named) {
    BOOST_TEST(refusal(with("format", "5")) == "d/shard.json: format: not a rotbeam shard file");
    BOOST_TEST(refusal(with("version", "12")).find("d/shard.json: version: ") == 0u);
    BOOST_TEST(refusal(with("units", "[1]")).find("d/shard.json: units: ") == 0u);
    BOOST_TEST(refusal(with("job", "[]")).find("d/shard.json: job: ") == 0u);
    const std::string command =
        refusal(with("job", R"({"command": "a\nb", "study": "", "cases": "*", "quick": true,
                   "studies": false, "reduced_follower": false, "estimate": true,
                   "sweep": ""})"));
    BOOST_TEST(command.find("d/shard.json: job: command: ") == 0u);
    BOOST_TEST(command.find('\n') == std::string::npos);
}
