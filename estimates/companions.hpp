// The companion discretizations of a run's error estimate (docs/error-estimates.md): the one
// place where the method is chosen per formulation.
//   displacement: "p+1", the same mesh at order p + 1;
//   mixed:        "h/2,h/4", every member's elements doubled and quadrupled.
// Everything else of the model (loads, load factors, solver settings, parameterization) is kept.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/model.hpp"

namespace rotbeam::estimate {

struct Companion {
    std::string label;  // "order 5", "2x elements", "4x elements"
    Model model;
};

// bugprone-exception-escape: the implicit special members may throw through Model's (its
// containers' moves are not all noexcept); a plan is built and returned once, never moved inside a
// noexcept context, so nothing relies on them not throwing.
struct CompanionPlan {   // NOLINT(bugprone-exception-escape)
    std::string method;  // "p+1" | "h/2,h/4"
    std::vector<Companion> companions;
    // The theoretical order of each estimated quantity (docs/error-estimates.md): numbers of
    // the h-convergence rate; for p+1 also "in_p": "exponential".
    nlohmann::json theoretical_order;
    // Non-empty: no companion can be run (why); `companions` is then empty.
    std::string refusal;
};

// The companions in space alone, whatever the analysis (a dynamic one keeps its time grid).
CompanionPlan plan_space_companions(const Model& model);
// plan_space_companions, refused for a dynamic analysis (its estimate also needs a companion in
// time: dynamic_companions.hpp).
CompanionPlan plan_companions(const Model& model);

}  // namespace rotbeam::estimate
