// The Gauss–Legendre collocation with the choices of its stage iteration (GaussOptions), for the
// tests and studies that compare them; run_gauss_collocation of core/gauss_collocation.hpp runs
// with the defaults. `stage_predictor` true extrapolates the previous step's collocation polynomial
// to the new stage times (Hairer & Wanner, "Solving ODEs II", §IV.8); false (run_gauss_collocation
// of core/gauss_collocation.hpp) starts every step from the Taylor polynomial at its start, c_i h
// v_n + ½ (c_i h)² v˙_n. The extrapolation is off by default because it saved nothing where
// measured (docs/performance.md, "joined-beam-dynamic"; test_displacement_gauss): the start error
// at these steps is that of the modes with ωh ≳ 1, which no polynomial extrapolates.
#pragma once

#include "core/gauss_collocation.hpp"

namespace rotbeam {

struct GaussOptions {
    bool stage_predictor = false;
    // Kept stage matrices (core/stage_iteration.hpp, KeptMatrices); false: fresh ones at every
    // step, the reference the kept ones are tested against (test_displacement_gauss).
    bool keep_matrices = true;
};

DynamicOutcome run_gauss_collocation(CollocationProblem& problem, int stages,
                                     const TimeIntegrationSettings& settings,
                                     const NewtonSettings& newton,
                                     const std::function<void(const TimeStepRecord&)>& on_output,
                                     const GaussOptions& options);

}  // namespace rotbeam
