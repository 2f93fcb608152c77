// Fuzz target: the case loader on a YAML text in memory, as `rotbeam check` reads a case file
// (load and validate everything, then describe the model). docs/fuzzing.md.
//
// A finding is anything but a clean refusal: a crash or sanitizer report, any exception other
// than InputError, or an InputError that is not ONE line starting with the file's name.
#include <cstdint>
#include <string>

#include "cases/loader/case_loader.hpp"
#include "tests/fuzz/fuzz_finding.hpp"

namespace {

constexpr const char* kFile = "fuzz.yaml";

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    rotbeam::fuzz::expect_clean_refusal("fuzz_case_loader", kFile, [&] {
        const rotbeam::Model model = rotbeam::load_case_text(text, kFile);
        (void)rotbeam::describe_model(model);
    });
    return 0;
}
