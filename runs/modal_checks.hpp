// The checks of a modal run in its result (analyses.hpp): each mode's eigenpair check
// (core/eigenpair_check.hpp) in `modes[i].check`, `frequencies_hz` holding only accepted pairs,
// and the status `eigenpair-check-failed` naming the first rejected mode when any is rejected.
#pragma once

#include <complex>
#include <nlohmann/json.hpp>
#include <vector>

#include "core/eigenpair_check.hpp"

namespace rotbeam {

struct CheckedMode {
    double frequency_hz;
    double growth_rate;
    std::complex<double> s;  // the oscillation exponent e^{st}
    EigenpairCheck check;
};

// A refined mode's `refinement` (core/refined_ritz_modes.hpp): the Arnoldi value before the
// refinement and the steps taken.
nlohmann::json refinement_json(std::complex<double> arnoldi_s, int steps);

// Appends `check`, `s` and (when accepted) `frequency_hz` to each of result["modes"] (already
// holding one entry per mode, in order), sets `frequencies_hz`, `status` and `message`.
void report_checked_modes(const std::vector<CheckedMode>& modes, const std::string& state,
                          nlohmann::json& result);

}  // namespace rotbeam
