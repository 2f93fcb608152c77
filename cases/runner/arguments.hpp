// Command-line parsing for the rotbeam program: each command declares its options once; the
// parser validates them (unknown options get a "did you mean"), and the same table prints --help.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace rotbeam::cli {

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
    // A positive integer option; InputError naming the command and option otherwise.
    std::optional<int> positive_int(const std::string& command, const std::string& name) const;

    std::map<std::string, std::vector<std::string>> values_;
};

ParsedArguments parse_arguments(const CommandSpec& spec, const std::vector<std::string>& args);
std::string help_text(const CommandSpec& spec);
// Closest candidate by edit distance (empty if none is close).
std::string closest_match(const std::string& word, const std::vector<std::string>& candidates);

}  // namespace rotbeam::cli
