// Central-difference Jacobians for tests.
//
// Step h_k = ∛ε · max(1, |x_k|): for a central difference the truncation error is O(h²) and the
// round-off error O(ε/h), balanced at h ~ ∛ε ≈ 6e-6, giving ~ε^(2/3) ≈ 4e-11 relative accuracy for
// smooth functions of unit scale. Tests derive their tolerance from that.
#pragma once

#include <cmath>
#include <functional>
#include <limits>

#include "core/types.hpp"

namespace rotbeam {

inline double central_difference_step(double x) {
    return std::cbrt(std::numeric_limits<double>::epsilon()) * std::max(1.0, std::abs(x));
}

// J_ij = ∂f_i/∂x_j of f: Rⁿ → Rᵐ at x.
inline MatX central_difference_jacobian(const std::function<VecX(const VecX&)>& f, const VecX& x) {
    const VecX f0 = f(x);
    MatX J(f0.size(), x.size());
    for (Eigen::Index j = 0; j < x.size(); ++j) {
        const double h = central_difference_step(x[j]);
        VecX xp = x, xm = x;
        xp[j] += h;
        xm[j] -= h;
        J.col(j) = (f(xp) - f(xm)) / (2.0 * h);
    }
    return J;
}

// The same through a retraction: column j is (f(x ⊕ h e_j) − f(x ⊕ −h e_j)) / 2h, with
// f_at_increment(δ) evaluating f at x ⊕ δ for an increment δ of dimension n.
inline MatX central_difference_jacobian_retraction(
    const std::function<VecX(const VecX&)>& f_at_increment, Eigen::Index n, double h_scale = 1.0) {
    const VecX f0 = f_at_increment(VecX::Zero(n));
    MatX J(f0.size(), n);
    const double h = central_difference_step(0.0) * h_scale;
    for (Eigen::Index j = 0; j < n; ++j) {
        VecX d = VecX::Zero(n);
        d[j] = h;
        const VecX fp = f_at_increment(d);
        d[j] = -h;
        const VecX fm = f_at_increment(d);
        J.col(j) = (fp - fm) / (2.0 * h);
    }
    return J;
}

}  // namespace rotbeam
