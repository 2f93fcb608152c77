// `rotbeam study --help`'s description, generated from the study registry (study_registry.hpp) so
// that the help lists what the registry holds.
#pragma once

#include <string>

namespace rotbeam::cli {

// `rotations` and every registered study with its one-line summary, in report order, then `all`
// (study_registry.cpp, next to the registry; a registered study without a summary is API misuse,
// ROTBEAM_VERIFY).
std::string study_help_text();

}  // namespace rotbeam::cli
