// When an error estimate has failed (docs/error-estimates.md, "Effectivity"): the true error of a
// quantity, known from an independent reference, exceeds kFailureFactor × its estimate. One place
// for the rule, shared by the report's list over the suite's runs and the effectivity study.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>

namespace rotbeam::estimate {

// An estimate misses when the true error exceeds this multiple of it.
inline constexpr double kFailureFactor = 3.0;

// True errors at or below this (times the estimates' reference length for displacements, in rad
// for rotations) are not counted: the continuum reference is verified to 1.8e-11 and the solves'
// algebraic error is near 1e-12 (docs/reference-solutions.md, docs/solver-convergence.md), so
// below 1e-9 the "true error" is not known to better than a few per cent.
inline constexpr double kFailureFloor = 1e-9;

// The cause of a failure of the estimate `q` ({"error", "reliable", "reason"}), as the estimate
// itself gives it: "reliable" (a miss nothing explains) or "not reliable: <its reason>".
std::string failure_cause(const nlohmann::json& q);

// "true 2.1e-08 > 3 × estimate 1.7e-09 (<cause>)" when `true_error` is above `floor` and above
// kFailureFactor × q's error; nullopt otherwise (and when q has no error).
std::optional<std::string> estimator_failure(double true_error, double floor,
                                             const nlohmann::json& q);

// The same with the cause given by the caller (what it knows beyond the estimate's own verdict).
std::optional<std::string> estimator_failure(double true_error, double floor,
                                             const nlohmann::json& q, const std::string& cause);

}  // namespace rotbeam::estimate
