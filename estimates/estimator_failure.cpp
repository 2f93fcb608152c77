#include "estimator_failure.hpp"

#include <iomanip>
#include <sstream>

namespace rotbeam::estimate {

std::string failure_cause(const nlohmann::json& q) {
    return q.value("reliable", false) ? "reliable"
                                      : "not reliable: " + q.value("reason", std::string());
}

std::optional<std::string> estimator_failure(double true_error, double floor,
                                             const nlohmann::json& q) {
    if (!q.contains("error")) return std::nullopt;
    const double est = q["error"].get<double>();
    if (true_error <= floor || true_error <= kFailureFactor * est) return std::nullopt;
    std::ostringstream line;
    line << std::setprecision(2) << std::scientific << "true " << true_error << " > 3 × estimate "
         << est << " (" << failure_cause(q) << ")";
    return line.str();
}

}  // namespace rotbeam::estimate
