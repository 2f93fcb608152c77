#include "modal_checks.hpp"

#include <cmath>
#include <sstream>

namespace rotbeam {

namespace {

// |Re s| below this fraction of |s| is the eigensolver's round-off (an undamped structure at rest
// has Re s = 0; the Arnoldi iteration leaves ≲ 1e-9 |s|), not a growth or decay rate: the
// threshold of the pairs without an error estimate of their own.
constexpr double kRoundOffGrowth = 1e-8;

// A growth rate Re s above what the eigenvalue's error allows: its own first-order estimate
// (check.error_estimate, relative to |s|: core/quadratic_eigenpair.hpp) when it has one. A
// decaying mode (Re s < 0: damping) is not an instability.
bool grows(const CheckedMode& m) {
    const double allowed = m.check.error_estimate >= 0.0 ? m.check.error_estimate : kRoundOffGrowth;
    return m.growth_rate > allowed * std::abs(m.s);
}

nlohmann::json check_json(const EigenpairCheck& c) {
    nlohmann::json j = {{"backward_error", c.backward_error}, {"accepted", c.accepted}};
    if (c.error_bound >= 0.0) j["error_bound"] = c.error_bound;
    if (c.error_estimate >= 0.0 && std::isfinite(c.error_estimate)) {
        j["error_estimate"] = c.error_estimate;
    }
    if (c.mass_orthogonality >= 0.0) j["mass_orthogonality"] = c.mass_orthogonality;
    if (c.mass_participation >= 0.0) j["mass_participation"] = c.mass_participation;
    if (!c.accepted) j["failed"] = c.failure;
    return j;
}

}  // namespace

nlohmann::json refinement_json(std::complex<double> arnoldi_s, int steps) {
    return {{"arnoldi_s", {arnoldi_s.real(), arnoldi_s.imag()}}, {"steps", steps}};
}

void report_checked_modes(const std::vector<CheckedMode>& modes, const std::string& state,
                          nlohmann::json& result) {
    std::vector<double> accepted;
    std::ostringstream rejected;
    rejected.precision(6);
    int growing = 0;
    for (size_t i = 0; i < modes.size(); ++i) {
        const CheckedMode& m = modes[i];
        nlohmann::json& j = result["modes"][i];
        j["s"] = {m.s.real(), m.s.imag()};
        j["growth_rate"] = m.growth_rate;
        j["check"] = check_json(m.check);
        if (grows(m)) ++growing;
        if (m.check.accepted) {
            accepted.push_back(m.frequency_hz);
            j["frequency_hz"] = m.frequency_hz;
        } else {
            j.erase("frequency_hz");
            if (rejected.tellp() == 0) {
                rejected << "mode " << i + 1 << " (s = " << m.s.real() << " + " << m.s.imag()
                         << "i) rejected: " << describe(m.check);
            }
        }
    }
    result["frequencies_hz"] = accepted;
    if (accepted.size() == modes.size()) {
        result["status"] = "converged";
        std::ostringstream msg;
        msg << "modes of the " << state << " state; every eigenpair passed its checks";
        if (growing > 0) {
            msg << "; " << growing
                << " with a growth rate above round-off (complex s: flutter or divergence)";
        }
        result["message"] = msg.str();
    } else {
        result["status"] = "eigenpair-check-failed";
        result["message"] =
            "modes of the " + state + " state: " + rejected.str() + "; not reported as a frequency";
    }
}

}  // namespace rotbeam
