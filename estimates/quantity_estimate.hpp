// The estimate of one reported quantity's discretization error from its companions
// (docs/error-estimates.md). Two methods:
//
// - p+1 (displacement formulation): the same mesh at order p+1. Under spectral convergence
//   e_{p+1} ≪ e_p, so |q_p − q_{p+1}| = |e_p − e_{p+1}| estimates e_p = |q_p − q|. One companion
//   cannot see a p-sequence that is not yet decaying (locking on a coarse mesh, or a fine mesh at
//   low p where e_{p+1} ≈ e_p): below kSpectralOrder (companions.hpp) a p+2 companion checks the
//   decay of the successive differences; at and above it the estimate says that it rests on the
//   assumption.
// - h/2, h/4 (mixed formulation): the mesh with every member's elements doubled and quadrupled.
//   With q_h − q ≈ C h^r, e₁ = |q_h − q_{h/2}| and e₂ = |q_{h/2} − q_{h/4}| give the observed order
//   r = log₂(e₁/e₂) and Richardson's estimate e_h = e₁ / (1 − 2^−r). It is `reliable` only when the
//   sequence is monotone (e₂ < e₁) and r lies within kOrderWindow of the theoretical order;
//   otherwise the estimate is still given (with the theoretical order) and says why it is not.
// - 2h, 4h (mixed formulation, coarser companions): the elements halved and quartered. With
//   e₁ = |q_h − q_{2h}| ≈ C h^r (2^r − 1) and e₂ = |q_{2h} − q_{4h}| = 2^r e₁, r = log₂(e₂/e₁) and
//   e_h = e₁ / (2^r − 1); monotone means e₂ > e₁. Both are e₁ / |1 − k^−r| with k the run's mesh
//   width over the first companion's (2 for h/2, 1/2 for 2h), r = log_k(e₁/e₂).
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>

namespace rotbeam::estimate {

// Observed orders further than this from the theoretical one are not asymptotic. Within the
// window the Richardson factor 1/(1 − 2^−r) for a theoretical order 2 lies between 1.55 (r = 1.5)
// and 1.22 (r = 2.5) against 1.33: a sequence whose order is off by more has not settled, and
// its extrapolation is not to be trusted.
inline constexpr double kOrderWindow = 0.5;

// The p-sequence decays when the successive differences do: d₂ = |q_{p+1} − q_{p+2}| below this
// fraction of d₁ = |q_p − q_{p+1}|. Under a geometric decay e_{k+1} = r e_k with r ≤ 1/2 the
// sum of the remaining differences puts e_p between d₁/(1 + r) (alternating signs) and
// d₁/(1 − r) (same sign): the effectivity d₁/e_p lies within [1 − r, 1 + r] ⊂ [0.5, 1.5].
inline constexpr double kDecayRatio = 0.5;

struct QuantityEstimate {
    double error = 0.0;                    // the estimated |q − q_exact|
    bool reliable = true;                  // false: the value is indicative only (`reason`)
    std::optional<double> observed_order;  // h/2, h/4 only (absent when undefined)
    std::string reason;                    // why it is not reliable, or what it assumes
};

// |q_p − q_{p+1}|: `difference`, resting on spectral convergence (not checked).
QuantityEstimate p_refinement(double difference);

// p+1 with the decay checked by a p+2 companion, from d₁ = |q_p − q_{p+1}|, d₂ = |q_{p+1} −
// q_{p+2}| and d₀₂ = |q_p − q_{p+2}|. d₂ < kDecayRatio d₁: d₁, reliable. Otherwise the sequence
// has not entered its spectral regime (order p+1 no better than p): max(d₁, d₀₂), not reliable
// (d₀₂ estimates e_p if order p+2 is well ahead, which nothing here checks; the larger of the
// two keeps the value on the safe side). Both at or below `floor`: round-off, max(d₁, d₂),
// reliable.
QuantityEstimate p_refinement(double d1, double d2, double d02, double floor);

// The mesh sequence of an h-estimate: the companions' widths h/2, h/4 (finer) or 2h, 4h.
enum class HSequence { finer, coarser };

// From e₁ = |q_h − q_{h/2}|, e₂ = |q_{h/2} − q_{h/4}| (finer), or e₁ = |q_h − q_{2h}|, e₂ = |q_{2h}
// − q_{4h}| (coarser). Both at or below `floor` (round-off of the solves): the quantity does not
// change under refinement (a clamped point, a value fixed by symmetry); the estimate is max(e₁,
// e₂), reliable.
QuantityEstimate h_refinement(double e1, double e2, double theoretical_order, double floor,
                              HSequence sequence = HSequence::finer);

// {"error", "reliable", "observed_order" (when defined), "reason" (when not empty)}.
nlohmann::json to_json(const QuantityEstimate& e);

}  // namespace rotbeam::estimate
