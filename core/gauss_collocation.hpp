// Gauss–Legendre collocation on a Lie group: the Runge–Kutta–Munthe-Kaas (RKMK) form of the
// s-stage Gauss method, s = 2 (order 4) and s = 3 (order 6), for the second-order problems the
// generalized-α integrator drives (core/generalized_alpha.hpp).
//
// The state is (q, v): a configuration on the group (per node R³ × SO(3); spatial composition on
// the left, q = exp(Δ) ∘ q_n) and a velocity in a vector space (spatial: Ṙ = ω̃ R). Written in the
// increment Δ of the configuration from q_n (a vector-space chart centred at the step start),
// the equations of motion are an ODE in (Δ, v):
//   Δ˙ = dexp(Δ)⁻¹ v,    r(exp(Δ) ∘ q_n, v, v˙, t) = 0  (linear in v˙, M invertible),
// with dexp(Δ) the rotation vector's spatial tangent on the rotation rows (ω = dexp(Δ) Δ˙; the
// identity on the translation rows). RKMK (Munthe-Kaas 1998, "Runge–Kutta methods on Lie groups",
// BIT 38, Theorem 1; Hairer, Lubich & Wanner, "Geometric Numerical Integration", 2nd ed., §IV.8.2)
// applies the Gauss method (Butcher tableau A, b, c) to that ODE, which keeps the classical order
// 2s of the method at the step points when dexp⁻¹ is exact, as here. With the stage rates
// K_i = Δ˙(t_n + c_i h) and the stage accelerations L_i = v˙(t_n + c_i h):
//   Δ_i = h Σ_j a_ij K_j,    v_i = v_n + h Σ_j a_ij L_j,    v_i = dexp(Δ_i) K_i,
//   r(exp(Δ_i) ∘ q_n, v_i, L_i, t_n + c_i h) = 0                              (i = 1 … s),
//   q_{n+1} = exp(h Σ_j b_j K_j) ∘ q_n,    v_{n+1} = v_n + h Σ_j b_j L_j.
// The unknowns are the stage increments Z = (Δ_1, …, Δ_s); with W = A⁻¹,
//   K_i = (1/h) Σ_j w_ij Δ_j,  v_i = dexp(Δ_i) K_i,  L_i = (1/h) Σ_j w_ij (v_j − v_n),
// and the s·n stage residuals are r_i above. Gauss is A-stable with |R(iy)| = 1: the linear
// undamped modes keep their amplitude at every step size (no numerical dissipation). RKMK is not
// symmetric on the group (its chart is centred at q_n, not at the step midpoint; GNI §IV.8.2),
// so energy conservation is not guaranteed by the construction: it is measured
// (docs/displacement-dynamics.md).
//
// Stage equations: simplified Newton (Hairer & Wanner, "Solving ODEs II", §IV.8) with the
// iteration matrix frozen for the step at the mean of the predicted stages (Δ̄, v̄, L̄, t_n + h/2):
//   J ≈ I ⊗ K₀ + (W/h) ⊗ C₀ + (W/h)² ⊗ M₀,   K₀ = ∂r/∂q dexp(Δ̄), C₀ = ∂r/∂v, M₀ = ∂r/∂v˙.
// The mean is centred in the step, so the matrix errs by O(h/2) of the motion at the outer stages
// instead of O(h) at the last one from the step start (Δ = 0, v_n, v˙_n): on the joined beam
// (Gauss 3, 1.25 ms) 13 % fewer stage iterations, 10 % fewer instructions, the stages the same
// within the Newton tolerance (docs/performance.md, "Cost of one step of the high-order schemes").
// With W = S Λ S⁻¹ (eigenvalues of A⁻¹: one conjugate pair for s = 2; one real value and one pair
// for s = 3) the system decouples into one sparse matrix per eigenvalue,
//   E(λ) = K₀ + (λ/h) C₀ + (λ/h)² M₀,
// each of the problem's pattern: the real one factored by KLU (core/sparse_lu.hpp), the complex
// one by KLU in complex arithmetic (core/complex_klu.hpp), both refactored in place with their
// pivot orders kept; the conjugate partner's solution is the complex conjugate. No dense stage
// matrix is formed. The convergence test is the project's (core/convergence.hpp) on the stacked
// stage residuals and corrections. The matrix is kept for the next step of the same size while
// the last stage iteration contracted by kKeptMatrixRate or better (core/stage_iteration.hpp), as
// Radau IIA keeps its own (core/dae_radau.hpp); an iteration with a kept matrix that fails is
// repeated with a fresh one before the step counts as failed. A kept matrix changes only the
// iterates, not the converged stages (within the Newton tolerance).
#pragma once

#include <functional>

#include "core/choices.hpp"
#include "core/generalized_alpha.hpp"

namespace rotbeam {

// A SecondOrderProblem that can also be evaluated at any stage state (configuration exp(Δ) ∘ q_n,
// velocity, acceleration, time), which the collocation needs besides the generalized-α calls.
class CollocationProblem : public SecondOrderProblem {
  public:
    // v_n and v˙_n of the step start, in the numbering of the unknowns (size()).
    virtual void start_rates(VecX& v, VecX& v_dot) const = 0;
    // Sets v˙_n of the step start (in the numbering of the unknowns).
    virtual void set_start_acceleration(const Eigen::Ref<const VecX>& v_dot) = 0;
    // Moves the iterate to q = exp(Δ) ∘ q_n with velocity v and acceleration v˙, loads at t; the
    // matrix of evaluate() is then ∂r/∂q dexp(Δ) + c_v ∂r/∂v + c_a ∂r/∂v˙. May throw
    // SingularityError (a parameterization refusing the configuration; the iterate unchanged).
    virtual void set_stage(const Eigen::Ref<const VecX>& delta, const Eigen::Ref<const VecX>& v,
                           const Eigen::Ref<const VecX>& v_dot, double t, double c_v,
                           double c_a) = 0;
    // The iteration matrix's three parts at the stage state (Δ, v, v˙, t) of set_stage: K = ∂r/∂q
    // dexp(Δ), C = ∂r/∂v and M = ∂r/∂v˙, each on evaluate()'s pattern; r the residual. This
    // default sets the stage three times, (c_v, c_a) = (0, 0), (1, 0), (0, 1), evaluates each and
    // takes C and M as differences from K; a problem that can assemble its rate terms alone
    // overrides it (the displacement dynamics: one full evaluation and the inertial terms twice).
    virtual void stage_matrices(const Eigen::Ref<const VecX>& delta,
                                const Eigen::Ref<const VecX>& v,
                                const Eigen::Ref<const VecX>& v_dot, double t, VecX& r,
                                SparseMatrix& K, SparseMatrix& C, SparseMatrix& M);
    // v = dexp(Δ) w: the velocity of the motion exp(Δ(t)) ∘ q_n when Δ˙ = w.
    virtual void velocity_of_rate(const Eigen::Ref<const VecX>& delta,
                                  const Eigen::Ref<const VecX>& w, Eigen::Ref<VecX> v) const = 0;
    // For the step doubling of adaptive steps: keep the accepted state (q_n, v_n, v˙_n) in `slot`
    // (0 or 1), return to it (as accepted state, the iterate at it), and the distance of the
    // iterate's configuration from the one kept (max over the nodes: translation / length,
    // rotation angle in rad). A problem without them cannot run with adaptive steps (SolverError).
    virtual void keep_start(int slot);
    virtual void restore_start(int slot);
    virtual double distance_from_kept(int slot, double length) const;
};

// The Gauss–Legendre tableau of `stages` (2 or 3; else InputError): nodes c, weights b, matrix A.
struct GaussLegendre {
    int stages = 0;
    Eigen::MatrixXd A;
    Eigen::VectorXd b, c;
    static GaussLegendre of(int stages);
    int order() const { return 2 * stages; }
};

// From start_time to end_time (settings.rho_infinity is not used) through the shared step loop
// of run_generalized_alpha (core/time_stepping.hpp): fixed steps, or adaptive steps when
// settings.tolerance > 0; on_output at the initial state and every output_interval; the state at
// an output has the consistent acceleration of its (q, v), for the report only: the next step
// starts from the collocation polynomial's, so the output times do not change the motion. A step
// whose stage iteration fails is first retried once with the iteration matrix refreshed at its
// stages (the matrix is otherwise frozen at the predicted stages), then cut to h/2 (settings.max_cuts);
// the energy balance stops a run whose energy grows, as for generalized-α.
//
// Adaptive steps use step doubling (Richardson): from the accepted state, one step of H and two of
// H/2; the pair is the candidate, its local error estimated as ‖q_H − q_{H/2,H/2}‖ / (2^{2s} − 1)
// (the errors C H^{2s+1} and 2 C (H/2)^{2s+1} differ by (1 − 2^{−2s}) C H^{2s+1}, of which the
// pair's is 1/(2^{2s} − 1)). Gauss–Legendre has no embedded pair of its own order: the stage
// values give the collocation polynomial, an estimate of order s + 1, which would overstate the
// error of the order-2s result by a factor ∝ h^(−s) and drive the steps far below need at tight
// tolerances. Step doubling costs one extra step of H per accepted pair (about 1.5× the stage
// iterations of the pair alone); for an undamped mode it resolves no worse than the scheme itself:
// Gauss keeps every mode's amplitude, so the difference is bounded by twice the mode's amplitude
// even for ωH ≫ 1 (the estimate saturates instead of growing as (ωH)^{2s+1}).
// The stage count of a Gauss–Legendre integrator (2 or 3), 0 for every other integrator.
constexpr int gauss_legendre_stages(Integrator integrator) {
    if (integrator == Integrator::gauss_legendre_2) return 2;
    if (integrator == Integrator::gauss_legendre_3) return 3;
    return 0;
}

DynamicOutcome run_gauss_collocation(CollocationProblem& problem, int stages,
                                     const TimeIntegrationSettings& settings,
                                     const NewtonSettings& newton,
                                     const std::function<void(const TimeStepRecord&)>& on_output);

}  // namespace rotbeam
