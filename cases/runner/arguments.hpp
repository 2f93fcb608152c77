// Command-line parsing for the rotbeam program: each command declares its options once; the
// parser validates them (unknown options get a "did you mean"), and the same table prints --help.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "runs/catalog.hpp"  // closest_match, for the "did you mean"

namespace rotbeam::cli {

// The limits of the numeric options (docs/case-format.md, "Limits"); a case file's sizes are
// limited by the loader (cases/loader/limits.hpp).
inline constexpr int kMaxJobs = 256;       // suite --jobs: worker threads
inline constexpr int kMaxRepeats = 1000;   // bench --repeats: timing repeats per measurement
inline constexpr int kMaxSamples = 20000;  // study rotations --samples: angles in the sweep
inline constexpr double kMaxTimeLimit = 604800.0;  // --time-limit: seconds (a week)

struct OptionSpec {
    std::string name;        // without the leading "--"
    std::string value_name;  // empty: a flag without value
    std::string help;
    bool repeatable = false;
};

struct CommandSpec {
    std::string name;
    std::string positional;  // e.g. "CASE.yaml" (shown in usage)
    int min_positional = 0;
    int max_positional = 0;  // −1: any number
    std::string summary;
    std::vector<OptionSpec> options;
};

class ParsedArguments {
  public:
    bool help = false;
    std::vector<std::string> positional;

    bool has(const std::string& name) const { return values_.count(name) > 0; }
    std::optional<std::string> value(const std::string& name) const;
    std::vector<std::string> values(const std::string& name) const;
    // An integer option in [min, max] (its documented limits); InputError naming the command,
    // the option and the range otherwise (non-numeric, fractional, out of range, overflowing).
    std::optional<int> positive_int(const std::string& command, const std::string& name, int max,
                                    int min = 1) const;
    // A finite number in (0, max]; InputError naming the command and the option otherwise.
    std::optional<double> positive_number(const std::string& command, const std::string& name,
                                          double max) const;

    std::map<std::string, std::vector<std::string>> values_;
};

ParsedArguments parse_arguments(const CommandSpec& spec, const std::vector<std::string>& args);
// The usage, summary and every option with its default: a flag's is "off"; a value option's help
// says its default or "required" (tests/runner/cli_conventions.sh checks it).
std::string help_text(const CommandSpec& spec);

// Reading a command's options without running it (the completion script, completion.cpp): each
// command declares its CommandSpec beside its code and hands it to parse_arguments first; while a
// capture is installed, parse_arguments records the spec and throws SpecCaptured instead of
// parsing, so the command stops there.
struct SpecCaptured {};
inline thread_local std::vector<CommandSpec>* spec_capture = nullptr;

// --time-limit SECONDS of `run`, `suite` and `sweep`: the wall-clock limit of each run
// (core/time_limit.hpp; docs/durability.md, "Time limit"), one option text for all three.
extern const OptionSpec kTimeLimitOption;
// Its value in seconds, 0 when not given; InputError naming `command` outside (0, kMaxTimeLimit].
double time_limit_option(const ParsedArguments& a, const std::string& command);

// The shorthand options of `run` and `check`: each stands for a --set override of one case key
// (`*`: every member): {option without its dashes, key}.
struct Shorthand {
    const char* option;
    const char* key;
};
const std::vector<Shorthand>& run_shorthands();

// `run`'s and `check`'s case overrides: the shorthand options as --set overrides, then every --set
// in order; the case loader validates them like the file.
std::vector<std::string> case_overrides(const ParsedArguments& a);

}  // namespace rotbeam::cli
