// A value that becomes part of a file or folder name: a case name (runs write
// `OUT/NAME_ROTATION_FORMULATION.json`), a sweep's name and output folder, the name a sweep gives
// a case (the stem of its path). Every such value is checked here, by one rule, when it is read,
// so that no input can make a run write outside its output folder (`/`, `..`), hide a file (a
// leading `.`), or make a name that some file system refuses (docs/case-format.md, "Names").
#pragma once

#include <cstddef>
#include <string>

namespace rotbeam::cases {

// The longest name part: a sweep run's file joins two of them with a rotation and a formulation
// (`SWEEP-0001_CASE_wiener-milenkovic_displacement.json`), well inside the 255 bytes of a file
// name.
inline constexpr std::size_t kMaxFileNamePart = 64;

// Empty when `text` is 1 to kMaxFileNamePart characters among the letters A–Z and a–z, the digits,
// '-', '_' and '.', neither starting with '.' nor holding "..". Otherwise the problem, one line
// that quotes the value: "'../x' cannot be part of a file name: it holds '/' (allowed: ...)".
std::string file_name_part_problem(const std::string& text);

}  // namespace rotbeam::cases
