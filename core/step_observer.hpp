// Progress of a time integration for a benchmark that times it from inside the process (`rotbeam
// bench --targets long-run`, benches/bench_long_run.cpp: the cost per step over a long run).
// The drivers (generalized_alpha.cpp, dae_trapezoidal.cpp, dae_ida.cpp) call notify_step after
// every accepted step and its output — IDA, which steps inside IDASolve, after every output
// interval, with its cumulative counts. Normal runs install no observer: they pay one
// thread-local load and a predictable branch per step. An observer sees counts, never the state,
// so it cannot change a result.
#pragma once

namespace rotbeam {

struct StepProgress {
    double time = 0.0;               // of the state just accepted
    long steps = 0;                  // accepted steps since the start of the integration
    long newton_iterations = 0;      // since the start (IDA: its nonlinear iterations)
    long jacobian_evaluations = -1;  // since the start; −1 where the driver does not count them
};

using StepObserverFunction = void (*)(void* context, const StepProgress& progress);

struct StepObserver {
    StepObserverFunction function = nullptr;
    void* context = nullptr;
};

// Per thread: an observer installed by one thread never sees another thread's integration.
inline thread_local StepObserver current_step_observer;

inline bool step_observed() { return current_step_observer.function != nullptr; }

inline void notify_step(const StepProgress& progress) {
    const StepObserver& o = current_step_observer;
    if (o.function != nullptr) o.function(o.context, progress);
}

// Installs an observer for the scope; the previous one is restored on exit.
class ScopedStepObserver {
  public:
    ScopedStepObserver(StepObserverFunction function, void* context)
        : previous_(current_step_observer) {
        current_step_observer = {function, context};
    }
    ~ScopedStepObserver() { current_step_observer = previous_; }
    ScopedStepObserver(const ScopedStepObserver&) = delete;
    ScopedStepObserver& operator=(const ScopedStepObserver&) = delete;

  private:
    StepObserver previous_;
};

}  // namespace rotbeam
