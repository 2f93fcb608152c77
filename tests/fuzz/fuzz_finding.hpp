// What a fuzz target counts as a finding (docs/fuzzing.md): a crash or a sanitizer report (the
// runtimes stop on those themselves), any exception other than InputError, or an InputError that
// is not ONE line starting with the name of the file it refuses.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <typeinfo>

#include "core/errors.hpp"

namespace rotbeam::fuzz {

// Stops the fuzzer on a finding, naming the target.
[[noreturn]] inline void finding(const char* target, const std::string& what) {
    std::fprintf(stderr, "%s: %s\n", target, what.c_str());
    std::abort();
}

// Runs `body` (a parse of the input named `file`): it is accepted, or refused cleanly.
template <class Body>
void expect_clean_refusal(const char* target, const std::string& file, Body&& body) {
    try {
        body();
    } catch (const InputError& e) {
        const std::string message = e.what();
        if (message.rfind(file, 0) != 0) finding(target, "refusal not naming the file: " + message);
        if (message.find('\n') != std::string::npos)
            finding(target, "refusal on several lines: " + message);
    } catch (const std::exception& e) {
        finding(target, std::string("escaped exception ") + typeid(e).name() + ": " + e.what());
    }
}

}  // namespace rotbeam::fuzz
