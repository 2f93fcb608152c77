#include "core/static_stability_kinetic.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace rotbeam {

namespace {

// The relative error of s beyond which its growth rate is not decided: the refined eigenvalues
// of the stiff beam models carry 2e-10 … 4e-10 |s| (the round-off of the matrices' entries,
// core/quadratic_eigenpair.hpp); a thousand times that is an eigenvalue ill-conditioned by a
// neighbour it is meeting (Beck's column: flutter is that meeting).
constexpr double kKineticResolution = 1e-6;

}  // namespace

StaticStability assess_kinetic_stability(const KineticSpectrum& spectrum) {
    StaticStability out;
    if (!spectrum.unavailable.empty()) {
        out.reason = spectrum.unavailable;
        return out;
    }
    if (spectrum.eigenvalues.empty()) {
        out.reason = "no eigenvalue of the linearized motion computed";
        return out;
    }
    KineticSummary k;
    int defective = 0;
    int at_zero = 0;
    // Complex s off the axis by more than their error, right and left of it: the solver keeps
    // a + ib and −a + ib (Im s > 0) of each flutter quadruple, so each count alone is the number
    // of fluttering modes; the larger is taken in case one member fell outside the set kept.
    int right = 0;
    int left = 0;
    for (const KineticEigenvalue& e : spectrum.eigenvalues) {
        if (!e.accepted) {
            out.reason = "an eigenvalue of the linearized motion failed its check (" + e.failure +
                         "): no kinetic verdict";
            return out;
        }
        ++k.modes;
        k.highest_frequency_hz = std::max(k.highest_frequency_hz, std::abs(e.s) / (2.0 * kPi));
        const double growth = std::abs(e.s.real());
        if (std::isfinite(e.error) && growth > e.error) {
            // s and −s are eigenvalues together: a decaying s has a growing partner.
            if (std::abs(e.s.imag()) <= e.error) {
                ++k.divergent;
            } else {
                ++(e.s.real() > 0.0 ? right : left);
            }
            if (growth > k.growth_rate) {
                k.growth_rate = growth;
                k.growth_rate_error = e.error;
            }
        } else if (std::isfinite(e.error) && std::abs(e.s) <= e.error) {
            ++at_zero;
        } else if (!std::isfinite(e.error) || e.error > kKineticResolution * std::abs(e.s)) {
            // Known only to more than kKineticResolution of itself: next to another eigenvalue
            // it is meeting (the estimate grows as 1/|yᴴQ'(s)x|, infinite where two meet), so a
            // growth rate within its error could still be positive.
            ++defective;
        } else {
            k.largest_error = std::max(k.largest_error, e.error);
        }
    }
    k.fluttering = std::max(right, left);
    out.criterion = StaticStability::Criterion::kinetic;
    out.negative = k.divergent + k.fluttering;
    if (out.negative > 0) {
        out.assessment = StaticStability::Assessment::unstable;
    } else if (defective + at_zero > 0) {
        std::ostringstream s;
        if (defective > 0) {
            s << defective << " eigenvalue(s) defective or known only to more than "
              << kKineticResolution << " of |s| (two modes meeting: a growth rate is undecidable)";
        }
        if (at_zero > 0) {
            s << (defective > 0 ? "; " : "") << at_zero
              << " eigenvalue(s) within their error of s = 0 (a divergence threshold)";
        }
        out.assessment = StaticStability::Assessment::critical;
        out.reason = s.str();
    } else {
        out.assessment = StaticStability::Assessment::stable;
    }
    out.kinetic = k;
    return out;
}

}  // namespace rotbeam
