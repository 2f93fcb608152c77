// Fuzz target: the BeamDyn deck reader and import (docs/beamdyn-import.md) on three files in
// memory, then the case loader on the imported text and the model's description: what
// `rotbeam check DRIVER.inp` does. docs/fuzzing.md.
//
// The input is the driver, the primary and the blade file separated by lines `%%%%` (missing
// files are empty). A finding is anything but a clean refusal: a crash or sanitizer report, any
// exception other than InputError, or an InputError that is not ONE line starting with the name
// of one of the three files.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <typeinfo>

#include "cases/loader/beamdyn_deck.hpp"
#include "cases/loader/beamdyn_import.hpp"
#include "cases/loader/case_loader.hpp"
#include "core/errors.hpp"

namespace {

constexpr const char* kNames[3] = {"driver.inp", "primary.inp", "blade.inp"};

[[noreturn]] void finding(const std::string& what) {
    std::fprintf(stderr, "fuzz_beamdyn_import: %s\n", what.c_str());
    std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string input(reinterpret_cast<const char*>(data), size);
    rotbeam::cases::DeckText files[3];
    size_t start = 0;
    for (int i = 0; i < 3; ++i) {
        files[i].name = kNames[i];
        if (start > input.size()) continue;
        const size_t end = i < 2 ? input.find("\n%%%%\n", start) : std::string::npos;
        files[i].text = input.substr(start, end == std::string::npos ? end : end - start);
        start = end == std::string::npos ? input.size() + 1 : end + 6;
    }
    try {
        const auto deck = rotbeam::cases::parse_beamdyn_deck(files[0], files[1], files[2]);
        const std::string text = rotbeam::cases::beamdyn_case_text(deck, "fuzz");
        const rotbeam::Model model =
            rotbeam::load_case_text(text, std::string(kNames[0]) + " (imported)");
        (void)rotbeam::describe_model(model);
    } catch (const rotbeam::InputError& e) {
        const std::string message = e.what();
        bool named = false;
        for (const char* name : kNames) named = named || message.rfind(name, 0) == 0;
        if (!named) finding("refusal not naming a file: " + message);
        if (message.find('\n') != std::string::npos)
            finding("refusal on several lines: " + message);
    } catch (const std::exception& e) {
        finding(std::string("escaped exception ") + typeid(e).name() + ": " + e.what());
    }
    return 0;
}
