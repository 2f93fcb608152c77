// The companion discretizations of a run's error estimate (docs/error-estimates.md): the one
// place where the method is chosen per formulation.
//   displacement: "p+1", the same mesh at order p + 1; below kSpectralOrder, for statics and
//                 modes, also order p + 2, which checks that the p-sequence decays
//                 (quantity_estimate.hpp);
//   mixed:        "h/2,h/4", every member's elements doubled and quadrupled; with coarser
//                 companions (analysis.estimate_companions) "2h,4h", halved and quartered.
//                 The p-sequence has no coarser form (order p − 1 measures e_{p−1}, not e_p):
//                 the displacement formulation keeps p+1 either way.
// Everything else of the model (loads, load factors, solver settings, parameterization) is kept.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/model.hpp"
#include "estimates/quantity_estimate.hpp"

namespace rotbeam::estimate {

// From this order on the p+1 estimate rests on spectral convergence without a p+2 companion
// (docs/error-estimates.md). Below it the p-sequence need not have entered its spectral regime
// even for a smooth solution: on a coarse mesh orders 2–3 lock, on a fine one the errors of orders
// p and p+1 scale as C_p h^{2p} and C_{p+1} h^{2p+2} and cross where C_{p+1} h² ≈ C_p (measured:
// order 3 worse than order 2 on the 45° bend up to 32 elements; one element turning 2π decays by
// only 0.65–0.73 per order up to order 4). The decay check costs one run at order p + 2, which
// is why it is not run on the high-order meshes the p-sequence is spectral on.
inline constexpr int kSpectralOrder = 6;

struct Companion {
    std::string label;  // "order 5", "2x elements", "4x elements", "1/2 elements", "1/4 elements"
    Model model;
};

// bugprone-exception-escape: the implicit special members may throw through Model's (its
// containers' moves are not all noexcept); a plan is built and returned once, never moved inside a
// noexcept context, so nothing relies on them not throwing.
struct CompanionPlan {                        // NOLINT(bugprone-exception-escape)
    std::string method;                       // "p+1" | "h/2,h/4" | "2h,4h"
    HSequence h_sequence = HSequence::finer;  // the h-methods' side of the run
    std::vector<Companion> companions;
    // The theoretical order of each estimated quantity (docs/error-estimates.md): numbers of
    // the h-convergence rate; for p+1 also "in_p": "exponential".
    nlohmann::json theoretical_order;
    // Non-empty: no companion can be run (why); `companions` is then empty.
    std::string refusal;
};

// The multiple every member's element count must be for the model's companions: 4 for the mixed
// formulation's coarser ones, which halve and quarter it (both meshes nest in the run's), else 1.
int element_count_multiple(const Model& model);

// The companions in space alone, whatever the analysis (a dynamic one keeps its time grid).
CompanionPlan plan_space_companions(const Model& model);
// plan_space_companions with, for the displacement formulation below kSpectralOrder, the order
// p + 2 companion of the decay check; refused for a dynamic analysis (its estimate also needs a
// companion in time: dynamic_companions.hpp, whose space estimate has no decay check yet).
CompanionPlan plan_companions(const Model& model);

}  // namespace rotbeam::estimate
