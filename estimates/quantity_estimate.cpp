#include "estimates/quantity_estimate.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace rotbeam::estimate {

namespace {

// Richardson's extrapolation from e₁ = |q_h − q_{h/k}| at order r: e_h = e₁ / |1 − k^−r|, with
// k = 2 (the h/2 companion: e₁ / (1 − 2^−r)) or k = 1/2 (the 2h companion: e₁ / (2^r − 1)).
double richardson(double e1, double order, HSequence sequence) {
    const double k_to_minus_r = sequence == HSequence::finer ? std::exp2(-order) : std::exp2(order);
    return e1 / std::abs(1.0 - k_to_minus_r);
}

// The companions' names in the reasons, nearer the run first.
struct Widths {
    const char* near;
    const char* far;
};
Widths widths(HSequence sequence) {
    return sequence == HSequence::finer ? Widths{"h/2", "h/4"} : Widths{"2h", "4h"};
}

// Both successive differences at or below the round-off floor: the value is unchanged under
// refinement, and the estimate is the larger difference (reliable).
bool at_round_off(double a, double b, double floor, QuantityEstimate& e) {
    if (a > floor || b > floor) return false;
    e.error = std::max(a, b);
    e.reason = "unchanged under refinement to within the round-off floor";
    return true;
}

}  // namespace

QuantityEstimate p_refinement(double difference) {
    return {difference, true, std::nullopt,
            "assumes spectral convergence (e_{p+1} much smaller than e_p), not checked by one "
            "companion"};
}

QuantityEstimate p_refinement(double d1, double d2, double d02, double floor) {
    QuantityEstimate e;
    if (at_round_off(d1, d2, floor, e)) return e;
    if (d2 < kDecayRatio * d1) {
        e.error = d1;
        return e;
    }
    e.error = std::max(d1, d02);
    e.reliable = false;
    std::ostringstream why;
    why.precision(3);
    why << "no p-decay: |q_p+1 - q_p+2| / |q_p - q_p+1| = " << d2 / d1 << ", not below "
        << kDecayRatio << " (value: the larger of the p+1 and p+2 differences)";
    e.reason = why.str();
    return e;
}

QuantityEstimate h_refinement(double e1, double e2, double theoretical_order, double floor,
                              HSequence sequence) {
    QuantityEstimate e;
    if (at_round_off(e1, e2, floor, e)) return e;
    const Widths w = widths(sequence);
    std::ostringstream why;
    why.precision(3);
    // The two finest of the three values (h/2 and h/4, or the run and 2h) agree to round-off and
    // the third does not: the finest have converged, and the run's error is e₁, measured rather
    // than extrapolated (no order is needed, none is defined). A linear problem whose nodal values
    // the mixed formulation reproduces at h/2 (or already at 2h) does this.
    const bool finest_agree = sequence == HSequence::finer ? e2 <= floor : e1 <= floor;
    if (finest_agree) {
        e.error = e1;
        e.reason = sequence == HSequence::finer
                       ? "the h/2 and h/4 companions agree to round-off: the run's difference from "
                         "them"
                       : "the run and its 2h companion agree to round-off: their difference";
        return e;
    }
    // The width halves from the coarsest to the finest value, so a converging sequence has the
    // larger difference on the coarse side: e₁ > e₂ for h/2, h/4, e₂ > e₁ for 2h, 4h.
    const double coarse_side = sequence == HSequence::finer ? e1 : e2;
    const double fine_side = sequence == HSequence::finer ? e2 : e1;
    if (!(fine_side < coarse_side)) {
        e.error = richardson(e1, theoretical_order, sequence);
        e.reliable = false;
        e.observed_order = std::log2(coarse_side / fine_side);
        why << "not monotone: |q_" << w.near << " - q_" << w.far << "| = " << e2 << ", |q_h - q_"
            << w.near << "| = " << e1;
        e.reason = why.str();
        return e;
    }
    const double r = std::log2(coarse_side / fine_side);
    e.observed_order = r;
    if (std::abs(r - theoretical_order) <= kOrderWindow) {
        e.error = richardson(e1, r, sequence);
        return e;
    }
    e.error = richardson(e1, theoretical_order, sequence);
    e.reliable = false;
    why << "observed order " << r << " outside " << theoretical_order << " +- " << kOrderWindow
        << ": not in the asymptotic range (extrapolated with the theoretical order)";
    e.reason = why.str();
    return e;
}

nlohmann::json to_json(const QuantityEstimate& e) {
    nlohmann::json j = {{"error", e.error}, {"reliable", e.reliable}};
    if (e.observed_order) j["observed_order"] = *e.observed_order;
    if (!e.reason.empty()) j["reason"] = e.reason;
    return j;
}

}  // namespace rotbeam::estimate
