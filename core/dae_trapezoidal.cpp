// The fixed-step scheme and the consistent initial conditions of core/dae_driver.hpp, both as
// additive nonlinear systems for the shared Newton (solve_newton).
#include <array>
#include <cmath>
#include <limits>
#include <sstream>

#include "core/dae_driver.hpp"
#include "core/dae_fixed_steps.hpp"
#include "core/errors.hpp"
#include "core/step_observer.hpp"
#include "core/step_size_control.hpp"
#include "core/time_limit.hpp"

namespace rotbeam {

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

namespace {

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
    explicit TrapezoidalStep(DaeSystem& dae) : AdditiveSystem(dae) {}
    void begin(double t, double dt, const VecX& xn, const VecX& xdn) {
        t_ = t;
        dt_ = dt;
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
    double dt_ = 0.0;
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

namespace {

// The run of the fixed-step scheme: the state, the step (one Newton workspace for all steps: the
// LU's symbolic analysis is made once per pattern instead of once per step, where it was 9.6 % of
// the instructions of a mixed joined-beam run, docs/performance.md) and the bookkeeping.
class TrapezoidalRun : public DaeRun {
  public:
    TrapezoidalRun(DaeSystem& dae, VecX& x, VecX& xdot, const DaeSettings& s, DaeOutcome& outcome)
        : DaeRun(dae, x, xdot, s, outcome, "fixed-step Newton", "Newton"),
          step_(dae),
          workspace_(s.newton.dense_linear_solver ? SparseLUSolver::Kind::dense
                                                  : SparseLUSolver::Kind::sparse_lu) {}

    // The converged step's rate Ẋ_{n+1} (before accept).
    const VecX& rate() { return step_.rate(); }

    // Tries the step of size h to t_next from the state at t (unchanged until accept).
    bool try_step(double t_next, double h) {
        step_.begin(t_next, h, x_, xdot_);
        if (!scaled_) {
            step_.set_scales();  // once, at the first step's iteration matrix
            scaled_ = true;
        }
        try {
            return attempted(solve_newton(step_, s_.newton, workspace_));
        } catch (const TimeLimitReached& e) {
            rethrow_with_context(e, "in the step to time", t_next);
        }
    }
    void accept(double t_next, double h) {
        x_ = step_.state();
        xdot_ = step_.rate();
        accepted(t_next, h);
        if (adaptive_) {
            accel_before_ = accel_;
            h_before_ = h;
        }
    }
    void finish(const std::string& what) { DaeRun::finish(what, "solves"); }

    // Adaptive steps (core/step_size_control.hpp). The trapezoidal rule's local error is
    // −h³/12 X⃛ (Hairer, Nørsett & Wanner I, §II.7); X⃛ is estimated on the differential unknowns
    // from the rates of three consecutive states, X¨_{n+1/2} = (Ẋ_{n+1} − Ẋ_n)/h_n and
    // X⃛ ≈ 2 (X¨_{n+1/2} − X¨_{n−1/2}) / (h_n + h_{n−1}), each unknown divided by its state scale,
    // measured on the configuration only (the system's configuration(): u, c of the mixed
    // formulation), as Radau IIA's (core/dae_radau.hpp "Adaptive steps"). With the momenta in it
    // the closed loop of the joined beam underflowed its step at t = 0.015 s: the load's onset
    // excites stiff modes that the trapezoidal rule does not damp, and their momenta, their
    // displacements times ω, made the estimate's largest entry a momentum ~3000× the
    // configuration's (measured; tests/mixed/test_mixed_trapezoidal_adaptive.cpp).
    // The first step has no X¨_{n−1/2} (returns −1: no estimate); it is taken at kFirstStep of the
    // case's Δt (its error, ∝ h³, is then 1e-9 of a full step's) and the control grows the step
    // from there (at most 2× per step).
    static constexpr double kFirstStep = 1e-3;
    double local_error(double h) {
        if (!adaptive_) {
            weight_ = dae_.configuration().cwiseQuotient(dae_.state_scale());
            adaptive_ = true;
        }
        accel_ = (step_.rate() - xdot_) / h;
        if (accel_before_.size() == 0) return -1.0;
        return h * h * h / 12.0 *
               (2.0 * (accel_ - accel_before_) / (h + h_before_))
                   .cwiseProduct(weight_)
                   .lpNorm<Eigen::Infinity>();
    }

  private:
    TrapezoidalStep step_;
    NewtonWorkspace workspace_;
    bool scaled_ = false;
    bool adaptive_ = false;
    VecX weight_, accel_, accel_before_;  // X¨_{n−1/2}: empty before the first step
    double h_before_ = 0.0;
};

}  // namespace

DaeOutcome integrate_trapezoidal(DaeSystem& dae, VecX& x, VecX& xdot, const DaeSettings& s,
                                 const DaeOutput& output) {
    DaeOutcome outcome;
    NewtonOutcome ic;
    if (!start_dae_run(dae, x, xdot, s, output, outcome, ic)) return outcome;
    TrapezoidalRun run(dae, x, xdot, s, outcome);
    run.add_initial(ic);
    run.start(s.start_time);
    if (s.time_tolerance > 0.0) {
        StepSizeControl control{s.time_tolerance, s.end_time - s.start_time};
        if (!run_adaptive_steps(run, s, control, TrapezoidalRun::kFirstStep * s.time_step, output,
                                outcome)) {
            return outcome;
        }
        std::ostringstream m;
        m.precision(3);
        m << "adaptive trapezoidal, " << outcome.steps << " steps, tolerance " << s.time_tolerance
          << ", steps " << outcome.control.smallest_step << " … " << outcome.control.largest_step
          << ", " << outcome.control.rejected_steps << " rejected";
        run.finish(m.str());
        return outcome;
    }
    if (!run_fixed_steps(run, s, output)) return outcome;
    run.finish("fixed-step trapezoidal, " +
               std::to_string(std::lround((s.end_time - s.start_time) / s.time_step)) + " steps");
    return outcome;
}

}  // namespace rotbeam
