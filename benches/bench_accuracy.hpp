// `rotbeam bench`'s accuracy-control target (docs/accuracy-control.md, "Cost"): the displacement
// formulation (quaternion) on the roll-up to λ = 2 and the 45° bend at TOL = 1e-6. For each: the
// best hand-picked discretization (the fastest of a grid of elements × orders whose true error,
// against the exact roll-up or the continuum bend, is ≤ TOL in the measure of the accuracy
// control), timed with the estimate off; the whole `--accuracy` run (which starts coarse,
// estimate::coarse_start), estimate included; in-process medians; the ratio; and whether the
// controlled run's true error is ≤ TOL.
#pragma once

#include <nlohmann/json.hpp>

namespace rotbeam::cli {

nlohmann::json bench_accuracy_control(bool quick, int repeats);

}  // namespace rotbeam::cli
