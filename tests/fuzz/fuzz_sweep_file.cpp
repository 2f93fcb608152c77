// Fuzz target: the sweep-file reader on a YAML text in memory, as `rotbeam sweep FILE --list`
// reads a sweep file (parse, expand, and validate every value and every run with the case
// loader on the catalog cases). docs/fuzzing.md.
//
// A finding is anything but a clean refusal: a crash or sanitizer report, any exception other
// than InputError, or an InputError that is not ONE line starting with the file's name. An input
// with a '/' is skipped: a case path would open a file the input names (a FIFO blocks), and the
// target reads only the catalog.
#include <cstdint>
#include <string>

#include "distribution/sweep_file.hpp"
#include "tests/fuzz/fuzz_finding.hpp"

namespace {

constexpr const char* kFile = "fuzz.yaml";

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    if (text.find('/') != std::string::npos) return 0;
    rotbeam::fuzz::expect_clean_refusal(
        "fuzz_sweep_file", kFile, [&] { (void)rotbeam::cli::read_sweep_text(text, kFile, ""); });
    return 0;
}
