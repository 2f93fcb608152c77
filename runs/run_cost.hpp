// The expected run time of a case run before it has ever run: the cost model that balances shards
// (runs/shards.hpp, docs/distributed-runs.md) when no earlier timing of the run exists.
#pragma once

#include "core/model.hpp"

namespace rotbeam::cli {

// Seconds ≈ kFixedSeconds + kSecondsPerElementStep × elements × order × steps × (mixed_factor if
// mixed): elements summed over the members, the element order (the mixed element is linear: 1),
// steps = reported load factors × initial sub-steps (statics), end time / time step (dynamics),
// modes (modal). The step constant is the displacement formulation's joined-beam dynamics at the
// paper's mesh (20 linear elements, 2000 steps, ~0.6 s). Only the ratios between runs matter for
// the balance and the time left; measured times replace the model wherever an earlier run left
// one. Measured on the catalog (docs/distributed-runs.md, "Cost model").
//
// The fixed part: the start-up and case loading of a run, 9.0 M callgrind instructions of the
// whole `rotbeam run tip-load-cantilever --estimate off` (one load step on 8 linear elements),
// against 869 M for the displacement bend-45 (16 elements of order 3, 30 sub-steps: 1440
// element-order-steps, 0.0216 s of the model): 2.2e-4 s. (It was 0.01 s, which made the model's
// static runs mostly start-up: 30 % of the bend where the process spends 1 %.)
constexpr double kFixedSeconds = 2e-4;
constexpr double kSecondsPerElementStep = 1.5e-5;
// A mixed element-step over a displacement element-order-step, per analysis: one factor cannot
// say both. The mixed statics step Newton's iterations on the element's 12 unknowns at its
// mid-point, the displacement statics on 6 per node with the order's quadrature; at the catalog's
// orders 3–4 a mixed run costs 0.30–0.52 of the displacement one: factors 1.16–1.76 (callgrind,
// 4 cases). The mixed dynamics add the trapezoidal rule's stiff DAE per step: 3.2–5.8 (CPU
// seconds, 4 cases, up to 3 timings). Each factor is the geometric mean of the smallest and
// largest fitted (each within 1.4× of it). The modes: one catalog case (the joined beam, 20
// elements, the displacement formulation at its order 1), 46. The dense eigenproblems grow as
// the cube of the unknowns, which this model, linear in elements × order, cannot say: the same
// joined beam's mixed / displacement is 40 at order 1, 6.1 at order 2 and 0.87 at order 4, so
// the factor holds at the catalog's own order only.
constexpr double kMixedStaticFactor = 1.4;
constexpr double kMixedDynamicFactor = 4.3;
constexpr double kMixedModalFactor = 46.0;
double mixed_cost_factor(AnalysisKind kind);
double modelled_seconds(const Model& model);

}  // namespace rotbeam::cli
