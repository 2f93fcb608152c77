// The fixed-step scheme and the consistent initial conditions of core/dae_driver.hpp, both as
// additive nonlinear systems for the shared Newton (solve_newton).
#include <array>
#include <cmath>
#include <limits>
#include <sstream>

#include "core/dae_driver.hpp"
#include "core/errors.hpp"
#include "core/step_observer.hpp"
#include "core/time_limit.hpp"

namespace rotbeam {

namespace {

// An increment δx_j is resolvable only to the residual's accuracy: it changes row i by J_ij δx_j,
// so below min_i rscale_i / |J_ij| (times the tolerance) it is invisible in every scaled residual
// row. The increment scale is raised to that resolution where the unknown's own scale is finer
// (an angular-momentum rate whose effect h Ḣ on a moment row is tiny against the moment scale; a
// stiff section's force), so the increment test asks for what round-off allows.
void raise_to_resolution(const SparseMatrix& J, const VecX& rscale, VecX& scale) {
    for (Eigen::Index c = 0; c < J.outerSize(); ++c) {
        double resolution = std::numeric_limits<double>::infinity();
        for (SparseMatrix::InnerIterator it(J, c); it; ++it) {
            if (it.value() != 0.0) {
                resolution = std::min(resolution, rscale[it.row()] / std::abs(it.value()));
            }
        }
        if (std::isfinite(resolution)) scale[c] = std::max(scale[c], resolution);
    }
}

// Common state handling of the two systems below: an additive unknown vector with checkpoints.
class AdditiveSystem : public NonlinearSystem {
  public:
    explicit AdditiveSystem(DaeSystem& dae) : dae_(dae) {}
    int size() const override { return dae_.size(); }
    void retract(const Eigen::Ref<const VecX>& dx) override { z_ += dx; }
    void save_state(int slot) override { saved_[static_cast<std::size_t>(slot)] = z_; }
    void restore_state(int slot) override { z_ = saved_[static_cast<std::size_t>(slot)]; }
    const VecX& residual_scale() const override { return dae_.residual_scale(); }
    bool additive() const override { return true; }
    VecX state_vector() const override { return z_; }
    void set_state_vector(const Eigen::Ref<const VecX>& z) override { z_ = z; }

  protected:
    DaeSystem& dae_;
    VecX z_;
    std::array<VecX, kCheckpointSlots> saved_;
    VecX xdot_;
    SparseMatrix Jx_, Jxd_;
};

// One trapezoidal step: unknown X_{n+1}, Ẋ_{n+1} = 2/Δt (X_{n+1} − X_n) − Ẋ_n.
class TrapezoidalStep : public AdditiveSystem {
  public:
    TrapezoidalStep(DaeSystem& dae, double dt) : AdditiveSystem(dae), dt_(dt) {}
    void begin(double t, const VecX& xn, const VecX& xdn) {
        t_ = t;
        xn_ = xn;
        xdn_ = xdn;
        z_ = xn;  // predictor: the last state (the Newton's first iterate)
    }
    const VecX& state() const { return z_; }
    // The algebraic unknowns' rates are not in F (∂F/∂Ẋ has zero columns there); they are kept
    // at zero rather than propagated by the recurrence, where they would carry (X_{n+1} − X_n)/Δt
    // of quantities that are not differentiable in time.
    const VecX& rate() {
        xdot_ = (2.0 / dt_) * (z_ - xn_) - xdn_;
        xdot_.array() *= dae_.differential().array();
        return xdot_;
    }
    void evaluate(VecX& residual, SparseMatrix* jacobian) override {
        rate();
        if (jacobian == nullptr) {
            dae_.evaluate(t_, z_, xdot_, residual, nullptr, nullptr);
            return;
        }
        dae_.evaluate(t_, z_, xdot_, residual, &Jx_, &Jxd_);
        combine_same_pattern(Jx_, 2.0 / dt_, Jxd_, *jacobian);
    }
    const VecX& increment_scale() const override { return scale_; }
    std::string describe_state() const override { return dae_.describe_state(z_); }
    // The increment scales at the current iteration matrix (once, at the first step).
    void set_scales() {
        scale_ = dae_.increment_scale();
        VecX r;
        SparseMatrix J;
        evaluate(r, &J);
        raise_to_resolution(J, dae_.residual_scale(), scale_);
    }

  private:
    VecX scale_;
    double dt_;
    double t_ = 0.0;
    VecX xn_, xdn_;
};

// Unknowns: the algebraic entries of X and the differential entries of Ẋ (one vector z, entry by
// entry); the Jacobian column of an entry is ∂F/∂X's or ∂F/∂Ẋ's.
class InitialConditions : public AdditiveSystem {
  public:
    InitialConditions(DaeSystem& dae, double t, const VecX& x, const VecX& xdot, double rate_time)
        : AdditiveSystem(dae), t_(t), x_(x), d_(dae.initial_condition_differential(x)) {
        const VecX& d = d_;
        z_ = VecX(x.size());
        scale_ = dae.increment_scale();
        for (Eigen::Index i = 0; i < x.size(); ++i) {
            z_[i] = d[i] != 0.0 ? xdot[i] : x[i];
            // A rate's scale: the unknown's scale per `rate_time` (the time step).
            if (d[i] != 0.0) scale_[i] = dae.state_scale()[i] / rate_time;
        }
        VecX r;
        SparseMatrix J;
        evaluate(r, &J);
        raise_to_resolution(J, dae.residual_scale(), scale_);
    }
    void split(VecX& x, VecX& xdot) const {
        const VecX& d = d_;
        x = x_;
        xdot = VecX::Zero(x_.size());
        for (Eigen::Index i = 0; i < x_.size(); ++i) {
            if (d[i] != 0.0) {
                xdot[i] = z_[i];
            } else {
                x[i] = z_[i];
            }
        }
    }
    void evaluate(VecX& residual, SparseMatrix* jacobian) override {
        split(xs_, xdot_);
        if (jacobian == nullptr) {
            dae_.evaluate(t_, xs_, xdot_, residual, nullptr, nullptr);
            return;
        }
        dae_.evaluate(t_, xs_, xdot_, residual, &Jx_, &Jxd_);
        if (jacobian->nonZeros() != Jx_.nonZeros()) *jacobian = Jx_;
        const VecX& d = d_;
        for (Eigen::Index c = 0; c < Jx_.outerSize(); ++c) {
            const SparseMatrix& from = d[c] != 0.0 ? Jxd_ : Jx_;
            for (int k = Jx_.outerIndexPtr()[c]; k < Jx_.outerIndexPtr()[c + 1]; ++k) {
                jacobian->valuePtr()[k] = from.valuePtr()[k];
            }
        }
    }
    const VecX& increment_scale() const override { return scale_; }

  private:
    double t_;
    VecX x_;
    VecX d_;  // the initial-condition split (DaeSystem::initial_condition_differential)
    VecX xs_;
    VecX scale_;
};

}  // namespace

bool already_consistent(DaeSystem& dae, double t, const VecX& x, const VecX& xdot,
                        double tolerance) {
    VecX r;
    dae.evaluate(t, x, xdot, r, nullptr, nullptr);
    return (r.array() / dae.residual_scale().array()).abs().maxCoeff() <= tolerance;
}

NewtonOutcome consistent_initial_conditions(DaeSystem& dae, double t, VecX& x, VecX& xdot,
                                            const NewtonSettings& settings, double rate_time) {
    if (already_consistent(dae, t, x, xdot, settings.residual_tolerance)) {
        NewtonOutcome consistent;
        consistent.converged = true;  // accepted as given: no solve, so no criterion
        return consistent;
    }
    InitialConditions ic(dae, t, x, xdot, rate_time);
    const NewtonOutcome out = solve_newton(ic, settings);
    if (out.accepted()) {
        ic.split(x, xdot);
        dae.complete_initial_rates(x, xdot);
    }
    return out;
}

DaeOutcome integrate_trapezoidal(DaeSystem& dae, VecX& x, VecX& xdot, const DaeSettings& s,
                                 const DaeOutput& output) {
    ROTBEAM_VERIFY(s.time_step > 0.0 && s.end_time > s.start_time, "bad time interval");
    DaeOutcome outcome;
    outcome.last_time = s.start_time;
    const NewtonOutcome ic =
        consistent_initial_conditions(dae, s.start_time, x, xdot, s.newton, s.time_step);
    if (!ic.accepted()) {
        outcome.status = ic.singular ? SolveStatus::singular : SolveStatus::diverged;
        outcome.message =
            "initial conditions at t = " + std::to_string(s.start_time) + ": " + ic.failure;
        return outcome;
    }
    outcome.newton_iterations += ic.iterations;
    StallSummary stalls;
    stalls.add(ic);
    if (output) output(s.start_time, x, xdot, ic.iterations);
    const long steps = std::lround((s.end_time - s.start_time) / s.time_step);
    const long every =
        s.output_interval > 0.0 ? std::max(1L, std::lround(s.output_interval / s.time_step)) : 1;
    TrapezoidalStep step(dae, s.time_step);
    // One Newton workspace for all steps: the LU's symbolic analysis (ordering, elimination tree)
    // is made once per pattern instead of once per step, where it was 9.6 % of the instructions
    // of a mixed joined-beam run (docs/performance.md, joined-beam profile).
    NewtonWorkspace workspace(s.newton.dense_linear_solver ? SparseLUSolver::Kind::dense
                                                           : SparseLUSolver::Kind::sparse_lu);
    for (long n = 1; n <= steps; ++n) {
        const double t = s.start_time + static_cast<double>(n) * s.time_step;
        check_time_limit("at time", t - s.time_step);
        step.begin(t, x, xdot);
        if (n == 1) step.set_scales();
        NewtonOutcome out;
        try {
            out = solve_newton(step, s.newton, workspace);
        } catch (const TimeLimitReached& e) {
            rethrow_with_context(e, "in the step to time", t);
        }
        outcome.newton_iterations += out.iterations;
        if (!out.accepted()) {
            std::ostringstream m;
            m << "fixed-step Newton failed at t = " << t << " (step " << n << ", Δt " << s.time_step
              << "): " << out.failure;
            outcome.status = out.singular ? SolveStatus::singular : SolveStatus::diverged;
            outcome.message = m.str();
            return outcome;
        }
        stalls.add(out);
        x = step.state();
        xdot = step.rate();
        outcome.steps = n;
        outcome.last_time = t;
        if (output && (n % every == 0 || n == steps)) output(t, x, xdot, out.iterations);
        if (step_observed()) {
            notify_step({t, n, outcome.newton_iterations, dae.counters().jacobian_evaluations});
        }
    }
    const AssemblyCounters c = dae.counters();
    outcome.residual_evaluations = c.residual_evaluations;
    outcome.jacobian_evaluations = c.jacobian_evaluations;
    outcome.message = "fixed-step trapezoidal, " + std::to_string(steps) + " steps";
    if (stalls.count > 0) {
        outcome.status = SolveStatus::stalled_at_round_off;
        outcome.message += "; " + stalls.describe("solves", s.newton.residual_tolerance);
    }
    return outcome;
}

}  // namespace rotbeam
