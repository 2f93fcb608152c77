// Fuzz target: the sweep-file reader on a YAML text in memory, as `rotbeam sweep FILE --list`
// reads a sweep file (parse, expand, and validate every value and every run with the case
// loader on the catalog cases). docs/fuzzing.md.
//
// A finding is anything but a clean refusal: a crash or sanitizer report, any exception other
// than InputError, or an InputError that is not ONE line starting with the file's name. An input
// with a '/' is skipped: a case path would open a file the input names (a FIFO blocks), and the
// target reads only the catalog.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <typeinfo>

#include "cases/runner/sweep_file.hpp"
#include "core/errors.hpp"

namespace {

constexpr const char* kFile = "fuzz.yaml";

[[noreturn]] void finding(const std::string& what) {
    std::fprintf(stderr, "fuzz_sweep_file: %s\n", what.c_str());
    std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    if (text.find('/') != std::string::npos) return 0;
    try {
        (void)rotbeam::cli::read_sweep_text(text, kFile, "");
    } catch (const rotbeam::InputError& e) {
        const std::string message = e.what();
        if (message.rfind(kFile, 0) != 0) finding("refusal not naming the file: " + message);
        if (message.find('\n') != std::string::npos)
            finding("refusal on several lines: " + message);
    } catch (const std::exception& e) {
        finding(std::string("escaped exception ") + typeid(e).name() + ": " + e.what());
    }
    return 0;
}
