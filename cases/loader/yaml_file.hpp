// Reading a rotbeam input file written in YAML (a case file, a sweep file) into its tree, within
// the limits of the format (limits.hpp): its size, UTF-8 text, alias expansion and nesting are
// checked before or while yaml-cpp builds the tree, never after it has exploded. Every refusal is
// one line `FILE:LINE: (file|yaml): problem`.
#pragma once

#include <yaml-cpp/yaml.h>

#include <cstddef>
#include <string>

namespace rotbeam::cases {

// What the messages call a kind of file.
struct YamlFileKind {
    const char* name;        // "case file"
    const char* contents;    // "sections (points, members, ...)": what its top-level mapping holds
    const char* size_limit;  // "a limit of the case format": what the size limit is
};
inline constexpr YamlFileKind kCaseFile{"case file", "sections (points, members, ...)",
                                        "a limit of the case format"};

// The offset of the first byte that is not UTF-8 text (a NUL or other control byte but tab and
// line ends, or a malformed UTF-8 sequence), or npos.
size_t first_non_text_byte(const std::string& text);

// Throws InputError `FILE:LINE: (yaml): a second YAML document starts here; a WHAT holds one
// document` when `text`, whose first document yaml-cpp loaded as `first`, holds another (`---`
// then anything, even nothing).
void check_one_document(const std::string& text, const YAML::Node& first, const std::string& file,
                        const std::string& what);

// The tree of `text` (named `file` in messages): a mapping, or InputError.
YAML::Node parse_yaml_file(const std::string& text, const std::string& file,
                           const YamlFileKind& kind);

}  // namespace rotbeam::cases
