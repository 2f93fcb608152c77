// `rotbeam bench` (static targets): for every parameterization × formulation, the
// cheapest discretization (elements, order, load sub-steps, found by a search over a small grid)
// that reaches the target accuracy, timed as median whole-process and in-process time to solution
// with the timing harness (timing.hpp), plus Newton iterations, unknowns and peak memory; the
// start-up time; a table and a JSON file (a copy under reports/history/ with --history).
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "studies/study_common.hpp"

namespace rotbeam::cli {

// One benchmark target: a static case solved to one load factor, with its accuracy measure.
struct BenchTarget {
    std::string name;       // e.g. "rollup-2.0"
    std::string case_name;  // catalog case
    double load_factor = 0.0;
    double accuracy = 0.0;               // target error
    std::string measure;                 // how the error is scaled (for the table)
    double target_seconds = 0.0;         // wall-time target (0: none)
    std::vector<std::string> overrides;  // applied to the case (and to its reference)
};

// A grid point of the discretization search.
struct GridPoint {
    int elements = 1;
    int order = 1;
    int substeps = 1;
    // Displacement formulation: the mixed-integration-point Newton without damping
    // (solver.mip = true, solver.line_search = false) instead of the case's solver settings.
    bool mip = false;
};

std::vector<BenchTarget> bench_targets();
std::vector<GridPoint> bench_grid(Formulation formulation, bool quick);

// Benchmarks one target for one combination (the search, then the timings of the winner).
nlohmann::json bench_combination(const BenchTarget& target, const Combination& c,
                                 const nlohmann::json& reference, bool quick, int repeats);

// The row of `rows` (bench_combination's, or the joined-beam bench's) with the smallest
// whole-process time among those whose status is "reached" (and, when `formulation` is given,
// whose formulation it is), the first of equal ones; nullptr when none reached.
const nlohmann::json* fastest_reaching_run(const nlohmann::json& rows,
                                           const std::string& formulation = "");

}  // namespace rotbeam::cli
