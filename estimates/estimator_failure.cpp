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
    return estimator_failure(true_error, floor, q, failure_cause(q));
}

std::optional<std::string> estimator_failure(double true_error, double floor,
                                             const nlohmann::json& q, const std::string& cause) {
    if (!q.contains("error")) return std::nullopt;
    const double est = q["error"].get<double>();
    if (true_error <= floor || true_error <= kFailureFactor * est) return std::nullopt;
    std::ostringstream line;
    line << std::setprecision(2) << std::scientific << "true " << true_error << " > 3 × estimate "
         << est << " (" << cause << ")";
    return line.str();
}

}  // namespace rotbeam::estimate
