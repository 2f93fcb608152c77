// The temporal orders of every time scheme on the manufactured solution of the semi-discrete
// equations (MotionRunSpec::semi_discrete; studies/semi_discrete_forcing.hpp): per scheme the
// steps, the Newton tolerance and the theoretical order, and a series of runs with its observed
// orders per component. Shared by the time study (study_manufactured_time.cpp) and its test
// (tests/agreement/test_semi_discrete_motion.cpp): the one place where the steps are chosen.
#pragma once

#include <vector>

#include "manufactured_motion_runs.hpp"

namespace rotbeam::cli {

struct SemiDiscreteSeries {
    std::vector<double> steps;  // Δt, halving
    double newton_tolerance = 1e-12;
    int order = 0;  // the scheme's classical order (every component: index-1 DAE for the mixed)
};

// For spec's formulation and integrator (the displacement mesh p = 3, 2 elements per member; the
// mixed one 8 per member), the window where the order is observed (docs/studies.md "Manufactured
// motion, semi-discrete"): generalized-α Δt = 0.025 … 0.00625; Gauss–Legendre 2 0.05 … 0.0125;
// Gauss–Legendre 3 0.1 … 0.0125 with a Newton tolerance of 1e-14 (at 1e-12 the stage tolerance
// leaves a floor of ~2e-10 in u over 80 steps, which its error reaches at Δt = 0.0125);
// trapezoidal and Radau IIA 0.05 … 0.0125 (Radau with Rodrigues 0.025 … 0.00625, Newton 1e-14).
SemiDiscreteSeries semi_discrete_series(const MotionRunSpec& spec);

struct SemiDiscreteResult {
    std::vector<double> dt;                   // the steps that ran
    std::vector<ComponentDifferences> error;  // against y_h, per step
    ComponentDifferences order;               // least squares over the steps
    std::vector<ComponentDifferences> pair;   // log2 of each pair's ratio
    std::string note;                         // a run that failed: its step, status, message
    long steps = 0;                           // time steps over the series
};

// spec (its motion: motion_within_reach) with semi_discrete set, at every step of
// semi_discrete_series(spec).
SemiDiscreteResult run_semi_discrete_series(MotionRunSpec spec);

}  // namespace rotbeam::cli
