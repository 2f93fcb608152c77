#include "estimates/quantity_estimate.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace rotbeam::estimate {

namespace {

// Richardson's factor: e_h = e₁ / (1 − 2^−r).
double richardson(double e1, double order) { return e1 / (1.0 - std::exp2(-order)); }

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

QuantityEstimate h_refinement(double e1, double e2, double theoretical_order, double floor) {
    QuantityEstimate e;
    if (at_round_off(e1, e2, floor, e)) return e;
    std::ostringstream why;
    why.precision(3);
    if (e2 <= floor) {
        // The h/2 and h/4 values agree to round-off and the h value does not: the companions have
        // converged, so the run's error is its difference from them, e₁, measured rather than
        // extrapolated (no order is needed, none is defined). A linear problem whose nodal values
        // the mixed formulation reproduces at h/2 already does this.
        e.error = e1;
        e.reason = "the h/2 and h/4 companions agree to round-off: the run's difference from them";
        return e;
    }
    if (!(e2 < e1)) {
        // e₂ ≥ e₁: not converging monotonically.
        e.error = richardson(e1, theoretical_order);
        e.reliable = false;
        e.observed_order = std::log2(e1 / e2);
        why << "not monotone: |q_h/2 - q_h/4| = " << e2 << " >= |q_h - q_h/2| = " << e1;
        e.reason = why.str();
        return e;
    }
    const double r = std::log2(e1 / e2);
    e.observed_order = r;
    if (std::abs(r - theoretical_order) <= kOrderWindow) {
        e.error = richardson(e1, r);
        return e;
    }
    e.error = richardson(e1, theoretical_order);
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
