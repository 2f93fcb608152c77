// The shared static driver: load stepping with automatic step cutting around a damped Newton
// method whose update is a retraction x ⊕ δ (rotations are composed, not added). Damping uses
// Deuflhard's natural monotonicity test (affine invariant; see damped_step in the .cpp). Used by
// both formulations (through StaticSystem only: residual, Jacobian, retraction, scales, load
// factor).
//
// Convergence: the criteria of core/convergence.hpp (the scaled residual within
// residual_tolerance and a scaled Newton correction within increment_tolerance, or a residual
// stalled at its round-off floor; docs/solver-convergence.md). A step whose Newton fails (max
// iterations, a non-finite residual, a singular factorization or a parameterization refusing the
// state) is halved, starting again from the last converged state; two converged sub-steps in a row
// double it again (never beyond the initial sub-step). `max_step_cuts` bounds the consecutive
// halvings: the step fails when the sub-step would fall below (initial sub-step) / 2^max_step_cuts.
#pragma once

#include <cstddef>
#include <functional>
#include <iosfwd>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "core/convergence.hpp"
#include "core/model.hpp"
#include "core/nonlinear_system.hpp"
#include "core/sparse_lu.hpp"
#include "core/static_stability.hpp"

namespace rotbeam {

// converged: every reported step met the tolerances. stalled_at_round_off: every reported step
// was accepted, at least one with a residual at its round-off floor above residual_tolerance
// (the message gives the floor reached and the floor expected). Both leave a solution whose
// algebraic error is bounded (docs/solver-convergence.md); the others stop the run.
enum class SolveStatus { converged, stalled_at_round_off, diverged, singular, error };
const char* to_string(SolveStatus s);
std::ostream& operator<<(std::ostream& os, SolveStatus s);
// True for the statuses whose reported steps are solutions (converged, stalled-at-round-off);
// the string form reads a result file's `status`.
bool has_solution(SolveStatus s);
bool has_solution(const std::string& status);

struct NewtonSettings {
    double residual_tolerance = 1e-12;
    double increment_tolerance = 1e-12;
    int max_iterations = 50;
    bool line_search = true;
    int max_step_cuts = 12;
    int substeps = 1;
    // solver.linear_solver: sparse (Eigen SparseLU, default) or dense (core/sparse_lu.hpp).
    bool dense_linear_solver = false;
    std::ostream* trace = nullptr;  // when set: one line per Newton iteration and step cut
    // After each reported step, the inertia of the tangent at it (core/static_stability.hpp),
    // into StepRecord::stability; for systems whose tangent is symmetric at a dead load.
    bool assess_stability = false;
    // Stage iterations (core/stage_iteration.hpp) also accept an iterate whose measured
    // contraction bounds its error by the increment tolerance. That error is within the tolerance
    // but need not change sign from step to step, so over N steps it can add up to N τ instead of
    // walking as √N τ. Runs that measure long-time behaviour (the energy over 1000 periods) set
    // this false and solve each step to the residual-and-correction criterion: on the free
    // vibration over 120 000 steps at τ = 1e-14 the energy's window drift was 8.0e-9 (Gauss 2)
    // and 1.1e-8 (Gauss 3) with it, 2.0e-11 and 9.9e-12 without (docs/studies.md).
    bool contraction_stop = true;
};

struct NewtonOutcome;
// The nonlinear solver run_static calls at each load (sub-)step: solve_newton by default; the
// runner substitutes KINSOL for additive systems (solver.driver: kinsol).
using StepSolver = std::function<NewtonOutcome(NonlinearSystem&, const NewtonSettings&)>;

NewtonSettings newton_settings_from(const SolverSettings& solver, const StaticSettings& statics);

struct NewtonOutcome {
    bool converged = false;  // the tolerances were met (exact, residual-and-correction)
    // What accepted the state; none when the solve failed (or, with `converged`, when no solve
    // was needed: a consistent initial state kept as given).
    Convergence criterion = Convergence::none;
    int iterations = 0;
    double scaled_residual = 0.0;  // at the accepted state (before its final correction)
    // Bound on the scaled max norm of the accepted state's algebraic error (the Newton increment
    // that decided, docs/solver-convergence.md); +∞ when not accepted.
    double error_bound = std::numeric_limits<double>::infinity();
    double round_off_floor = 0.0;  // expected residual floor at the last factorized state
    std::string failure;           // why it failed
    bool singular = false;
    // Converged, or stalled at round-off: the state is a solution to the stated bound.
    bool accepted() const { return converged || criterion == Convergence::stalled_at_round_off; }
};

// One Newton solve at the current load: the in-house damped Newton along the retraction.
NewtonOutcome solve_newton(NonlinearSystem& system, const NewtonSettings& settings);

// Buffers of solve_newton kept between calls on the same system (a time integration solves one
// Newton per step): vectors, the Jacobian, the LU and its symbolic analysis are set up once.
// refactor_in_place: KLU refactoring into the same memory (core/sparse_lu.hpp) instead of Eigen's
// SparseLU, so that repeated solves allocate nothing.
struct NewtonWorkspace {
    explicit NewtonWorkspace(bool refactor_in_place = false);
    explicit NewtonWorkspace(SparseLUSolver::Kind kind);
    ~NewtonWorkspace();
    // Symbolic analyses made by this workspace's factorizations (Newton and damping test): one
    // per solver and pattern however many iterations and solves share the workspace.
    int symbolic_analyses() const;
    struct Impl;
    std::unique_ptr<Impl> impl;
};
NewtonOutcome solve_newton(NonlinearSystem& system, const NewtonSettings& settings,
                           NewtonWorkspace& workspace);

// The stalled solves of a run (criterion stalled_at_round_off), for its status and message.
struct StallSummary {
    int count = 0;
    double worst_residual = 0.0;  // largest scaled residual of a stalled solve
    double floor = 0.0;           // the expected round-off floor of that solve
    double worst_error_bound = 0.0;
    void add(const NewtonOutcome& o);
    // "N WHAT stalled at round-off: scaled residual up to X (tolerance T), expected floor Y
    // (ε‖D_r⁻¹|J|D_x‖∞); algebraic error ≤ Z (scaled)".
    std::string describe(const char* what, double tolerance) const;
};

struct StepRecord {
    double load_factor = 0.0;
    int newton_iterations = 0;  // summed over sub-steps and cut attempts that converged
    int substeps = 0;
    // The last sub-step's solve (the reported state): criterion, scaled residual, error bound
    // and expected round-off floor of NewtonOutcome.
    Convergence criterion = Convergence::none;
    double scaled_residual = 0.0;
    double error_bound = 0.0;
    double round_off_floor = 0.0;
    // Not assessed unless NewtonSettings::assess_stability (the reason then empty).
    StaticStability stability;
};

struct StaticOutcome {
    SolveStatus status = SolveStatus::converged;
    std::string message;
    std::vector<StepRecord> steps;            // reported (converged) steps
    double last_converged_load_factor = 0.0;  // the state the problem is left in
};

// An initial guess for reported step `step` (a warm start): sets the problem's state to an
// approximation of the solution at load_factors[step] and returns true, or returns false and
// leaves the state as it is.
using StepGuess = std::function<bool(std::size_t step)>;

// Follow the load factors; after each reported step converges, `on_step` is called (the problem is
// at that state). With `guess`, a step that has one is first solved by one Newton solve at its
// load factor from the guess, without sub-steps; the accepted state meets the same tolerances as
// one reached by load stepping. When that solve fails the step starts again from the last
// converged state and is stepped as without a guess (its iterations are not counted, as those of
// a cut sub-step are not).
StaticOutcome run_static(StaticSystem& problem, const std::vector<double>& load_factors,
                         const NewtonSettings& settings,
                         const std::function<void(const StepRecord&)>& on_step,
                         const StepSolver& solver = {}, const StepGuess& guess = {});

}  // namespace rotbeam
