#include "core/convergence.hpp"

#include <algorithm>
#include <cmath>

namespace rotbeam {

const char* to_string(Convergence c) {
    switch (c) {
        case Convergence::none:
            return "none";
        case Convergence::exact:
            return "exact";
        case Convergence::residual_and_correction:
            return "residual-and-correction";
        case Convergence::stalled_at_round_off:
            return "stalled-at-round-off";
    }
    return "none";
}

double round_off_floor(const SparseMatrix& J, const VecX& residual_scale,
                       const VecX& increment_scale, VecX& work) {
    work.setZero(J.rows());
    for (Eigen::Index c = 0; c < J.outerSize(); ++c) {
        for (SparseMatrix::InnerIterator it(J, c); it; ++it) {
            work[it.row()] += std::abs(it.value()) * increment_scale[c];
        }
    }
    double m = 0.0;
    for (Eigen::Index i = 0; i < work.size(); ++i) m = std::max(m, work[i] / residual_scale[i]);
    return std::numeric_limits<double>::epsilon() * m;
}

double scaled_max_norm(const VecX& v, const VecX& scale) {
    double m = 0.0;
    for (Eigen::Index i = 0; i < v.size(); ++i) {
        const double a = std::abs(v[i]) / scale[i];
        if (!std::isfinite(a)) return std::numeric_limits<double>::infinity();
        m = std::max(m, a);
    }
    return m;
}

bool at_round_off(const IterateMeasures& m) {
    return m.residual <= kRoundOffMargin * m.round_off_floor;
}

Convergence accepted(const IterateMeasures& m, const ConvergenceTolerances& t) {
    if (m.residual == 0.0) return Convergence::exact;
    if (m.residual <= t.residual && m.correction <= t.increment) {
        return Convergence::residual_and_correction;
    }
    const bool correction_stopped = !m.linear || m.correction >= 0.5 * m.previous_correction;
    if (at_round_off(m) && m.last_step_full && m.residual >= 0.5 * m.previous_residual &&
        correction_stopped) {
        return Convergence::stalled_at_round_off;
    }
    return Convergence::none;
}

}  // namespace rotbeam
