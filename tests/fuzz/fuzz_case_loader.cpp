// Fuzz target: the case loader on a YAML text in memory, as `rotbeam check` reads a case file
// (load and validate everything, then describe the model). docs/fuzzing.md.
//
// A finding is anything but a clean refusal: a crash or sanitizer report, any exception other
// than InputError, or an InputError that is not ONE line starting with the file's name.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <typeinfo>

#include "cases/loader/case_loader.hpp"
#include "core/errors.hpp"

namespace {

constexpr const char* kFile = "fuzz.yaml";

[[noreturn]] void finding(const std::string& what) {
    std::fprintf(stderr, "fuzz_case_loader: %s\n", what.c_str());
    std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        const rotbeam::Model model = rotbeam::load_case_text(text, kFile);
        (void)rotbeam::describe_model(model);
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
