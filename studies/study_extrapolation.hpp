// The numerical logic of the joined-beam studies (modal convergence, dynamic speed vs accuracy),
// kept free of I/O so it is unit-tested (tests/studies/test_study_extrapolation.cpp): Richardson
// extrapolation of a refinement sequence with its observed order, and the history error of a
// time response against a reference history.
#pragma once

#include <cstddef>
#include <vector>

namespace rotbeam::cli {

// Richardson extrapolation from the last three values of a sequence computed at mesh sizes
// h, h/r, h/r² (r = refinement ratio > 1): the observed order q = log(|f₁ − f₀| / |f₂ − f₁|) / log
// r and f∞ = f₂ + (f₂ − f₁)/(r^q − 1). `valid` is false when the differences do not shrink
// monotonically (same sign, |f₂ − f₁| < |f₁ − f₀|), i.e. the sequence is not asymptotic (or has
// reached round-off): then `value` is the finest f₂ and `order` NaN.
struct Richardson {
    double value = 0.0;
    double order = 0.0;
    bool valid = false;
};
Richardson richardson(double f0, double f1, double f2, double ratio);

// One scalar history sampled at common output times: time and a 3-vector per sample.
struct History {
    std::vector<double> time;
    std::vector<double> x, y, z;
    std::size_t size() const { return time.size(); }
};

// max over the samples of ‖u(t) − u_ref(t)‖ divided by max over t of ‖u_ref(t)‖ (the error measure
// of the joined-beam studies). Samples are matched by time (|Δt| ≤ 1e-9 (1 + |t|));
// a sample of `u` without a matching reference sample makes the result NaN, so histories on
// different output grids are never compared silently.
double history_error(const History& u, const History& reference);

// Pointwise Richardson extrapolation of two histories on the same output times computed with steps
// Δt and Δt/ratio by a scheme of order q: u∞ = u_fine + (u_fine − u_coarse)/(ratio^q − 1).
// API misuse (ROTBEAM_VERIFY) when the output times differ.
History extrapolate_history(const History& coarse, const History& fine, double ratio, double order);

}  // namespace rotbeam::cli
