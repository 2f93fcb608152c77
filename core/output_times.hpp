#pragma once

#include <algorithm>

namespace rotbeam {

// The output times of a time integration, start + k·every for k = 1, 2, …: each computed from k,
// never accumulated. A running sum drifts by up to an ulp per addition; over 15 000 outputs of
// 2 ms it passed grid times by more than the 1e-9 Δt within which an output is due, so a run
// skipped outputs and its Δt/2 companion (the time estimate) wrote others than the run.
class OutputTimes {
  public:
    OutputTimes(double start, double every) : start_(start), every_(every) {}

    // The next output time.
    double next() const { return start_ + static_cast<double>(k_) * every_; }

    // Whether the step that ended at t reaches the next output time (within `tolerance`); if so,
    // the schedule moves past t.
    bool due(double t, double tolerance) {
        if (t < next() - tolerance) return false;
        while (next() <= t + tolerance) ++k_;
        return true;
    }

    // Moves to the output time after the next (the adaptive loops land on each one).
    void advance() { ++k_; }

  private:
    double start_, every_;
    long k_ = 1;
};

}  // namespace rotbeam
