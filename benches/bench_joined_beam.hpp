// `rotbeam bench`'s joined-beam targets (docs/benchmarks.md §3):
// - joined-beam-modal: the five lowest frequencies of the undeformed joined beam to 1e-6 relative
//   (largest over the modes) of the converged frequencies, which the bench computes first
//   (displacement formulation, p-converged; docs/performance.md says why and how they agree with
//   the Richardson values of `rotbeam study joined-beam-modal`); target ≤ 20 ms whole process;
// - joined-beam-dynamic (dead joint force) and joined-beam-dynamic-follower: the 0–2 s response
//   with the joint's displacement and rotation histories to a time error ≤ 1e-3 of their
//   amplitude against the combination's same-mesh time-converged reference (the high-order
//   scheme at two fixed steps that agree to 1e-5, joined_beam_dynamics.hpp; computed, or read
//   from the cache the study wrote); target ≤ 0.5 s (docs/performance.md says what bounds the
//   mixed formulation's).
// For every parameterization × formulation: the cheapest discretization / integrator setting that
// reaches the accuracy, its median whole-process and in-process time, Newton iterations, unknowns,
// peak memory — or "unreachable" with the reason and the best accuracy per time budget.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace rotbeam::cli {

// Both targets' JSON (the same layout as the static targets: name, accuracy, target_seconds,
// results[]; the dynamic one's target_seconds is the displacement formulation's, and
// mixed_target_seconds the mixed one's), printed as tables on stdout. `reference_dir`: where the dynamic references are
// cached; `load`: "dead" | "follower".
nlohmann::json bench_joined_beam_modal(bool quick, int repeats);
nlohmann::json bench_joined_beam_dynamic(bool quick, int repeats, const std::string& reference_dir,
                                         const std::string& load);

}  // namespace rotbeam::cli
