// The case catalog: where the catalog's case files are, a case argument (a path or a catalog name)
// as a file, and the nearest name for a misspelt one (also for options and targets).
#pragma once

#include <string>
#include <vector>

#include "cases/loader/closest_match.hpp"

namespace rotbeam::cli {

// Catalog folder: $ROTBEAM_CASES, else the source tree's cases/ (compile-time).
std::string catalog_directory();
// A case argument is a path, or the name of a catalog case ("bend-45" → cases/bend-45.yaml).
std::string resolve_case_path(const std::string& argument);
std::vector<std::string> catalog_cases();

// The program's "did you mean" is the case loader's (cases/loader/closest_match.hpp).
using cases::closest_match;

}  // namespace rotbeam::cli
