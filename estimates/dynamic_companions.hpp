// The companions of a dynamic run's error estimate (docs/error-estimates.md, Dynamics): the one
// place where the method in time is chosen per integrator.
//   in space: plan_space_companions (p+1, or h/2 and h/4, or 2h and 4h), over the run's own time
//             grid;
//   in time:  the same mesh with half the time step ("dt/2") for the fixed-step schemes, or with
//             coarser companions (analysis.estimate_companions) twice the step ("2dt"); the
//             tolerances divided by 4 ("tolerance/4") for IDA and adaptive steps, on either side
//             (a coarser adaptive companion would take the run's steps wherever they sit at the
//             output cap, and a cap twice the run's would skip every other output).
// The output times of the time companion are the run's (an output interval of 0, "every step",
// becomes the run's step; 2dt needs them on its grid), so its history is compared with the run's
// at the same instants.
#pragma once

#include <string>

#include "core/model.hpp"
#include "estimates/companions.hpp"

namespace rotbeam::estimate {

struct DynamicPlan {  // NOLINT(bugprone-exception-escape): as CompanionPlan
    CompanionPlan space;
    std::string time_method;  // "dt/2" | "2dt" | "tolerance/4"
    // The rate at which the time error falls with the refined parameter: 2 in Δt (both fixed-step
    // schemes), 1 in the tolerance (IDA). The companion's parameter is the run's / time_ratio.
    double time_order = 2.0;
    double time_ratio = 2.0;  // Δt / Δt_companion (1/2 for 2dt), or tolerance / tolerance_companion
    std::vector<Companion> time;  // the one time companion (empty when refused)
    std::string time_refusal;     // why there is none
};

DynamicPlan plan_dynamic_companions(const Model& model);

}  // namespace rotbeam::estimate
