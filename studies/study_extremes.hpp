// The parts of `rotbeam study extremes`, each writing its Markdown section and
// figure: study_extremes.cpp (slenderness, tiny loads), study_extremes_newton.cpp (one big load
// step, refinement down to round-off).
#pragma once

#include <nlohmann/json.hpp>
#include <sstream>

#include "study_common.hpp"

namespace rotbeam::cli {

nlohmann::json extremes_slenderness(const StudyOptions& o, std::ostringstream& md);
nlohmann::json extremes_tiny_loads(const StudyOptions& o, std::ostringstream& md);
nlohmann::json extremes_single_step(const StudyOptions& o, std::ostringstream& md);
nlohmann::json extremes_round_off(const StudyOptions& o, std::ostringstream& md);

}  // namespace rotbeam::cli
