#include "effectivity_rows.hpp"

#include <cmath>
#include <map>

#include "estimates/estimator_failure.hpp"
#include "estimates/quantity_estimate.hpp"
#include "study_common.hpp"

namespace rotbeam::cli {

bool asymptotic_errors(RefinementKind kind, double e0, double e1, double e2, double floor,
                       double theoretical_order) {
    if (!(e0 > floor) || !std::isfinite(e1) || !std::isfinite(e2)) return false;
    if (kind == RefinementKind::p) {
        // Halving per order; a p+2 error at the floor has fallen as far as can be seen.
        return e1 < 0.5 * e0 && (e2 <= floor || e2 < 0.5 * e1);
    }
    // Order the three by mesh, coarsest first: monotone means falling from a to c, all above the
    // floor, at observed orders within the window.
    const bool coarser = kind == RefinementKind::h_coarser;
    const double a = coarser ? e2 : e0, b = e1, c = coarser ? e0 : e2;
    if (!(b < a && c < b) || c <= floor) return false;
    return std::abs(std::log2(a / b) - theoretical_order) <= estimate::kOrderWindow &&
           std::abs(std::log2(b / c) - theoretical_order) <= estimate::kOrderWindow;
}

namespace {

// The finite true errors of a quantity over a sequence: how many, smallest, largest.
struct TrueErrorSpan {
    size_t n = 0;
    double lo = 0.0, hi = 0.0;
};

TrueErrorSpan true_error_span(const std::vector<double>& true_errors) {
    TrueErrorSpan s;
    for (const double e : true_errors) {
        if (!std::isfinite(e)) continue;
        s.lo = s.n == 0 ? e : std::min(s.lo, e);
        s.hi = std::max(s.hi, e);
        ++s.n;
    }
    return s;
}

// "other state: the true error stays at 3.1e+00 … 3.1e+00 over 5 levels, …; the estimate says:
// reliable".
std::string other_state_cause(const std::vector<double>& true_errors, const nlohmann::json& q) {
    const TrueErrorSpan s = true_error_span(true_errors);
    return "other state: the true error stays at " + sci(s.lo) + " … " + sci(s.hi) + " over " +
           std::to_string(s.n) +
           " levels, the discrete solutions converge to another state than the reference "
           "(another solution of the equations, or the reference's own error), not a "
           "discretization error; the estimate says: " +
           estimate::failure_cause(q);
}

}  // namespace

bool true_error_stalls(const std::vector<double>& true_errors, double floor) {
    const TrueErrorSpan s = true_error_span(true_errors);
    return s.n >= kOtherStateLevels && s.hi > floor && s.lo > 0.5 * s.hi;
}

std::vector<EffectivityRow> effectivity_rows(const std::vector<LevelQuantities>& levels,
                                             RefinementKind kind, double theoretical_order) {
    // The true error of each quantity at each level, by name.
    std::vector<std::map<std::string, double>> true_at(levels.size());
    for (size_t k = 0; k < levels.size(); ++k) {
        for (const QuantityAtLevel& q : levels[k]) true_at[k][q.quantity] = q.true_error;
    }
    const auto true_error = [&](size_t k, const std::string& name) {
        if (k >= levels.size()) return kNoValue;
        const auto it = true_at[k].find(name);
        return it == true_at[k].end() ? kNoValue : it->second;
    };
    std::vector<EffectivityRow> rows;
    for (size_t k = 0; k < levels.size(); ++k) {
        for (const QuantityAtLevel& q : levels[k]) {
            if (!q.estimate.contains("error")) continue;
            EffectivityRow row{k, q, kNoValue, {}, false, std::nullopt};
            // The companions' levels, nearer first: after k, or before it for h_coarser.
            const auto companion_level = [&](size_t n) {
                if (kind != RefinementKind::h_coarser) return true_error(k + n, q.quantity);
                return k >= n ? true_error(k - n, q.quantity) : kNoValue;
            };
            row.next_true = {companion_level(1), companion_level(2)};
            if (q.true_error > q.floor) {
                row.effectivity = q.estimate["error"].get<double>() / q.true_error;
            }
            row.asymptotic = asymptotic_errors(kind, q.true_error, row.next_true[0],
                                               row.next_true[1], q.floor, theoretical_order);
            std::vector<double> sequence;
            for (size_t j = 0; j < levels.size(); ++j)
                sequence.push_back(true_error(j, q.quantity));
            row.other_state = true_error_stalls(sequence, q.floor);
            row.failure = row.other_state
                              ? estimate::estimator_failure(q.true_error, q.floor, q.estimate,
                                                            other_state_cause(sequence, q.estimate))
                              : estimate::estimator_failure(q.true_error, q.floor, q.estimate);
            if (!row.failure) row.other_state = false;  // a stall without a miss is no failure
            rows.push_back(std::move(row));
        }
    }
    return rows;
}

nlohmann::json to_json(const EffectivityRow& row) {
    const auto number = [](double v) { return std::isfinite(v) ? nlohmann::json(v) : nullptr; };
    nlohmann::json j = {{"level", row.level},
                        {"quantity", row.q.quantity},
                        {"estimate", row.q.estimate},
                        {"true_error", row.q.true_error},
                        {"floor", row.q.floor},
                        {"effectivity", number(row.effectivity)},
                        {"next_true_errors", {number(row.next_true[0]), number(row.next_true[1])}},
                        {"asymptotic", row.asymptotic}};
    j["failure"] = row.failure ? nlohmann::json(*row.failure) : nullptr;
    j["other_state"] = row.other_state;
    return j;
}

}  // namespace rotbeam::cli
