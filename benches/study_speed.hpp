// The speed-accuracy study (`rotbeam study speed-accuracy`, docs/studies.md): for every
// combination the cheapest discretization of each bench target (bench.hpp) and its time against
// its error, the Pareto front, and the time that assembling only what a scene needs saves. It lives
// with the benches because its numbers are timings made with their search and harness.
#pragma once

#include <nlohmann/json.hpp>
#include <sstream>

#include "studies/study_common.hpp"

namespace rotbeam::cli {

nlohmann::json study_speed_accuracy(const StudyOptions& o);  // study_speed.cpp
// The time "model only what the scene requires" saves against solver.assemble_all_terms: a
// section of the speed study (study_assembly.cpp).
nlohmann::json assembly_savings(const StudyOptions& o, std::ostringstream& md);

}  // namespace rotbeam::cli
