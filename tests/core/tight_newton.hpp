// The Newton settings of the tests that compare a solution with an independent one: residual and
// increment tolerances of 1e-12, so that the solve's own error is far below every tolerance
// compared against (the other settings as given, else NewtonSettings' defaults).
#pragma once

#include "core/static_driver.hpp"

namespace rotbeam::test {

inline NewtonSettings tight_newton(int max_iterations = NewtonSettings{}.max_iterations,
                                   int max_step_cuts = NewtonSettings{}.max_step_cuts) {
    NewtonSettings s;
    s.residual_tolerance = 1e-12;
    s.increment_tolerance = 1e-12;
    s.max_iterations = max_iterations;
    s.max_step_cuts = max_step_cuts;
    return s;
}

}  // namespace rotbeam::test
