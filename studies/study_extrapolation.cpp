#include "study_extrapolation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/errors.hpp"

namespace rotbeam::cli {

Richardson richardson(double f0, double f1, double f2, double ratio) {
    ROTBEAM_VERIFY(ratio > 1.0, "richardson: the refinement ratio must exceed 1");
    const double d1 = f1 - f0, d2 = f2 - f1;
    Richardson r{f2, std::numeric_limits<double>::quiet_NaN(), false};
    // Asymptotic: both differences of one sign and shrinking. d2 = 0 (converged to round-off)
    // leaves nothing to extrapolate.
    if (!(d1 * d2 > 0.0) || !(std::abs(d2) < std::abs(d1))) return r;
    r.order = std::log(d1 / d2) / std::log(ratio);
    r.value = f2 + d2 / (std::pow(ratio, r.order) - 1.0);
    r.valid = true;
    return r;
}

namespace {

bool same_time(double a, double b) { return std::abs(a - b) <= 1e-9 * (1.0 + std::abs(a)); }

double norm_at(const History& h, size_t i) {
    return std::sqrt(h.x[i] * h.x[i] + h.y[i] * h.y[i] + h.z[i] * h.z[i]);
}

}  // namespace

double history_error(const History& u, const History& reference) {
    double scale = 0.0;
    for (size_t i = 0; i < reference.size(); ++i) scale = std::max(scale, norm_at(reference, i));
    double worst = 0.0;
    size_t j = 0;
    for (size_t i = 0; i < u.size(); ++i) {
        while (j < reference.size() && reference.time[j] < u.time[i] &&
               !same_time(reference.time[j], u.time[i])) {
            ++j;
        }
        if (j == reference.size() || !same_time(reference.time[j], u.time[i])) {
            return std::numeric_limits<double>::quiet_NaN();
        }
        const double dx = u.x[i] - reference.x[j], dy = u.y[i] - reference.y[j],
                     dz = u.z[i] - reference.z[j];
        worst = std::max(worst, std::sqrt(dx * dx + dy * dy + dz * dz));
    }
    if (u.size() == 0 || !(scale > 0.0)) return std::numeric_limits<double>::quiet_NaN();
    return worst / scale;
}

History extrapolate_history(const History& coarse, const History& fine, double ratio,
                            double order) {
    ROTBEAM_VERIFY(coarse.size() == fine.size(), "extrapolate_history: different output counts");
    const double factor = 1.0 / (std::pow(ratio, order) - 1.0);
    History out = fine;
    for (size_t i = 0; i < fine.size(); ++i) {
        ROTBEAM_VERIFY(same_time(coarse.time[i], fine.time[i]),
                       "extrapolate_history: different output times");
        out.x[i] += (fine.x[i] - coarse.x[i]) * factor;
        out.y[i] += (fine.y[i] - coarse.y[i]) * factor;
        out.z[i] += (fine.z[i] - coarse.z[i]) * factor;
    }
    return out;
}

}  // namespace rotbeam::cli
