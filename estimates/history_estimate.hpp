// The error estimate of a dynamic run's histories (docs/error-estimates.md, Dynamics): every named
// point's displacement and rotation at every output time, in space (the companions of the statics,
// run over the same time grid) and in time (dynamic_companions.hpp), reported separately and
// combined, and over the whole history relative to its amplitude. Adds to the result JSON
//   `estimate`: {status, method ("p+1 & dt/2", …), space_method, time_method, theoretical_order
//                (+ time), companions, wall_seconds, cost, history, phase_error_rad, phase_of,
//                time_reliable, estimated, unreliable, missing, reason?};
//   per output time `estimate`: {point: {displacement: D, rotation: D}} or {status:
//                "not-estimated", reason}, D = {error (space + time), reliable, relative?, space:
//                Q, time: Q, reason?} with Q = to_json(QuantityEstimate);
// and sets the status `inaccurate` (kInaccurate) when the estimate cannot vouch for the history.
#pragma once

#include <nlohmann/json.hpp>

#include "core/model.hpp"
#include "estimates/estimate.hpp"

namespace rotbeam::estimate {

// A solved dynamic run whose time step is far beyond what its estimate can vouch for.
inline constexpr const char* kInaccurate = "inaccurate";

// The time estimate is reliable while the accumulated phase error of the response is ≪ 1 rad:
// at most 0.1 rad. The estimate is linear in the error only while sin φ ≈ φ (off by φ²/6 = 0.2 %
// at 0.1 rad) and the zeros of the estimated and the true error history coincide (they are φ/8
// apart for dt/2); docs/error-estimates.md derives both.
inline constexpr double kPhaseReliable = 0.1;
// Beyond 1 rad (a sixth of a period) the difference of the two histories approaches its ceiling
// 2A and stops growing with the error: the estimate cannot vouch for the run, `inaccurate`.
inline constexpr double kPhaseInaccurate = 1.0;
// So is a run whose estimated error reaches half the amplitude of a history.
inline constexpr double kRelativeInaccurate = 0.5;

// The accumulated phase error φ of a history of amplitude A whose largest difference from its
// time companion is D, for a scheme of order q whose companion's step (or tolerance) is the run's
// / k: the companion's phase error is φ / kᵠ, the two histories A sin(ωt + φ) and A sin(ωt + φ/kᵠ)
// differ by at most 2A sin(φ |1 − k⁻ᵠ| / 2), so φ = 2 asin(D / 2A) / |1 − k⁻ᵠ| (D ≥ 2A: the
// value at D = 2A, a lower bound). k = 1/2 for a 2dt companion, whose phase is 2ᵠ φ.
double accumulated_phase(double difference, double amplitude, double order, double ratio);

// Runs the space and time companions and adds the estimate (see above). A run whose status is
// not a solution gets no companions and `estimate.status = "not-estimated"`.
void add_dynamic_estimate(const Model& model, nlohmann::json& result, const CompanionRun& run);

}  // namespace rotbeam::estimate
