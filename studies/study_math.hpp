// The non-trivial logic of the studies, kept free of I/O so it is unit-tested
// (tests/studies/test_study_math.cpp): observed-order fits, the Pareto front of cost vs error, the
// singularity study's reach classifier (diverged / singular / wrong branch) and the round-off
// floor of a refinement sequence.
#pragma once

#include <string>
#include <vector>

namespace rotbeam::cli {

// Observed order of convergence from errors e_i at mesh sizes n_i (elements or unknowns):
// −(least-squares slope of log e against log n) over the points with a finite e > floor.
// NaN when fewer than two such points remain.
double fit_order(const std::vector<double>& n, const std::vector<double>& error,
                 double floor = 0.0);

// The asymptotic order over the last `points` usable points (same filtering as fit_order).
double tail_order(const std::vector<double>& n, const std::vector<double>& error, int points,
                  double floor = 0.0);

// Pareto front of (cost, error), both minimized: flag i is true when no other point has cost ≤ and
// error ≤ with at least one strictly smaller. Non-finite points are never on the front.
std::vector<bool> pareto_front(const std::vector<double>& cost, const std::vector<double>& error);

// One converged step of a continuation: its load factor and its error against the exact (or
// reference) answer.
struct ConvergedStep {
    double load_factor = 0.0;
    double error = 0.0;
};

struct Reach {
    double load_factor = 0.0;  // the largest load factor reached on the right branch (0: none)
    int steps_reached = 0;     // how many reported steps were right
    std::string stopped;       // completed | diverged | singular | wrong branch | error | ...
};

// Classifies a continuation: walks the converged steps in order; the first whose error exceeds
// `tolerance` (or is not finite) ends the reach. It is a "wrong branch" (converged, but on another
// equilibrium) when the error jumped there — by more than `jump_factor` over the previous step's,
// or at the first step — and "lost accuracy" when the error grew smoothly past the tolerance (a
// discretization error accumulating along the path, e.g. the precession phase of a coarse helix).
// Otherwise the reach is the last step, stopped by the run's `status` (a status with a solution,
// converged or stalled-at-round-off, with every target step reached reads "completed").
Reach classify_reach(const std::vector<ConvergedStep>& steps, const std::string& status,
                     int target_steps, double tolerance, double jump_factor = 10.0);

// Index of the smallest error of a refinement sequence, i.e. where refining stops paying (the
// round-off floor when the errors before it fell at the discretization order). −1 when empty.
int floor_index(const std::vector<double>& error);

}  // namespace rotbeam::cli
