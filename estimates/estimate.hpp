// A run's error estimate (docs/error-estimates.md): runs the companions of plan_companions and adds
// to the result JSON
//   `estimate`: {status, method, theoretical_order, companions: [{label, elements, order, status,
//                message, wall_seconds}], wall_seconds, estimated, unreliable, missing, reason?};
//   per step `estimate`: {point: {displacement: Q, rotation: Q}} or {status: "not-estimated",
//                reason};
//   per mode with a frequency `estimate`: {frequency: Q} or {status: "not-estimated", reason};
// where Q is to_json(QuantityEstimate): {error, reliable, observed_order?, reason?}. The
// displacement error is the norm of the difference of the displacement vectors, the rotation
// error the angle of R_aᵀ R_b (radians), the frequency error in Hz.
// A run whose status is not a solution (has_solution) gets no companions and
// `estimate.status = "not-estimated"` with the reason; so does one the plan refuses.
#pragma once

#include <functional>
#include <nlohmann/json.hpp>
#include <vector>

#include "core/model.hpp"

namespace rotbeam::estimate {

// Runs one companion model and returns its result JSON (the program's run_case). May throw
// InputError for a model the formulation refuses: the companion then counts as failed.
using CompanionRun = std::function<nlohmann::json(const Model&)>;
// For each of the run's `modes`, the index of the same mode among a companion's `modes`, or −1
// (the program pairs them by shape, runs/mode_matching.hpp).
using ModePairing =
    std::function<std::vector<int>(const nlohmann::json& modes, const nlohmann::json& companion)>;

// Below this, two solves' values are equal to round-off: the Newton acceptance bounds the scaled
// algebraic error near 1e-12 (docs/solver-convergence.md) and the finest companion's conditioning
// costs at most two more digits. Relative to the model's size for displacements, to one radian
// for rotations and to the frequency itself.
inline constexpr double kRoundOffFloor = 1e-10;

// One companion run and its wall time. A model the formulation refuses (InputError) gives
// {status: "error", message, steps: []}: the companion then counts as failed.
// bugprone-exception-escape: the implicit special members may throw through the JSON value's; a
// TimedRun is returned once and unpacked, never moved inside a noexcept context.
struct TimedRun {  // NOLINT(bugprone-exception-escape)
    nlohmann::json result;
    double seconds = 0.0;
};
TimedRun run_companion_timed(const CompanionRun& run, const Model& model);

// The elements of all members.
int total_elements(const Model& model);

void add_estimate(const Model& model, nlohmann::json& result, const CompanionRun& run,
                  const ModePairing& pair_modes);

// When the companions' plan refuses (`refusal` not empty) or the run has no solution (an
// untrustworthy solve gets no estimate): sets result["estimate"] to `header` with status
// not-estimated and the reason, and returns true.
bool refuse_estimate(nlohmann::json& result, nlohmann::json header, std::string refusal);

// The `estimate` of a result whose estimate was switched off: {status: "off"}.
nlohmann::json estimate_off();

}  // namespace rotbeam::estimate
