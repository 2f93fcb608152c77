// Fuzz target: the command line. The input is an argument vector (arguments separated by NUL or
// newline; the first one is the command). It goes through the parser of cases/runner/arguments.*
// with each command's option shapes, the numeric validators with the documented limits, and, for
// `check` and `run`, the --set overrides and the shorthand options into the case loader on a
// catalog case — everything the program does before a solve, and no solve. docs/fuzzing.md.
//
// The option tables of the commands live inside the command functions (cases/runner/*.cpp),
// which also run the solves, so the target would have to link the whole program to read them; they
// are mirrored here instead, and the test fuzz_command_line_table (command_table.sh) fails when the
// copy drifts: it compares the help this table prints (ROTBEAM_FUZZ_PRINT_TABLE=1) with the
// program's own `rotbeam COMMAND --help` for every command the program lists. A finding is
// anything but a clean refusal: a crash or sanitizer report, any exception other than InputError,
// or a multi-line message.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <typeinfo>
#include <vector>

#include "cases/loader/case_loader.hpp"
#include "cases/runner/arguments.hpp"
#include "core/errors.hpp"
#include "runs/shards.hpp"

using rotbeam::cli::CommandSpec;
using rotbeam::cli::OptionSpec;
using rotbeam::cli::ParsedArguments;

namespace {

const OptionSpec kSet{"set", "KEY.PATH=VALUE", "", true};

const std::map<std::string, CommandSpec>& specs() {
    static const std::map<std::string, CommandSpec> table = {
        {"list", {"list", "", 0, 0, "", {}}},
        {"check", {"check", "CASE.yaml", 1, 1, "", {kSet}}},
        {"run",
         {"run",
          "CASE.yaml",
          1,
          1,
          "",
          {{"rotation", "NAME", ""},
           {"formulation", "NAME", ""},
           {"elements", "N", ""},
           {"order", "P", ""},
           {"interpolation", "NAME", ""},
           kSet,
           {"out", "DIR", ""},
           {"json", "FILE", ""},
           {"quiet", "", ""},
           {"trace-newton", "", ""},
           {"time-limit", "SECONDS", ""},
           {"vtk", "DIR", ""},
           {"estimate", "on|off", ""},
           {"frame", "rotbeam|beamdyn", ""},
           {"accuracy", "TOL", ""}}}},
        {"reference",
         {"reference",
          "CASE.yaml",
          1,
          1,
          "",
          {kSet, {"json", "FILE", ""}, {"out", "DIR", ""}, {"quiet", "", ""}}}},
        {"study",
         {"study",
          "NAME",
          1,
          1,
          "",
          {{"json", "FILE", ""},
           {"samples", "N", ""},
           {"out", "DIR", ""},
           {"quick", "", ""},
           {"reduced-follower", "", ""},
           {"shard", "I/N", ""},
           {"timings", "DIR", "", true},
           {"jobs", "N", ""}}}},
        {"suite",
         {"suite",
          "",
          0,
          0,
          "",
          {{"out", "DIR", ""},
           {"jobs", "N", ""},
           {"cases", "GLOB", ""},
           {"force", "", ""},
           {"quick", "", ""},
           {"studies", "", ""},
           {"no-studies", "", ""},
           {"estimate", "on|off", ""},
           {"time-limit", "SECONDS", ""},
           {"shard", "I/N", ""},
           {"timings", "DIR", "", true}}}},
        {"sweep",
         {"sweep",
          "FILE",
          1,
          1,
          "",
          {{"out", "DIR", ""},
           {"jobs", "N", ""},
           {"force", "", ""},
           {"list", "", ""},
           {"time-limit", "SECONDS", ""},
           {"shard", "I/N", ""},
           {"timings", "DIR", "", true}}}},
        {"merge", {"merge", "SHARD_DIR...", 1, -1, "", {{"out", "DIR", ""}}}},
        {"completion", {"completion", "bash", 1, 1, "", {{"out", "FILE", ""}}}},
        {"verify", {"verify", "[CASE ...]", 0, -1, "", {{"json", "FILE", ""}}}},
        {"import", {"import", "beamdyn DRIVER.inp", 2, 2, "", {{"out", "CASE.yaml", ""}}}},
        {"bench",
         {"bench",
          "",
          0,
          0,
          "",
          {{"json", "FILE", ""},
           {"history", "", ""},
           {"repeats", "N", ""},
           {"quick", "", ""},
           {"targets", "LIST", ""},
           {"references", "DIR", ""}}}},
    };
    return table;
}

// The catalog case text, read once; the positional argument picks one by name, else the first.
const std::string& catalog_text(const std::string& name) {
    static std::map<std::string, std::string> texts;
    static const char* const names[] = {"tip-load-cantilever", "cantilever-moment", "helix",
                                        "joined-beam",         "free-vibration",    "blade-mh104"};
    std::string chosen = names[0];
    for (const char* n : names) {
        if (name == n) chosen = n;
    }
    auto it = texts.find(chosen);
    if (it == texts.end()) {
        std::ifstream in(std::string(ROTBEAM_CASES_DIR) + "/" + chosen + ".yaml");
        std::ostringstream s;
        s << in.rdbuf();
        it = texts.emplace(chosen, s.str()).first;
    }
    return it->second;
}

void parse(const std::vector<std::string>& argv) {
    if (argv.empty()) return;
    const auto it = specs().find(argv[0]);
    if (it == specs().end()) return;  // main's unknown-command message: no parsing
    const CommandSpec& spec = it->second;
    const ParsedArguments a =
        rotbeam::cli::parse_arguments(spec, std::vector<std::string>(argv.begin() + 1, argv.end()));
    if (a.help) {
        (void)rotbeam::cli::help_text(spec);
        return;
    }
    (void)a.positive_int("suite", "jobs", rotbeam::cli::kMaxJobs);
    (void)a.positive_int("bench", "repeats", rotbeam::cli::kMaxRepeats);
    (void)a.positive_int("study", "samples", rotbeam::cli::kMaxSamples, 2);
    (void)rotbeam::cli::time_limit_option(a, spec.name);
    if (const auto shard = a.value("shard")) (void)rotbeam::cli::parse_shard(spec.name, *shard);
    if (spec.name == "check" || spec.name == "run" || spec.name == "reference") {
        const rotbeam::Model model = rotbeam::load_case_text(
            catalog_text(a.positional[0]), "case.yaml", rotbeam::cli::case_overrides(a));
        (void)rotbeam::describe_model(model);
    }
}

[[noreturn]] void finding(const std::string& what) {
    std::fprintf(stderr, "fuzz_command_line: %s\n", what.c_str());
    std::abort();
}

}  // namespace

// ROTBEAM_FUZZ_PRINT_TABLE=1: print every command's help from the table above and stop, for the
// comparison with the program's (command_table.sh).
extern "C" int LLVMFuzzerInitialize(int*, char***) {
    if (std::getenv("ROTBEAM_FUZZ_PRINT_TABLE") != nullptr) {
        for (const auto& [name, spec] : specs()) {
            std::cout << "=== " << name << "\n" << rotbeam::cli::help_text(spec);
        }
        std::exit(0);
    }
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::vector<std::string> argv(1);
    for (size_t i = 0; i < size; ++i) {
        const char c = static_cast<char>(data[i]);
        if (c == '\0' || c == '\n') {
            argv.emplace_back();
        } else {
            argv.back().push_back(c);
        }
    }
    try {
        parse(argv);
    } catch (const rotbeam::InputError& e) {
        const std::string message = e.what();
        if (message.empty() || message.find('\n') != std::string::npos) {
            finding("refusal not on one line: " + message);
        }
    } catch (const std::exception& e) {
        finding(std::string("escaped exception ") + typeid(e).name() + ": " + e.what());
    }
    return 0;
}
