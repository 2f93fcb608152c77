// The report's estimator failures (docs/error-estimates.md, "Effectivity"): in every solved run
// with an error estimate and an independent reference (point_reference: the exact roll-up, the
// continuum reference), each load step and named point where the true error of the displacement
// or of the rotation exceeds 3 × its estimate, with the cause as far as the run knows it: the
// estimate's own reason when it says it is not reliable, else that a reliable estimate missed.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "estimates/estimator_failure.hpp"

namespace rotbeam::cli {

// One line per failure of `run`: "tip displacement at load factor 450: true 2.1e-08 > 3 ×
// estimate 1.7e-09 (reliable)". Empty when there is none, or nothing to compare.
std::vector<std::string> estimator_failures(const nlohmann::json& run);

// The "## Estimator failures" section over the suite's runs.
std::string estimator_failures_section(const std::vector<nlohmann::json>& runs);

}  // namespace rotbeam::cli
