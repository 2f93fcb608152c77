// The one finite-difference check of a formulation's analytic Jacobian, for every combination of
// the harness (statics and dynamics, displacement and mixed).
//
// Column k of the difference Jacobian is (f(x ⊕ h_k e_k) − f(x ⊕ −h_k e_k)) / 2h_k, where
// f_at(δ) evaluates the residual at the state moved by the increment δ: through the formulation's
// retraction (the displacement formulation's Newton update) or additively (the mixed formulation's
// unknowns are the parameters themselves). The steps follow core/finite_difference.hpp: h_k = ∛ε
// times the unknown's scale (the increment scale of the displacement formulation, max(1, |x_k|)
// of the mixed one), which balances truncation O(h²) against round-off O(ε/h) at ~ε^(2/3) ≈ 4e-11
// relative for smooth functions of unit scale. Each caller argues its tolerance from that.
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

#include "core/types.hpp"

namespace rotbeam::test {

// How far an analytic Jacobian J is from the central differences.
struct JacobianError {
    // max_k ‖J_fd,k − J_k‖∞ s_k / max(‖J_k‖∞ s_k, 1e-3 max|J|): each column relative to its own
    // size in scaled unknowns (s_k the unknown's scale), small columns to 1e-3 of the largest
    // entry.
    double column_relative = 0.0;
    // max |J − J_fd| (unscaled).
    double absolute = 0.0;
    // max |J|: a comparison against a vanishing Jacobian would prove nothing.
    double largest_entry = 0.0;
};

// The difference Jacobian of f_at (an increment of scale.size() unknowns → the residual) with the
// steps h_k = ∛ε · scale_k, against J.
inline JacobianError compare_with_central_differences(const MatX& J,
                                                      const std::function<VecX(const VecX&)>& f_at,
                                                      const VecX& scale) {
    const double root_eps = std::cbrt(std::numeric_limits<double>::epsilon());
    JacobianError e;
    e.largest_entry = J.cwiseAbs().maxCoeff();
    VecX d = VecX::Zero(scale.size());
    for (Eigen::Index k = 0; k < scale.size(); ++k) {
        const double h = root_eps * scale[k];
        d[k] = h;
        const VecX fp = f_at(d);
        d[k] = -h;
        const VecX fm = f_at(d);
        d[k] = 0.0;
        const VecX fd = (fp - fm) / (2.0 * h);
        const double err = (fd - J.col(k)).cwiseAbs().maxCoeff();
        const double col = J.col(k).cwiseAbs().maxCoeff();
        e.absolute = std::max(e.absolute, err);
        e.column_relative = std::max(
            e.column_relative, err * scale[k] / std::max(col * scale[k], 1e-3 * e.largest_entry));
    }
    return e;
}

// The residual of a formulation that keeps its state in checkpoint slots (the displacement
// statics and dynamics) at the slot's state ⊕ dx, through its retraction; the state is back at
// the slot's afterwards.
template <class S>
VecX residual_after_retraction(S& s, int slot, const VecX& dx) {
    s.restore_state(slot);
    s.retract(dx);
    VecX r;
    s.evaluate(r, nullptr);
    s.restore_state(slot);
    return r;
}

// The mixed formulation's steps: max(1, |x_k|) (core/finite_difference.hpp).
inline VecX additive_scale(const VecX& x) { return x.cwiseAbs().cwiseMax(1.0); }

}  // namespace rotbeam::test
