// A scalar DAE ẋ − cos t = 0 (x(0) = 0, x = sin t) whose evaluation is refused (SingularityError,
// as a parameterization near its singular angle) or fails (another exception, when `fatal`) the
// first `refusals` times it is asked about a time in (0.5, refuse_until]: what the time
// integrators' step cuts and the IDA trampolines make of a refused state.
#pragma once

#include <limits>
#include <stdexcept>

#include "core/dae_system.hpp"
#include "core/errors.hpp"

namespace rotbeam::test {

class RefusingSystem : public DaeSystem {
  public:
    explicit RefusingSystem(int refusals, bool fatal = false,
                            double refuse_until = std::numeric_limits<double>::infinity())
        : refusals_(refusals), fatal_(fatal), refuse_until_(refuse_until) {
        pattern_ = SparseMatrix(1, 1);
        pattern_.insert(0, 0) = 0.0;
        pattern_.makeCompressed();
        ones_ = VecX::Ones(1);
    }
    int size() const override { return 1; }
    void evaluate(double t, const VecX& /*x*/, const VecX& xdot, VecX& r, SparseMatrix* Jx,
                  SparseMatrix* Jxd) override {
        if (t > 0.5 && t <= refuse_until_ && refused < refusals_) {
            ++refused;
            if (fatal_) throw std::logic_error("a fatal evaluation error");
            throw SingularityError("toy", "evaluate", 6.28, "refused on purpose");
        }
        r.resize(1);
        r[0] = xdot[0] - std::cos(t);
        if (Jx != nullptr) {
            *Jx = pattern_;
            Jx->valuePtr()[0] = 0.0;
        }
        if (Jxd != nullptr) {
            *Jxd = pattern_;
            Jxd->valuePtr()[0] = 1.0;
        }
    }
    const SparseMatrix& pattern() const override { return pattern_; }
    const VecX& differential() const override { return ones_; }
    const VecX& residual_scale() const override { return ones_; }
    const VecX& state_scale() const override { return ones_; }
    AssemblyCounters counters() const override { return {}; }
    int refused = 0;

  private:
    int refusals_;
    bool fatal_;
    double refuse_until_;
    SparseMatrix pattern_;
    VecX ones_;
};

}  // namespace rotbeam::test
