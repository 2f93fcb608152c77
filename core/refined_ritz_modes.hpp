// The modes a modal analysis about a state reports from the shift-invert Arnoldi's Ritz pairs
// (core/shift_invert_arnoldi.hpp), each refined and checked on the problem the pencil stands for,
//   Q(s) x = (s² M + s G + K) x = 0   (core/quadratic_eigenpair.hpp),
// whose growth rates the flutter/divergence verdict reads against their own error estimates
// (runs/modal_checks.cpp). Two users:
// - the displacement formulation's modes about a spinning state, M ẍ + G ẋ + K x = 0 in
//   first-order form (formulations/displacement/gyroscopic_modal.hpp; x the first n entries of a
//   Ritz vector of the 2n × 2n pencil);
// - the mixed formulation's modes about a spinning state, the linearized DAE A x + B ẋ = 0
//   (formulations/mixed/mixed_modal.hpp): the linear pencil A + sB is the quadratic one with
//   M = 0, G = B, K = A (x the whole Ritz vector).
//
// Kept, from the Ritz values s = σ − 1/θ (the infinite ones dropped): one of each conjugate pair
// of oscillatory eigenvalues (Im s > 0), and the growing member of each real eigenvalue (s > 0,
// f = 0: divergence; a real s is one with |Im s| ≤ kRealEigenvalueTolerance |s|). A real s < 0
// (a decaying, non-oscillatory motion) is dropped. The `count` lowest in Im s (divergences first)
// are refined, then ordered by their refined Im s.
#pragma once

#include <complex>
#include <string>
#include <vector>

#include "core/eigenpair_check.hpp"
#include "core/quadratic_eigenpair.hpp"
#include "core/shift_invert_arnoldi.hpp"
#include "core/types.hpp"

namespace rotbeam {

struct RefinedRitzMode {
    std::complex<double> s;          // refined: Im s > 0, or a real s > 0 (divergence)
    std::complex<double> arnoldi_s;  // the Arnoldi iteration's, before refinement
    VecXc x;                         // refined right eigenvector of Q, unit 2-norm
    EigenpairCheck check;            // on Q (core/quadratic_eigenpair.hpp)
    double error = 0.0;              // first-order error estimate of s, absolute
    int refinement_steps = 0;
};

// The `count` kept modes (header comment) of `ritz` (shift σ), each refined on `pencil` from the
// first pencil.K.rows() entries of its Ritz vector. Throws SolverError naming `what` (the
// analysis, e.g. "about the rotating state") when fewer than `count` are kept.
std::vector<RefinedRitzMode> refined_ritz_modes(const ShiftInvertRitz& ritz, double shift,
                                                const QuadraticPencil& pencil, int count,
                                                const std::string& what);

}  // namespace rotbeam
