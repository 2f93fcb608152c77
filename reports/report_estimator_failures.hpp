// The report's estimator failures (docs/error-estimates.md, "Effectivity"): in every solved run
// with an error estimate and an independent reference (point_reference: the exact roll-up, the
// continuum reference), each load step and named point where the true error of the displacement
// or of the rotation exceeds 3 × its estimate, with the cause as far as the run knows it: the
// estimate's own reason when it says it is not reliable, else that a reliable estimate missed.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace rotbeam::cli {

// True errors at or below this (times the estimates' reference length for displacements, in rad
// for rotations) are not counted: the continuum reference is verified to 1.8e-11 and the solves'
// algebraic error is near 1e-12 (docs/reference-solutions.md, docs/solver-convergence.md), so
// below 1e-9 the "true error" is not known to better than a few per cent.
inline constexpr double kFailureFloor = 1e-9;

// One line per failure of `run`: "tip displacement at load factor 450: true 2.1e-08 > 3 ×
// estimate 1.7e-09 (reliable)". Empty when there is none, or nothing to compare.
std::vector<std::string> estimator_failures(const nlohmann::json& run);

// The "## Estimator failures" section over the suite's runs.
std::string estimator_failures_section(const std::vector<nlohmann::json>& runs);

}  // namespace rotbeam::cli
