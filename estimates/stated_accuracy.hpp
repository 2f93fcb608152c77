// What a run's estimate says against the accuracy its case states for its formulation
// (discretization.accuracy, docs/accuracy-control.md), in one line for `rotbeam run`: "met",
// "NOT met" with the first problem, or, when the case states none (an imported BeamDyn deck, a
// user's case), "none stated" with the worst estimate, so that a large estimated error never stands
// only beside the solver's status (which says the equations are solved, not how accurate the
// answer is).
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "core/model.hpp"

namespace rotbeam::estimate {

// The line, or "" when the run has no estimate to measure (off, not estimated, or under accuracy
// control, which reports its own outcome).
std::string stated_accuracy_line(const Model& model, const nlohmann::json& result);

}  // namespace rotbeam::estimate
