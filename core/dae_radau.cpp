// The 3-stage Radau IIA method on an implicit DAE (core/dae_radau.hpp): the tableau, its
// eigen-transformation, one step's simplified Newton and the fixed-step run.
#include "core/dae_radau.hpp"

#include <Eigen/Eigenvalues>
#include <array>
#include <cmath>
#include <complex>
#include <sstream>

#include "core/complex_klu.hpp"
#include "core/convergence.hpp"
#include "core/dae_fixed_steps.hpp"
#include "core/errors.hpp"
#include "core/sparse_lu.hpp"
#include "core/stage_iteration.hpp"
#include "core/step_observer.hpp"
#include "core/step_size_control.hpp"
#include "core/time_limit.hpp"

namespace rotbeam {

namespace {

using Complex = std::complex<double>;
constexpr int kStages = 3;

// Fresh stage matrices (∂F/∂X and ∂F/∂Ẋ, the real and the complex KLU factorization) cost about
// eight stage iterations (three residuals, the two solves, the transformations) on the joined beam
// (callgrind, mixed/WM at 2/3 ms, KLU with COLAMD: 8.2 M against 1.05 M per iteration;
// docs/performance.md "Cost of one step of the high-order schemes"). KeptMatrices' budget and the
// renewal rule's cost of fresh matrices.
constexpr double kRadauFreshMatrixCost = 8.0;

// Radau IIA, s = 3 (HW II, Table IV.5.6), and W = A⁻¹ = S Λ S⁻¹ with the real eigenvalue first
// and the pair's representative (imaginary part > 0) second; the third column of S is the
// conjugate of the second, so the third transformed system is the conjugate of the second's.
struct RadauTableau {
    Eigen::Matrix3d A, W;
    Eigen::Vector3d c;
    Eigen::Matrix3cd S, S_inv;
    // S⁻¹'s rows as used on real stage residuals: the real eigenvalue's row, then the real and the
    // imaginary part of the pair's row.
    Eigen::Matrix3d S_inv_real;
    double gamma = 0.0;  // the real eigenvalue of W
    Complex mu;          // the pair's representative α + iβ
    Eigen::Vector3d d;   // the embedded error estimate's weights on Z_i (radau_error_weights)
};

// The embedded estimate (HW II §IV.8, Eq. (8.19)–(8.20)): with γ0 = 1/γ, the method
// ŷ1 = y0 + h (γ0 f(y0) + Σ b̂_i f(Y_i)) of order 3 on the nodes (0, c) has
// ŷ1 − y1 = γ0 h f(y0) + Σ e_i Z_i with e = Wᵀ (b̂ − b), since h f(Y_i) = Σ_j w_ij Z_j. Returned
// as d = γ e, the weights of the estimate divided by γ0 h (HW's code RADAU5 writes them
// −(13 + 7√6)/3, (−13 + 7√6)/3, −1/3; checked against these).
Eigen::Vector3d radau_error_weights(const RadauTableau& t) {
    Eigen::Matrix3d V;
    V.row(0).setOnes();
    V.row(1) = t.c.transpose();
    V.row(2) = t.c.cwiseAbs2().transpose();
    const Eigen::Vector3d b_hat =
        V.partialPivLu().solve(Eigen::Vector3d(1.0 - 1.0 / t.gamma, 0.5, 1.0 / 3.0));
    const Eigen::Vector3d d = t.gamma * (t.W.transpose() * (b_hat - t.A.row(2).transpose()));
    const double r = std::sqrt(6.0);
    const Eigen::Vector3d closed(-(13.0 + 7.0 * r) / 3.0, (-13.0 + 7.0 * r) / 3.0, -1.0 / 3.0);
    ROTBEAM_VERIFY((d - closed).cwiseAbs().maxCoeff() <= 1e-12 * closed.cwiseAbs().maxCoeff(),
                   "Radau IIA tableau: embedded error weights differ from their closed form");
    return d;
}

RadauTableau radau_tableau() {
    RadauTableau t;
    const double r = std::sqrt(6.0);
    t.c << (4.0 - r) / 10.0, (4.0 + r) / 10.0, 1.0;
    t.A << (88.0 - 7.0 * r) / 360.0, (296.0 - 169.0 * r) / 1800.0, (-2.0 + 3.0 * r) / 225.0,
        (296.0 + 169.0 * r) / 1800.0, (88.0 + 7.0 * r) / 360.0, (-2.0 - 3.0 * r) / 225.0,
        (16.0 - r) / 36.0, (16.0 + r) / 36.0, 1.0 / 9.0;
    t.W = t.A.inverse();  // the 3 × 3 Butcher matrix, not a stage system
    const Eigen::EigenSolver<Eigen::Matrix3d> es(t.W);
    int real = -1, pair = -1;
    for (int k = 0; k < kStages; ++k) {
        const Complex l = es.eigenvalues()(k);
        if (std::abs(l.imag()) <= 1e-12 * std::abs(l)) real = k;
        if (l.imag() > 1e-12 * std::abs(l)) pair = k;
    }
    ROTBEAM_VERIFY(real >= 0 && pair >= 0, "Radau IIA tableau: unexpected spectrum of A⁻¹");
    t.gamma = es.eigenvalues()(real).real();
    t.mu = es.eigenvalues()(pair);
    t.S.col(0) = es.eigenvectors().col(real).real().cast<Complex>();
    t.S.col(1) = es.eigenvectors().col(pair);
    t.S.col(2) = es.eigenvectors().col(pair).conjugate();
    t.S_inv = t.S.inverse();
    t.S_inv_real.row(0) = t.S_inv.row(0).real();
    t.S_inv_real.row(1) = t.S_inv.row(1).real();
    t.S_inv_real.row(2) = t.S_inv.row(1).imag();
    const Eigen::Vector3cd lambda(t.gamma, t.mu, std::conj(t.mu));
    const double defect =
        (t.S * lambda.asDiagonal() * t.S_inv - t.W.cast<Complex>()).cwiseAbs().maxCoeff();
    ROTBEAM_VERIFY(defect <= 1e-12 * t.W.cwiseAbs().maxCoeff(), "Radau IIA tableau: W ≠ S Λ S⁻¹");
    t.d = radau_error_weights(t);
    return t;
}

// One step's stage equations and their simplified Newton (core/dae_radau.hpp). Buffers are sized
// once; both KLUs (real and complex) keep their pivot orders and refactor in place.
class RadauStepper {
  public:
    RadauStepper(DaeSystem& dae, const NewtonSettings& newton)
        : dae_(dae), T_(radau_tableau()), newton_(newton), n_(dae.size()) {
        for (auto* v : {&Z_, &Zold_, &Ydot_, &R_, &dZ_}) {
            for (VecX& z : *v) z.setZero(n_);
        }
        for (auto* v : {&y_, &r_, &gr_, &xr_, &x1_, &xd1_}) v->setZero(n_);
        xc_.setZero(n_);
    }

    // From (x_n, ẋ_n) at t to t + h; on success state() and rate() are the step end. The stage
    // matrices of an earlier step are kept while they serve (KeptMatrices,
    // core/stage_iteration.hpp); if the iteration with them fails or reaches its limit, fresh ones
    // are made and the step is tried again before it counts as failed.
    NewtonOutcome step(double t, double h, const VecX& xn, const VecX& xdn);
    // The step of size h was accepted: its stages predict the next step's.
    void remember(double h) {
        Zold_ = Z_;
        h_old_ = h;
    }
    const VecX& state() const { return x1_; }
    const VecX& rate() const { return xd1_; }
    long factorizations() const { return factorizations_; }
    // After a converged step h from (x_n, ẋ_n) at t: the embedded local error estimate, scaled max
    // norm with `weight`; filtered a second time when the first exceeds `allowed`
    // (core/dae_radau.hpp "Adaptive steps").
    double local_error(double t, double h, const VecX& xn, const VecX& xdn, const VecX& weight,
                       double allowed);

  private:
    // budget: iterate_stages' (0: none).
    NewtonOutcome iterate(double t, double h, const VecX& xn, const VecX& xdn, bool fresh,
                          int budget);
    bool factor(double t, double h, const VecX& xn, const VecX& xdn);
    void predict(double h, const VecX& xdn);
    double stage_residuals(double t, double h, const VecX& xn);
    double correction();
    void stage_rate(int i, double h, VecX& out) const;

    DaeSystem& dae_;
    RadauTableau T_;
    NewtonSettings newton_;
    int n_ = 0;
    std::array<VecX, kStages> Z_, Zold_, Ydot_, R_, dZ_;
    VecX y_, r_, gr_, xr_, x1_, xd1_, work_, scale_;
    SparseMatrix Jx_, Jxd_, E_real_, E_floor_;
    ComplexSparse E_complex_;
    Eigen::VectorXcd xc_;
    SparseLUSolver real_lu_{true};
    ComplexKlu complex_lu_;
    bool analysed_ = false;
    double floor_ = 0.0;
    double h_old_ = 0.0;  // 0: no previous step to extrapolate from
    KeptMatrices kept_{kRadauFreshMatrixCost, KeptMatrixRule::renewal};
    double rate_ = 1.0;  // the last converged iteration's worst contraction (iterate_stages)
    long factorizations_ = 0;
};

// ∂F/∂X, ∂F/∂Ẋ at the step start, E_γ by KLU and E_μ by the complex SparseLU. False when one is
// singular. The increment scales are fixed at the first factorization (as the trapezoidal scheme
// fixes them at its first iteration matrix).
bool RadauStepper::factor(double t, double h, const VecX& xn, const VecX& xdn) {
    dae_.evaluate(t, xn, xdn, r_, &Jx_, &Jxd_);
    const int nnz = static_cast<int>(Jx_.nonZeros());
    ROTBEAM_VERIFY(Jxd_.nonZeros() == nnz, "Radau IIA: ∂F/∂X and ∂F/∂Ẋ patterns differ");
    if (!analysed_) {
        E_real_ = Jx_;
        E_floor_ = Jx_;
        E_complex_ = Jx_.cast<Complex>();
    }
    const double g = T_.gamma / h;
    const Complex m = T_.mu / h;
    // The stage rates are sums (1/h) Σ_j w_ij Z_j: their terms are bounded by ‖W‖∞/h times Z.
    const double w1 = T_.W.cwiseAbs().rowwise().sum().maxCoeff() / h;
    const double* jx = Jx_.valuePtr();
    const double* jd = Jxd_.valuePtr();
    for (int k = 0; k < nnz; ++k) {
        E_real_.valuePtr()[k] = jx[k] + g * jd[k];
        E_complex_.valuePtr()[k] = jx[k] + m * jd[k];
        E_floor_.valuePtr()[k] = std::abs(jx[k]) + w1 * std::abs(jd[k]);
    }
    if (!analysed_) {
        scale_ = dae_.increment_scale();
        raise_to_resolution(E_real_, dae_.residual_scale(), scale_);
        analysed_ = true;
    }
    floor_ = round_off_floor(E_floor_, dae_.residual_scale(), scale_, work_);
    factorizations_ += 2;
    if (!complex_lu_.factorize(E_complex_)) return false;
    return real_lu_.factorize(E_real_);
}

// The previous step's collocation polynomial (through (0, 0) and (c_j, Z_j) in units of its step)
// at the new stage times 1 + c_i h/h_old, less its end value Z_3; without one, Z_i = c_i h Ẋ_n.
void RadauStepper::predict(double h, const VecX& xdn) {
    if (h_old_ <= 0.0) {
        for (int i = 0; i < kStages; ++i) Z_[i] = (T_.c(i) * h) * xdn;
        return;
    }
    for (int i = 0; i < kStages; ++i) {
        const double tau = 1.0 + T_.c(i) * h / h_old_;
        Z_[i] = -Zold_[kStages - 1];
        for (int j = 0; j < kStages; ++j) {
            double l = tau / T_.c(j);  // the basis polynomial vanishes at the node 0 too
            for (int m = 0; m < kStages; ++m) {
                if (m != j) l *= (tau - T_.c(m)) / (T_.c(j) - T_.c(m));
            }
            Z_[i] += l * Zold_[j];
        }
    }
}

// Ẏ_i = (1/h) Σ_j w_ij Z_j on the differential unknowns, zero on the algebraic ones.
void RadauStepper::stage_rate(int i, double h, VecX& out) const {
    out = ((T_.W(i, 0) / h) * Z_[0] + (T_.W(i, 1) / h) * Z_[1] + (T_.W(i, 2) / h) * Z_[2])
              .cwiseProduct(dae_.differential());
}

// The stage residuals R_i; returns their largest scaled max norm.
double RadauStepper::stage_residuals(double t, double h, const VecX& xn) {
    double rho = 0.0;
    for (int i = 0; i < kStages; ++i) {
        stage_rate(i, h, Ydot_[i]);
        y_ = xn + Z_[i];
        dae_.evaluate(t + T_.c(i) * h, y_, Ydot_[i], R_[i], nullptr, nullptr);
        rho = std::max(rho, scaled_max_norm(R_[i], dae_.residual_scale()));
    }
    return rho;
}

// δZ = −(S ⊗ I) diag(E_γ, E_μ, conj E_μ)⁻¹ (S⁻¹ ⊗ I) R; the pair contributes 2 Re(S_i1 x_μ).
// Returns the largest scaled max norm of the stage corrections. The complex coefficients times
// real vectors are written by parts: a complex-times-complex product of std::complex is a libgcc
// call with its NaN recovery (__muldc3), 2.6 % of a mixed run's instructions.
double RadauStepper::correction() {
    const Eigen::Matrix3d& Si = T_.S_inv_real;
    gr_ = Si(0, 0) * R_[0] + Si(0, 1) * R_[1] + Si(0, 2) * R_[2];
    xc_.real() = Si(1, 0) * R_[0] + Si(1, 1) * R_[1] + Si(1, 2) * R_[2];
    xc_.imag() = Si(2, 0) * R_[0] + Si(2, 1) * R_[1] + Si(2, 2) * R_[2];
    real_lu_.solve(gr_, xr_);
    complex_lu_.solve_in_place(xc_);
    double eta = 0.0;
    for (int i = 0; i < kStages; ++i) {
        const double a = 2.0 * T_.S(i, 1).real(), b = 2.0 * T_.S(i, 1).imag();
        dZ_[i] = -T_.S(i, 0).real() * xr_ - a * xc_.real() + b * xc_.imag();
        eta = std::max(eta, scaled_max_norm(dZ_[i], scale_));
    }
    return eta;
}

// err = E_γ⁻¹ ∂F/∂Ẋ (Ẋ_n + Σ_i d_i Z_i / h) (core/dae_radau.hpp "Adaptive steps"), with the
// step's factored E_γ and its ∂F/∂Ẋ; past `allowed`, err = E_γ⁻¹ (that right side − F(t_n, X_n +
// err, Ẋ_n)).
double RadauStepper::local_error(double t, double h, const VecX& xn, const VecX& xdn,
                                 const VecX& weight, double allowed) {
    y_ = xdn;
    for (int i = 0; i < kStages; ++i) y_ += (T_.d(i) / h) * Z_[i];
    gr_.noalias() = Jxd_ * y_;
    real_lu_.solve(gr_, xr_);
    const double first = xr_.cwiseProduct(weight).lpNorm<Eigen::Infinity>();
    if (first <= allowed) return first;
    y_ = xn + xr_;
    dae_.evaluate(t, y_, xdn, r_, nullptr, nullptr);
    gr_ -= r_;
    real_lu_.solve(gr_, xr_);
    return xr_.cwiseProduct(weight).lpNorm<Eigen::Infinity>();
}

NewtonOutcome RadauStepper::step(double t, double h, const VecX& xn, const VecX& xdn) {
    const bool reuse = kept_.usable(h);
    NewtonOutcome out = iterate(t, h, xn, xdn, !reuse, reuse ? kept_.iteration_limit() : 0);
    if (out.accepted()) {
        kept_.converged(out.iterations, rate_, !reuse);
    } else if (reuse) {
        // The kept matrices no longer describe the stage equations: fresh ones, then the cut.
        const int spent = out.iterations;
        out = iterate(t, h, xn, xdn, true, 0);
        if (out.accepted()) kept_.converged(out.iterations, rate_, true);
        out.iterations += spent;
    }
    return out;
}

NewtonOutcome RadauStepper::iterate(double t, double h, const VecX& xn, const VecX& xdn, bool fresh,
                                    int budget) {
    NewtonOutcome out;
    try {
        if (fresh) {
            kept_.made(0.0);
            if (!factor(t, h, xn, xdn)) {
                out.singular = true;
                out.failure = "a stage iteration matrix is singular";
                return out;
            }
            kept_.made(h);
        }
        predict(h, xdn);
        struct Stages {
            RadauStepper& r;
            double t, h;
            const VecX& xn;
            double residual() { return r.stage_residuals(t, h, xn); }
            double correction() { return r.correction(); }
            void apply_correction() {
                for (int i = 0; i < kStages; ++i) r.Z_[i] += r.dZ_[i];
            }
            void converged(double rate) {
                r.rate_ = rate;
                r.x1_ = xn + r.Z_[kStages - 1];  // stiffly accurate: the last stage
                r.stage_rate(kStages - 1, h, r.xd1_);
            }
        } stages{*this, t, h, xn};
        out = iterate_stages(stages, newton_, floor_, budget);
    } catch (const SingularityError& e) {
        out.singular = true;
        out.failure = e.what();
    }
    return out;
}

// The run: state, stepper and bookkeeping, with the interface run_fixed_steps drives.
class RadauRun : public DaeRun {
  public:
    RadauRun(DaeSystem& dae, VecX& x, VecX& xdot, const DaeSettings& s, DaeOutcome& outcome)
        : DaeRun(dae, x, xdot, s, outcome, "Radau IIA stage iteration", "stage-iteration"),
          stepper_(dae, s.newton),
          weight_(dae.configuration().cwiseQuotient(dae.state_scale())) {}

    bool try_step(double t_next, double h) {
        try {
            return attempted(stepper_.step(time(), h, x_, xdot_));
        } catch (const TimeLimitReached& e) {
            rethrow_with_context(e, "in the step to time", t_next);
        }
    }
    double local_error(double h) {
        return stepper_.local_error(time(), h, x_, xdot_, weight_,
                                    s_.time_tolerance * h / (s_.end_time - s_.start_time));
    }
    void accept(double t_next, double h) {
        stepper_.remember(h);
        x_ = stepper_.state();
        xdot_ = stepper_.rate();
        accepted(t_next, h);
    }
    void finish() {
        outcome_.factorizations = stepper_.factorizations();
        std::ostringstream m;
        if (s_.time_tolerance > 0.0) {
            m.precision(3);
            m << "adaptive Radau IIA (3 stages), " << outcome_.steps << " steps, tolerance "
              << s_.time_tolerance << ", steps " << outcome_.control.smallest_step << " … "
              << outcome_.control.largest_step << ", " << outcome_.control.rejected_steps
              << " rejected, ";
        } else {
            m << "fixed-step Radau IIA (3 stages), "
              << std::lround((s_.end_time - s_.start_time) / s_.time_step) << " steps, ";
        }
        m << outcome_.newton_iterations << " stage iterations";
        DaeRun::finish(m.str(), "steps");
    }

  private:
    RadauStepper stepper_;
    VecX weight_;  // the configuration unknowns over their state scales; 0 on the others
};

}  // namespace

DaeOutcome integrate_radau_iia(DaeSystem& dae, VecX& x, VecX& xdot, const DaeSettings& s,
                               const DaeOutput& output) {
    DaeOutcome outcome;
    NewtonOutcome ic;
    if (!start_dae_run(dae, x, xdot, s, output, outcome, ic)) return outcome;
    RadauRun run(dae, x, xdot, s, outcome);
    run.add_initial(ic);
    run.start(s.start_time);
    if (s.time_tolerance > 0.0) {
        // The embedded estimate is O(h^4) (order 3): the local error exponent q = 4.
        RadauStepControl control{s.time_tolerance, s.end_time - s.start_time, 4};
        if (!run_adaptive_steps(run, s, control, s.time_step, output, outcome)) return outcome;
    } else if (!run_fixed_steps(run, s, output)) {
        return outcome;
    }
    run.finish();
    return outcome;
}

}  // namespace rotbeam
