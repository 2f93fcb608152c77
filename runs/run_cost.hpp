// The expected run time of a case run before it has ever run: the cost model that balances shards
// (runs/shards.hpp, docs/distributed-runs.md) when no earlier timing of the run exists.
#pragma once

#include "core/model.hpp"

namespace rotbeam::cli {

// Seconds ≈ kFixedSeconds + kSecondsPerElementStep × elements × order × steps × (5 if mixed):
// elements summed over the members, the element order (the mixed element is linear: 1), steps =
// reported load factors × initial sub-steps (statics), end time / time step (dynamics), modes
// (modal). The constant is the displacement formulation's joined-beam dynamics at the paper's mesh
// (20 linear elements, 2000 steps, ~0.6 s); the mixed element costs 4–7× more per step
// (docs/studies.md, joined-beam dynamics). Only the ratios between runs matter for the balance;
// measured times replace the model wherever an earlier run left one.
constexpr double kFixedSeconds = 0.01;
constexpr double kSecondsPerElementStep = 1.5e-5;
constexpr double kMixedFactor = 5.0;
double modelled_seconds(const Model& model);

}  // namespace rotbeam::cli
