// `rotbeam bench`'s long-run target (the cost per time step stays constant over a long
// run). The joined beam under its dead sine joint force (cases/joined-beam-dead.yaml, the paper's
// mesh and Δt = 1 ms) integrated far past the case's 2 s — 20 000 fixed steps (--quick: 2 000) —
// through the normal runner path (run_case: the result's history is built as `rotbeam run` builds
// it), for the displacement formulation (generalized-α, ρ∞ = 0.9: with the case's ρ∞ = 1 its step
// at t = 5.491 s fails) and the mixed formulation (the trapezoidal fixed step, and IDA over a span
// in which it takes as many of its own steps). Each step is timed in process through the drivers'
// step observer (core/step_observer.hpp); the bench prints the median CPU cost per step of the
// first and the last tenth of the run and their ratio, Newton iterations and Jacobians per step in
// both, and the memory (VmHWM) after the first and the last tenth, whose growth is given per step
// and per output. Every combination runs twice: with the case's output (every step; the history
// kept for the result grows with the run, and its bytes per output are the expected growth) and
// with output every 100 steps (IDA: 5 ms), where any growth beyond the same bytes per output
// would be a defect.
#pragma once

#include <nlohmann/json.hpp>

namespace rotbeam::cli {

// The target's JSON (name, steps, results[]), printed as a table on stdout.
nlohmann::json bench_long_run(bool quick);

}  // namespace rotbeam::cli
