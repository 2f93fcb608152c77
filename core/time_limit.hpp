// A wall-clock limit on one run (`rotbeam run --time-limit SECONDS`, docs/case-format.md,
// "Limits"): the drivers check it between Newton iterations, load sub-steps and time steps
// (IDA: between outputs) and stop with TimeLimitReached, which the runner turns into the status
// `time-limit` (never a hang, never a partial number). A single linear solve, a dense modal
// eigen-solve or an IDA output interval is not interrupted.
//
// The limit belongs to the calling thread (the suite runs cases on several threads); without
// one, nothing is checked.
#pragma once

#include <stdexcept>
#include <string>

namespace rotbeam {

class TimeLimitReached : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

// Starts the limit of this thread's run: `seconds` from now; ≤ 0 removes it.
void set_time_limit(double seconds);
// Whether this thread has a limit and it has passed (cheap: one clock read when it has one).
bool past_time_limit();
// Throws TimeLimitReached "the wall-clock limit of S s was reached WHERE" if it has passed.
void check_time_limit(const char* where, double value);

// Rethrows `e` with where the run was ("..., in the step to time 0.25"): the Newton driver does
// not know the load factor or the time, its callers do.
[[noreturn]] void rethrow_with_context(const TimeLimitReached& e, const char* where, double value);

// Sets the limit for a scope and removes it at the end (also when the run throws).
class ScopedTimeLimit {
  public:
    explicit ScopedTimeLimit(double seconds) { set_time_limit(seconds); }
    ~ScopedTimeLimit() { set_time_limit(0.0); }
    ScopedTimeLimit(const ScopedTimeLimit&) = delete;
    ScopedTimeLimit& operator=(const ScopedTimeLimit&) = delete;
};

}  // namespace rotbeam
