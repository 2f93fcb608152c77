#pragma once
// A study's single run whose failure is a data point, not an error: a singular chart or a solve
// that does not converge becomes the run's status ("singular", "diverged") and message, which the
// study draws as a point without a value; the wall time is recorded either way. Any other
// exception (bad input, a full disk) propagates.

#include <chrono>
#include <utility>

#include "core/errors.hpp"

namespace rotbeam::cli {

template <class Run, class Body>
void run_guarded(Run& run, Body&& body) {
    const auto start = std::chrono::steady_clock::now();
    try {
        std::forward<Body>(body)();
    } catch (const SingularityError& e) {
        run.status = "singular";
        run.message = e.what();
    } catch (const SolverError& e) {
        run.status = "diverged";
        run.message = e.what();
    }
    run.wall_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace rotbeam::cli
