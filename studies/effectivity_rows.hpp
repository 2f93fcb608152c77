// The effectivity of the run's error estimate (estimated / true error, docs/error-estimates.md)
// along one refinement sequence: one row per estimated quantity (a named point's displacement or
// rotation at a load step, a frequency), with its true error against an independent reference,
// whether the sequence is asymptotic there, and whether the estimate failed
// (estimates/estimator_failure.hpp). What "asymptotic" means is decided from the true errors
// alone, never from the estimator:
// - p+1 (order p on a fixed mesh): the true errors of orders p, p+1, p+2 fall by more than half at
//   each step (a p+2 error below the floor counts as fallen): then |e_p − e_{p+1}| lies within
//   [1/2, 3/2] e_p, and the p+1 estimate's effectivity must lie within [0.5, 2];
// - h/2, h/4 (elements doubled): the true errors at N, 2N, 4N fall monotonically with both observed
//   orders within kOrderWindow of the theoretical order (Richardson's factor then off by at most
//   ~20 %).
// The last two levels of a sequence have no such evidence: they are never asymptotic.
//
// A failure's cause: where the quantity's true error does not fall under refinement (over at
// least kOtherStateLevels solved levels the smallest is above half the largest, where a
// discretization error falls by 4 or more over two doublings at order 2, or two orders each
// halving it), the discrete solutions converge to a state other than the reference: another
// solution of the equations (a continuation that left the reference's equilibrium) or the
// reference's own error. That is no discretization error an estimate could see; the row says so
// (`other_state`) with the true errors it rests on. Otherwise the cause is the estimate's own
// verdict (estimates/estimator_failure.hpp).
#pragma once

#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace rotbeam::cli {

// The effectivity band where the sequence is asymptotic.
inline constexpr double kEffectivityLow = 0.5;
inline constexpr double kEffectivityHigh = 2.0;

// One quantity at one level: its estimate ({"error", "reliable", "reason"}, or {} where it has
// none: its true error still classifies the other levels' rows) and true error.
struct QuantityAtLevel {
    std::string quantity;  // "tip displacement at load factor 2", "frequency of mode 3"
    nlohmann::json estimate;
    double true_error = 0.0;
    double floor = 0.0;  // true errors at or below it are not the discretization's
};

// Every quantity of one level's result with a reference; the same quantity must carry
// the same `quantity` name at every level (the rows pair levels by it).
using LevelQuantities = std::vector<QuantityAtLevel>;

struct EffectivityRow {
    size_t level = 0;  // index in the sequence
    QuantityAtLevel q;
    double effectivity = 0.0;  // estimate / true error (NaN at or below the floor)
    // The same quantity's true error on the companions' discretizations: the next two levels (p,
    // h), or the two before, nearer first (h_coarser). JSON: next_true_errors.
    std::vector<double> next_true;
    bool asymptotic = false;
    std::optional<std::string> failure;  // estimates/estimator_failure.hpp
    bool other_state = false;            // the true error does not fall under refinement (above)
};

// Solved levels a quantity needs before its true error's stall says "another state".
inline constexpr size_t kOtherStateLevels = 3;

// Whether true errors over a sequence's levels (non-finite: the level has none) stall: at least
// kOtherStateLevels finite values, the smallest above half the largest, the largest above floor.
bool true_error_stalls(const std::vector<double>& true_errors, double floor);

// p: orders on a fixed mesh, estimated by p+1; h: doubled elements, estimated by h/2, h/4 (the
// next two levels' meshes); h_coarser: doubled elements, estimated by 2h, 4h (the two levels
// before: a row needs the true errors of the levels below it).
enum class RefinementKind { p, h, h_coarser };

// The rows of a sequence; `theoretical_order` is the h-rate (unused for p).
std::vector<EffectivityRow> effectivity_rows(const std::vector<LevelQuantities>& levels,
                                             RefinementKind kind, double theoretical_order);

// Whether the true errors e0 (the level's), e1, e2 (its companions', nearer first) are asymptotic
// (above).
bool asymptotic_errors(RefinementKind kind, double e0, double e1, double e2, double floor,
                       double theoretical_order);

nlohmann::json to_json(const EffectivityRow& row);

}  // namespace rotbeam::cli
