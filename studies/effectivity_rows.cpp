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
    if (!(e1 < e0 && e2 < e1) || e2 <= floor) return false;
    return std::abs(std::log2(e0 / e1) - theoretical_order) <= estimate::kOrderWindow &&
           std::abs(std::log2(e1 / e2) - theoretical_order) <= estimate::kOrderWindow;
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
            row.next_true = {true_error(k + 1, q.quantity), true_error(k + 2, q.quantity)};
            if (q.true_error > q.floor) {
                row.effectivity = q.estimate["error"].get<double>() / q.true_error;
            }
            row.asymptotic = asymptotic_errors(kind, q.true_error, row.next_true[0],
                                               row.next_true[1], q.floor, theoretical_order);
            row.failure = estimate::estimator_failure(q.true_error, q.floor, q.estimate);
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
    return j;
}

}  // namespace rotbeam::cli
