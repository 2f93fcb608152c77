// A two-unknown DAE whose algebraic row cannot be solved below its round-off floor: ẋ − 1 = 0
// (x differential) and K (y² − 2) = 0 (y algebraic, root √2), with K = 1e12 and unit residual and
// state scales. No double squares to 2: the two around √2 give y² = 2 ± 4.4e-16, so the y row's
// scaled residual is at least K · 4.4e-16 = 4.4e-4 (its expected floor ε |∂r/∂y| = 6.2e-4), far
// above a Newton tolerance of 1e-10, however exact y is: every Newton on this system, the
// consistent initial conditions' included, ends stalled at round-off. Start with y ≠ 0.
#pragma once

#include "core/dae_system.hpp"

namespace rotbeam::test {

class StiffRowSystem : public DaeSystem {
  public:
    static constexpr double kStiffness = 1e12;
    StiffRowSystem() {
        pattern_ = SparseMatrix(2, 2);
        pattern_.insert(0, 0) = 0.0;
        pattern_.insert(1, 1) = 0.0;
        pattern_.makeCompressed();
        ones_ = VecX::Ones(2);
        differential_ = VecX::Zero(2);
        differential_[0] = 1.0;
    }
    int size() const override { return 2; }
    void evaluate(double /*t*/, const VecX& x, const VecX& xdot, VecX& r, SparseMatrix* Jx,
                  SparseMatrix* Jxd) override {
        r.resize(2);
        r[0] = xdot[0] - 1.0;
        r[1] = kStiffness * (x[1] * x[1] - 2.0);
        if (Jx != nullptr) {
            *Jx = pattern_;
            Jx->coeffRef(1, 1) = 2.0 * kStiffness * x[1];
        }
        if (Jxd != nullptr) {
            *Jxd = pattern_;
            Jxd->coeffRef(0, 0) = 1.0;
        }
    }
    const SparseMatrix& pattern() const override { return pattern_; }
    const VecX& differential() const override { return differential_; }
    const VecX& residual_scale() const override { return ones_; }
    const VecX& state_scale() const override { return ones_; }
    AssemblyCounters counters() const override { return {}; }

  private:
    SparseMatrix pattern_;
    VecX ones_, differential_;
};

}  // namespace rotbeam::test
