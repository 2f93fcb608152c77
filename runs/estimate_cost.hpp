// The expected run time of a run with its error estimate: the cost model (run_cost.hpp) times the
// measured cost of the estimate's strategy (add_run_estimate, estimates/companions.hpp).
#pragma once

#include "core/model.hpp"
#include "runs/run_cost.hpp"

namespace rotbeam::cli {

// The estimate's companions (estimates/companions.hpp, dynamic_companions.hpp: the one place that
// plans them) priced by the cost model, except where the model cannot say their cost and a
// measured factor of the run stands in (run_cost.cpp): a static displacement run's companions
// start from its solved path, the mixed formulation's modal companions grow faster than their
// unknowns. Measured against `rotbeam run …
// --quiet` with and without the estimate in docs/distributed-runs.md, "Cost model".
double estimate_cost_factor(const Model& model);

// modelled_seconds, times estimate_cost_factor when `estimate`.
inline double modelled_seconds(const Model& model, bool estimate) {
    return estimate ? modelled_seconds(model) * estimate_cost_factor(model)
                    : modelled_seconds(model);
}

}  // namespace rotbeam::cli
