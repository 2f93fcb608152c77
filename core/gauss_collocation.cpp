#include "core/gauss_collocation.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <sstream>

#include "core/complex_klu.hpp"
#include "core/convergence.hpp"
#include "core/errors.hpp"
#include "core/gauss_collocation_predictor.hpp"
#include "core/sparse_lu.hpp"
#include "core/stage_iteration.hpp"
#include "core/time_stepping.hpp"

namespace rotbeam {

// Hairer & Wanner, "Solving ODEs II", Table IV.5.1 (s = 2) and IV.5.2 (s = 3).
GaussLegendre GaussLegendre::of(int stages) {
    GaussLegendre g;
    g.stages = stages;
    if (stages == 2) {
        const double r = std::sqrt(3.0) / 6.0;
        g.c = Eigen::Vector2d(0.5 - r, 0.5 + r);
        g.b = Eigen::Vector2d(0.5, 0.5);
        g.A.resize(2, 2);
        g.A << 0.25, 0.25 - r, 0.25 + r, 0.25;
        return g;
    }
    if (stages == 3) {
        const double r = std::sqrt(15.0);
        g.c = Eigen::Vector3d(0.5 - r / 10.0, 0.5, 0.5 + r / 10.0);
        g.b = Eigen::Vector3d(5.0 / 18.0, 4.0 / 9.0, 5.0 / 18.0);
        g.A.resize(3, 3);
        g.A << 5.0 / 36.0, 2.0 / 9.0 - r / 15.0, 5.0 / 36.0 - r / 30.0,  //
            5.0 / 36.0 + r / 24.0, 2.0 / 9.0, 5.0 / 36.0 - r / 24.0,     //
            5.0 / 36.0 + r / 30.0, 2.0 / 9.0 + r / 15.0, 5.0 / 36.0;
        return g;
    }
    throw InputError("analysis.integrator: Gauss–Legendre collocation has 2 or 3 stages, not " +
                     std::to_string(stages));
}

namespace {

using Complex = std::complex<double>;

// Fresh stage matrices (stage_matrices, the complex and for 3 stages the real factorization)
// cost about three stage iterations on the joined beam (callgrind, docs/performance.md "Cost of
// one step of the high-order schemes": 2 stages 1.84 M against 0.48 M per iteration, 3.8;
// 3 stages 2.04 M against 0.73 M, 2.8; with the residual-only inertial terms and the rate-term
// stage matrices, "Residual-only inertial terms…", 3 stages 1.61 M against 0.56 M, 2.9). Both grow
// linearly with the elements (banded matrices), so the ratio holds for other meshes of the same
// elements. KeptMatrices' budget.
constexpr double kGaussFreshMatrixCost = 3.0;

// W = A⁻¹ = S Λ S⁻¹, with the columns of a conjugate pair conjugate to each other, so that the
// partner's transformed system is the conjugate of its representative's (imaginary part > 0).
struct StageTransform {
    Eigen::MatrixXd W;
    Eigen::MatrixXcd S, S_inv;
    Eigen::VectorXcd lambda;
    int real = -1;  // the index of the real eigenvalue (s = 3), −1 if none
    int pair = -1;  // the representative of the conjugate pair
    // The round-off floor of the stage residuals: v_i and L_i are sums Σ_j w_ij (·)/h of the
    // stage increments, so their terms are bounded by w1/h = ‖W‖∞/h and w2/h² = ‖|W|²‖∞/h² times
    // them.
    double w1 = 0.0, w2 = 0.0;
};

StageTransform transform_of(const Eigen::MatrixXd& A) {
    StageTransform t;
    t.W = A.inverse();  // the Butcher matrix (s ≤ 3), not a stage system
    const Eigen::EigenSolver<Eigen::MatrixXd> es(t.W);
    const int s = static_cast<int>(A.rows());
    t.lambda = es.eigenvalues();
    const Eigen::MatrixXcd V = es.eigenvectors();
    t.S.resize(s, s);
    for (int k = 0; k < s; ++k) {
        if (std::abs(t.lambda(k).imag()) <= 1e-12 * std::abs(t.lambda(k))) {
            t.real = k;
            t.lambda(k) = t.lambda(k).real();
            t.S.col(k) = V.col(k).real().cast<Complex>();
        } else if (t.lambda(k).imag() > 0.0) {
            t.pair = k;
        }
    }
    ROTBEAM_VERIFY(t.pair >= 0 && (s == 2 || t.real >= 0), "Gauss tableau: unexpected spectrum");
    for (int k = 0; k < s; ++k) {
        if (k == t.real) continue;
        t.S.col(k) = k == t.pair ? V.col(t.pair) : Eigen::VectorXcd(V.col(t.pair).conjugate());
        if (k != t.pair) t.lambda(k) = std::conj(t.lambda(t.pair));
    }
    t.S_inv = t.S.inverse();
    const Eigen::MatrixXd W_abs = t.W.cwiseAbs();
    t.w1 = W_abs.rowwise().sum().maxCoeff();
    t.w2 = (W_abs * W_abs).rowwise().sum().maxCoeff();
    const double defect =
        (t.S * t.lambda.asDiagonal() * t.S_inv - t.W.cast<Complex>()).cwiseAbs().maxCoeff();
    ROTBEAM_VERIFY(defect <= 1e-12 * t.W.cwiseAbs().maxCoeff(), "Gauss tableau: W ≠ S Λ S⁻¹");
    return t;
}

// One step's stage equations and their simplified Newton (the header's construction). Buffers
// are sized once; both KLUs (real and complex) keep their pivot orders and refactor in place.
class GaussStepper {
  public:
    GaussStepper(CollocationProblem& problem, int stages, const NewtonSettings& newton,
                 const GaussOptions& options);
    // From the problem's step start (q_n, v_n, v˙_n) at time t to t + h; on success the problem's
    // iterate is the step end (q_{n+1}, v_{n+1}, an extrapolated v˙_{n+1}), not yet accepted.
    NewtonOutcome step(double t, double h);
    // Steps that converged only after the iteration matrix was refreshed at their stages.
    int refreshes() const { return refreshes_; }
    // Iteration matrices made (each: three assemblies, a complex and, for s = 3, a real
    // factorization).
    long factorizations() const { return factorizations_; }
    // The problem's step start is no longer the end of the last converged step (a step rejected,
    // a state restored): the next step starts from the Taylor polynomial.
    void forget() { previous_h_ = 0.0; }

  private:
    void predict(double h);
    void extrapolate(double h);
    // The iteration matrix at the stage mean of Z_ (the predicted stages, or the best iterate) and
    // t_mid.
    bool factor(double t_mid, double h);
    bool refactor(double t, double h);
    // budget: iterate_stages' (0: none).
    NewtonOutcome iterate(double t, double h, int budget);
    void stage_mean(double h);
    void stage_rates(double h);
    double stage_residuals(double t, double h);
    double correction();
    void finish_step(double t, double h);

    CollocationProblem& problem_;
    GaussLegendre tableau_;
    StageTransform transform_;
    NewtonSettings newton_;
    Eigen::VectorXd extrapolate_;   // ℓ_j(1): the stage polynomial's value at the step end
    bool use_previous_;             // GaussOptions::stage_predictor
    std::vector<VecX> Z_previous_;  // the last converged step's stages
    double previous_h_ = 0.0;       // its step (0: none, or not the problem's step start)
    int n_ = 0;
    VecX v_n_, vd_n_, r_, work_, gr_, xr_;
    VecX delta1_, v1_, vd1_;  // the step end
    std::vector<VecX> Z_, K_, V_, L_, R_, dZ_, best_Z_;
    VecX z_mean_, v_mean_, l_mean_;
    SparseMatrix J0_, C0_, M0_, E_real_, E_floor_;
    ComplexSparse E_complex_;
    Eigen::VectorXcd gc_, xc_;
    SparseLUSolver real_lu_{true};
    ComplexKlu complex_lu_;
    bool analysed_ = false;
    double floor_ = 0.0;
    int refreshes_ = 0;
    KeptMatrices kept_;
    double rate_ = 1.0;  // the last converged iteration's worst contraction (iterate_stages)
    long factorizations_ = 0;
};

GaussStepper::GaussStepper(CollocationProblem& problem, int stages, const NewtonSettings& newton,
                           const GaussOptions& options)
    : problem_(problem),
      tableau_(GaussLegendre::of(stages)),
      transform_(transform_of(tableau_.A)),
      newton_(newton),
      use_previous_(options.stage_predictor),
      n_(problem.size()),
      kept_(options.keep_matrices ? kGaussFreshMatrixCost : 0.0, KeptMatrixRule::contraction) {
    const int s = tableau_.stages;
    extrapolate_.resize(s);
    for (int j = 0; j < s; ++j) {
        double l = 1.0;
        for (int m = 0; m < s; ++m) {
            if (m != j) l *= (1.0 - tableau_.c(m)) / (tableau_.c(j) - tableau_.c(m));
        }
        extrapolate_(j) = l;
    }
    for (auto* v :
         {&v_n_, &vd_n_, &r_, &gr_, &xr_, &delta1_, &v1_, &vd1_, &z_mean_, &v_mean_, &l_mean_}) {
        v->setZero(n_);
    }
    for (auto* v : {&Z_, &K_, &V_, &L_, &R_, &dZ_, &best_Z_, &Z_previous_}) {
        v->assign(s, VecX::Zero(n_));
    }
    gc_.setZero(n_);
    xc_.setZero(n_);
}

// The starting stages: the last converged step's collocation polynomial extrapolated when that
// step ended at this step's start and was no shorter; else Δ_i = c_i h v_n + ½ (c_i h)² v˙_n, the
// Taylor polynomial of the motion (dexp ≈ I).
void GaussStepper::predict(double h) {
    if (use_previous_ && previous_h_ > 0.0 && h <= previous_h_) {
        extrapolate(h);
        return;
    }
    for (int i = 0; i < tableau_.stages; ++i) {
        const double ch = tableau_.c(i) * h;
        Z_[i] = ch * v_n_ + (0.5 * ch * ch) * vd_n_;
    }
}

// Hairer & Wanner, "Solving ODEs II", §IV.8 (starting values): the last step's collocation
// polynomial u (degree s, u(0) = 0 at its start, u(c_j) = its stage Δ_j, in its time unit h_p)
// evaluated at this step's stage times, 1 + c_i h / h_p, and moved to this step's chart:
// Δ_i = u(1 + c_i h / h_p) − u(1). The chart change log(exp(u) exp(−u(1))) = u − u(1) − ½ u × u(1)
// + … on the rotation rows; u × u(1) vanishes to leading order (both ∝ the angular velocity), so
// the neglected term is of the order of the extrapolation error itself. Only the iterate's start
// changes: the converged stages are the same within the Newton tolerance.
void GaussStepper::extrapolate(double h) {
    const int s = tableau_.stages;
    const Eigen::VectorXd& c = tableau_.c;
    // ℓ_j(x): the Lagrange basis of the nodes {0, c_1, …, c_s} for the node c_j.
    const auto basis = [&](int j, double x) {
        double l = x / c(j);
        for (int m = 0; m < s; ++m) {
            if (m != j) l *= (x - c(m)) / (c(j) - c(m));
        }
        return l;
    };
    const double r = h / previous_h_;
    for (int i = 0; i < s; ++i) {
        Z_[i].setZero();
        for (int j = 0; j < s; ++j) {
            Z_[i] += (basis(j, 1.0 + r * c(i)) - basis(j, 1.0)) * Z_previous_[j];
        }
    }
}

// The mean over the stages of Δ_i, v_i and L_i of the iterate Z_ (with Z_ = 0 the step start:
// Δ = 0, v_n, v˙_n).
void GaussStepper::stage_mean(double h) {
    const int s = tableau_.stages;
    bool start = true;
    for (const VecX& z : Z_) start = start && z.isZero(0.0);
    if (start) {
        z_mean_.setZero();
        v_mean_ = v_n_;
        l_mean_ = vd_n_;
        return;
    }
    stage_rates(h);
    z_mean_.setZero();
    v_mean_.setZero();
    l_mean_.setZero();
    for (int i = 0; i < s; ++i) {
        z_mean_ += Z_[i] / s;
        v_mean_ += V_[i] / s;
        l_mean_ += L_[i] / s;
    }
}

// K₀, C₀, M₀ (CollocationProblem::stage_matrices) at the stage mean of Z_ (at the step start:
// Δ = 0, v_n, v˙_n),
// then E(λ) = K₀ + μ C₀ + μ² M₀, μ = λ/h, for the real eigenvalue (KLU) and the pair's
// representative (complex SparseLU). False when one is singular.
bool GaussStepper::factor(double t_mid, double h) {
    stage_mean(h);
    problem_.stage_matrices(z_mean_, v_mean_, l_mean_, t_mid, r_, J0_, C0_, M0_);
    const int nnz = static_cast<int>(J0_.nonZeros());
    ROTBEAM_VERIFY(C0_.nonZeros() == nnz && M0_.nonZeros() == nnz,
                   "Gauss collocation: the iteration matrices' patterns differ");
    if (!analysed_) {
        E_real_ = J0_;
        E_floor_ = J0_;
        E_complex_ = J0_.cast<Complex>();
        analysed_ = true;
    }
    const double* k0 = J0_.valuePtr();
    const double* c0_values = C0_.valuePtr();
    const double* m0_values = M0_.valuePtr();
    const Complex mu = transform_.lambda(transform_.pair) / h;
    const double w1 = transform_.w1 / h, w2 = transform_.w2 / (h * h);
    for (int k = 0; k < nnz; ++k) {
        const double c0 = c0_values[k], m0 = m0_values[k];
        E_complex_.valuePtr()[k] = k0[k] + mu * c0 + mu * mu * m0;
        E_floor_.valuePtr()[k] = std::abs(k0[k]) + w1 * std::abs(c0) + w2 * std::abs(m0);
        if (transform_.real >= 0) {
            const double mr = transform_.lambda(transform_.real).real() / h;
            E_real_.valuePtr()[k] = k0[k] + mr * c0 + mr * mr * m0;
        }
    }
    floor_ =
        round_off_floor(E_floor_, problem_.residual_scale(), problem_.increment_scale(), work_);
    if (!complex_lu_.factorize(E_complex_)) return false;
    return transform_.real < 0 || real_lu_.factorize(E_real_);
}

// K_i = (1/h) Σ w_ij Δ_j, v_i = dexp(Δ_i) K_i, L_i = (1/h) Σ w_ij (v_j − v_n).
void GaussStepper::stage_rates(double h) {
    const int s = tableau_.stages;
    const Eigen::MatrixXd& W = transform_.W;
    for (int i = 0; i < s; ++i) {
        K_[i].setZero();
        for (int j = 0; j < s; ++j) K_[i] += (W(i, j) / h) * Z_[j];
        problem_.velocity_of_rate(Z_[i], K_[i], V_[i]);
    }
    for (int i = 0; i < s; ++i) {
        L_[i].setZero();
        for (int j = 0; j < s; ++j) L_[i] += (W(i, j) / h) * (V_[j] - v_n_);
    }
}

// The stage residuals r_i; returns their largest scaled max norm.
double GaussStepper::stage_residuals(double t, double h) {
    stage_rates(h);
    double rho = 0.0;
    for (int i = 0; i < tableau_.stages; ++i) {
        problem_.set_stage(Z_[i], V_[i], L_[i], t + tableau_.c(i) * h, 0.0, 0.0);
        problem_.evaluate(R_[i], nullptr);
        rho = std::max(rho, scaled_max_norm(R_[i], problem_.residual_scale()));
    }
    return rho;
}

// δZ = −(S ⊗ I) diag(E(λ_k))⁻¹ (S⁻¹ ⊗ I) R; the pair contributes 2 Re(S_ik x_k). Returns the
// largest scaled max norm of the stage corrections.
double GaussStepper::correction() {
    const int s = tableau_.stages;
    const StageTransform& T = transform_;
    for (VecX& d : dZ_) d.setZero();
    if (T.real >= 0) {
        gr_.setZero();
        for (int i = 0; i < s; ++i) gr_ += T.S_inv(T.real, i).real() * R_[i];
        real_lu_.solve(gr_, xr_);
        for (int i = 0; i < s; ++i) dZ_[i] -= T.S(i, T.real).real() * xr_;
    }
    gc_.setZero();
    for (int i = 0; i < s; ++i) gc_ += T.S_inv(T.pair, i) * R_[i].cast<Complex>();
    xc_ = gc_;
    complex_lu_.solve_in_place(xc_);
    for (int i = 0; i < s; ++i) dZ_[i] -= 2.0 * (T.S(i, T.pair) * xc_).real();
    double eta = 0.0;
    for (const VecX& d : dZ_) eta = std::max(eta, scaled_max_norm(d, problem_.increment_scale()));
    return eta;
}

// q_{n+1} = exp(h Σ b_j K_j) ∘ q_n, v_{n+1} = v_n + h Σ b_j L_j, v˙_{n+1} = Σ ℓ_j(1) L_j (the
// collocation polynomial's, order s; the driver replaces it by the consistent one at outputs).
void GaussStepper::finish_step(double t, double h) {
    stage_rates(h);
    delta1_.setZero();
    v1_ = v_n_;
    vd1_.setZero();
    for (int j = 0; j < tableau_.stages; ++j) {
        delta1_ += (h * tableau_.b(j)) * K_[j];
        v1_ += (h * tableau_.b(j)) * L_[j];
        vd1_ += extrapolate_(j) * L_[j];
    }
    problem_.set_stage(delta1_, v1_, vd1_, t + h, 0.0, 0.0);
}

// The simplified Newton from the iterate Z_ with the factored matrix; Z_ ends at the last
// iterate, best_Z_ at the one of the smallest stage residual.
NewtonOutcome GaussStepper::iterate(double t, double h, int budget) {
    double best = std::numeric_limits<double>::infinity();
    for (int i = 0; i < tableau_.stages; ++i) best_Z_[i] = Z_[i];
    struct Stages {
        GaussStepper& g;
        double t, h, best;
        double residual() {
            const double r = g.stage_residuals(t, h);
            if (r < best) {
                best = r;
                for (int i = 0; i < g.tableau_.stages; ++i) g.best_Z_[i] = g.Z_[i];
            }
            return r;
        }
        double correction() { return g.correction(); }
        void apply_correction() {
            for (int i = 0; i < g.tableau_.stages; ++i) g.Z_[i] += g.dZ_[i];
        }
        void converged(double rate) {
            g.rate_ = rate;
            g.finish_step(t, h);
            for (int i = 0; i < g.tableau_.stages; ++i) g.Z_previous_[i] = g.Z_[i];
            g.previous_h_ = h;
        }
    } stages{*this, t, h, best};
    return iterate_stages(stages, newton_, floor_, budget);
}

// The stage iteration with kept matrices when they serve (KeptMatrices: within their iteration
// limit), else or then with fresh ones at the predicted stages; when that fails (not for a singular
// matrix or a refused state), once more from its best iterate with the matrix refreshed at that
// iterate's stage mean: the frozen matrix neglects dexp(Δ_i) − I and the change of K, C, M over
// the step, which grows with the rotation per step.
NewtonOutcome GaussStepper::step(double t, double h) {
    problem_.start_rates(v_n_, vd_n_);
    NewtonOutcome out;
    if (kept_.usable(h)) {
        predict(h);
        out = iterate(t, h, kept_.iteration_limit());
        if (out.accepted()) {
            kept_.converged(out.iterations, rate_, false);
            return out;
        }
    }
    const int spent = out.iterations;
    predict(h);
    if (!refactor(t, h)) {
        out.singular = true;
        out.failure = "the stage iteration matrix is singular";
        return out;
    }
    out = iterate(t, h, 0);
    if (out.accepted()) kept_.converged(out.iterations, rate_, true);
    out.iterations += spent;
    if (out.accepted() || out.singular || !std::isfinite(best_Z_[0].squaredNorm())) return out;
    for (int i = 0; i < tableau_.stages; ++i) Z_[i] = best_Z_[i];
    if (!refactor(t, h)) return out;
    NewtonOutcome again = iterate(t, h, 0);
    if (again.accepted()) {
        kept_.converged(again.iterations, rate_, true);
        ++refreshes_;
        again.iterations += out.iterations;
        return again;
    }
    out.failure += "; again with the iteration matrix refreshed at the stages: " + again.failure;
    return out;
}

// factor() at the stage mean of Z_ and t + h/2, with the bookkeeping of the kept matrix.
bool GaussStepper::refactor(double t, double h) {
    kept_.made(0.0);
    if (!factor(t + 0.5 * h, h)) return false;
    kept_.made(h);
    ++factorizations_;
    return true;
}

// The collocation step for the shared loop (core/time_stepping.hpp): one step per attempt, or
// with adaptive steps the step-doubling pair of the header (slot 0 of the problem keeps the
// accepted state, slot 1 the end of the step of H).
class GaussScheme : public StepScheme {
  public:
    GaussScheme(CollocationProblem& problem, int stages, const TimeIntegrationSettings& settings,
                const NewtonSettings& newton, const GaussOptions& options)
        : problem_(problem),
          stepper_(problem, stages, newton, options),
          doubling_(settings.tolerance > 0.0),
          length_(settings.length_scale),
          richardson_(std::ldexp(1.0, 2 * stages) - 1.0),
          order_(2 * stages + 1) {}

    NewtonOutcome attempt(double t, double /*t_next*/, double h) override {
        if (!doubling_) return stepper_.step(t, h);
        problem_.keep_start(0);
        NewtonOutcome whole = stepper_.step(t, h);
        if (!whole.accepted()) return whole;
        problem_.end_step();
        problem_.keep_start(1);
        restore();
        NewtonOutcome first = stepper_.step(t, 0.5 * h);
        if (!first.accepted()) return back(first);
        problem_.end_step();
        NewtonOutcome second = stepper_.step(t + 0.5 * h, 0.5 * h);
        if (!second.accepted()) return back(second);
        // The pair's iterations, and the weaker of its two convergence statements.
        second.iterations += first.iterations + whole.iterations;
        if (!first.converged) second = worse_of(second, first);
        return second;
    }
    int accept() override {
        problem_.end_step();
        return doubling_ ? 2 : 1;
    }
    // ‖q_H − q_{H/2,H/2}‖ / (2^{2s} − 1): the pair's local error (header).
    double local_error(double /*h*/) override {
        return problem_.distance_from_kept(1, length_) / richardson_;
    }
    void reject() override { restore(); }
    int local_error_order() const override { return order_; }
    int refreshes() const { return stepper_.refreshes(); }
    long factorizations() const { return stepper_.factorizations(); }

  private:
    // A failed half step: back to the accepted state, the failure reported.
    NewtonOutcome back(const NewtonOutcome& failed) {
        restore();
        return failed;
    }
    // Back to the accepted state, which is not the end of the stepper's last step.
    void restore() {
        problem_.restore_start(0);
        stepper_.forget();
    }
    static NewtonOutcome worse_of(NewtonOutcome a, const NewtonOutcome& b) {
        a.converged = false;
        a.criterion = b.criterion;
        a.scaled_residual = std::max(a.scaled_residual, b.scaled_residual);
        a.error_bound = std::max(a.error_bound, b.error_bound);
        a.round_off_floor = std::max(a.round_off_floor, b.round_off_floor);
        return a;
    }

    CollocationProblem& problem_;
    GaussStepper stepper_;
    bool doubling_;
    double length_;
    double richardson_;
    int order_;
};

}  // namespace

void CollocationProblem::stage_matrices(const Eigen::Ref<const VecX>& delta,
                                        const Eigen::Ref<const VecX>& v,
                                        const Eigen::Ref<const VecX>& v_dot, double t, VecX& r,
                                        SparseMatrix& K, SparseMatrix& C, SparseMatrix& M) {
    set_stage(delta, v, v_dot, t, 0.0, 0.0);
    evaluate(r, &K);
    set_stage(delta, v, v_dot, t, 1.0, 0.0);
    evaluate(r, &C);
    set_stage(delta, v, v_dot, t, 0.0, 1.0);
    evaluate(r, &M);
    ROTBEAM_VERIFY(C.nonZeros() == K.nonZeros() && M.nonZeros() == K.nonZeros(),
                   "Gauss collocation: the iteration matrices' patterns differ");
    for (Eigen::Index k = 0; k < K.nonZeros(); ++k) {
        C.valuePtr()[k] -= K.valuePtr()[k];
        M.valuePtr()[k] -= K.valuePtr()[k];
    }
}

void CollocationProblem::keep_start(int /*slot*/) {
    throw SolverError("this problem cannot keep a step start: adaptive Gauss steps not available");
}
void CollocationProblem::restore_start(int /*slot*/) {
    throw SolverError("this problem cannot keep a step start: adaptive Gauss steps not available");
}
double CollocationProblem::distance_from_kept(int /*slot*/, double /*length*/) const {
    throw SolverError("this problem cannot keep a step start: adaptive Gauss steps not available");
}

DynamicOutcome run_gauss_collocation(CollocationProblem& problem, int stages,
                                     const TimeIntegrationSettings& settings,
                                     const NewtonSettings& newton,
                                     const std::function<void(const TimeStepRecord&)>& on_output) {
    return run_gauss_collocation(problem, stages, settings, newton, on_output, GaussOptions{});
}

DynamicOutcome run_gauss_collocation(CollocationProblem& problem, int stages,
                                     const TimeIntegrationSettings& settings,
                                     const NewtonSettings& newton,
                                     const std::function<void(const TimeStepRecord&)>& on_output,
                                     const GaussOptions& options) {
    require_time_window(settings);
    const double h0 = settings.time_step;
    GaussScheme scheme(problem, stages, settings, newton, options);
    // The right limit of t_0, as run_generalized_alpha (a load released at t_0).
    constexpr double kRightLimit = 1e-6;
    problem.initialize_acceleration(settings.start_time + kRightLimit * h0);
    if (on_output) on_output({settings.start_time, 0});
    VecX kept_v(problem.size()), kept_v_dot(problem.size());
    const auto output = [&](const TimeStepRecord& record) {
        // The output state's acceleration (reactions) is the consistent one of its (q, v), not
        // the stage polynomial's order-s extrapolation; the next step starts from the latter
        // again, as it would without this output. It costs a residual and a refactorization of
        // the mass matrix (about a third of a fresh GL3 matrix on the joined beam:
        // docs/performance.md), spent only when someone reads the output.
        if (!on_output) return;
        problem.start_rates(kept_v, kept_v_dot);
        problem.initialize_acceleration(record.time);
        if (on_output) on_output(record);
        problem.set_start_acceleration(kept_v_dot);
    };
    const StepLoopLabels labels{"Gauss–Legendre " + std::to_string(stages) + " stages",
                                "stage iterations"};
    DynamicOutcome outcome = run_step_loop(scheme, problem, settings, newton, labels, output);
    outcome.control.matrix_refreshes = scheme.refreshes();
    outcome.message += "; " + std::to_string(scheme.factorizations()) + " fresh stage matrices";
    if (scheme.refreshes() > 0) {
        outcome.message += "; " + std::to_string(scheme.refreshes()) +
                           " steps converged after refreshing the stage iteration matrix";
    }
    return outcome;
}

}  // namespace rotbeam
