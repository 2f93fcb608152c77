// Typed, validating access to a parsed YAML case file.
//
// Every problem becomes ONE InputError line `FILE:LINE: KEY: problem`, where KEY is the full key
// path (`members.beam.elements`) and LINE the 1-based line of the offending node. Values that came
// from a `--set key.path=value` override report `FILE:--set:` instead of a line, because the file
// does not contain them. Unknown keys get a "did you mean ..." suggestion (edit distance).
#pragma once

#include <yaml-cpp/yaml.h>

#include <initializer_list>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "cases/loader/closest_match.hpp"
#include "core/types.hpp"

namespace rotbeam::cases {

// `text` with its control characters written as escapes (\n, \r, \t, \xHH), so that a message
// quoting a key or value the user wrote (a quoted YAML string may span lines) stays one line.
std::string one_line(const std::string& text);

// "a.b" + "c" → "a.b.c"; an empty parent gives the child.
std::string child_key(const std::string& parent, const std::string& child);

class YamlReader {
  public:
    YamlReader(std::string file, std::set<std::string> overridden_keys)
        : file_(std::move(file)), overridden_(std::move(overridden_keys)) {}

    const std::string& file() const { return file_; }

    // Records the line of every key (and list item) of the tree by key path, so that messages
    // name the line of the key — a block mapping or list value starts on the line after it.
    // A tree nested deeper than kMaxYamlDepth (limits.hpp) is refused here: `FILE:LINE: (yaml):`.
    void index_lines(const YAML::Node& root) { index(root, "", 1); }
    // Whether `key` (or a parent of it) was set by a --set override.
    bool overridden(const std::string& key) const;

    // `FILE:LINE:` or `FILE:--set:` for a node reached by key path `key`.
    std::string where(const YAML::Node& node, const std::string& key) const;
    [[noreturn]] void fail(const YAML::Node& node, const std::string& key,
                           const std::string& problem) const;

    // A mapping whose keys are all in `allowed` (else: unknown key, with a suggestion).
    void expect_map(const YAML::Node& node, const std::string& key,
                    std::initializer_list<const char*> allowed) const;
    // A mapping in which no key appears twice (yaml-cpp keeps both silently).
    void expect_unique_keys(const YAML::Node& node, const std::string& key) const;
    // A mapping with arbitrary (user-chosen) names as keys, each a valid identifier.
    void expect_named_map(const YAML::Node& node, const std::string& key) const;
    // The child `name` of `map`, which must be present.
    YAML::Node required(const YAML::Node& map, const std::string& key, const char* name) const;

    double number(const YAML::Node& node, const std::string& key) const;  // finite
    double positive(const YAML::Node& node, const std::string& key) const;
    double non_negative(const YAML::Node& node, const std::string& key) const;
    int integer(const YAML::Node& node, const std::string& key) const;
    int positive_integer(const YAML::Node& node, const std::string& key) const;
    // A positive integer no larger than `limit` (a size limit of limits.hpp).
    int positive_integer(const YAML::Node& node, const std::string& key, long limit) const;
    bool boolean(const YAML::Node& node, const std::string& key) const;
    std::string string(const YAML::Node& node, const std::string& key) const;
    // One of `choices` (else: the list, and the closest choice).
    std::string choice(const YAML::Node& node, const std::string& key,
                       const std::vector<std::string>& choices) const;
    // A name that must be one of `names` (points, members, sections); `what` says which.
    std::string name_in(const YAML::Node& node, const std::string& key,
                        const std::vector<std::string>& names, const std::string& what) const;

    Vec3 vec3(const YAML::Node& node, const std::string& key) const;
    Vec6 vec6(const YAML::Node& node, const std::string& key) const;
    // A sequence of numbers; a scalar is accepted as a one-element list.
    std::vector<double> numbers(const YAML::Node& node, const std::string& key) const;
    Mat6 mat6(const YAML::Node& node, const std::string& key) const;  // 6 rows of 6

  private:
    std::string kind_name(const YAML::Node& node) const;
    std::string scalar(const YAML::Node& node, const std::string& key,
                       const std::string& expected) const;

    void index(const YAML::Node& node, const std::string& path, int depth);

    std::string file_;
    std::set<std::string> overridden_;
    std::map<std::string, int> lines_;  // key path → 0-based line of its key
};

}  // namespace rotbeam::cases
