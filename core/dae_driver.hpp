// Time integration of an implicit DAE F(t, X, Ẋ) = 0 (core/dae_system.hpp; seed 002 Eq. 56) by
//  - the fixed-step scheme of GEBT/GXBeam (Yu & Blair 2012; seed 002 §III "a Newmark type time
//    marching scheme"): Ẋ_{n+1} = 2/Δt (X_{n+1} − X_n) − Ẋ_n, the trapezoidal rule, second order
//    and A-stable without numerical dissipation; F(t_{n+1}, X_{n+1}, Ẋ_{n+1}) = 0 is solved by the
//    shared Newton (core/static_driver's solve_newton) with the iteration matrix
//    ∂F/∂X + (2/Δt) ∂F/∂Ẋ; the algebraic unknowns' Ẋ never enters F;
//  - SUNDIALS IDA (variable-order, variable-step BDF) with the analytic iteration matrix
//    ∂F/∂X + c_j ∂F/∂Ẋ factorized by KLU, IDASetId from DaeSystem::differential(), per-component
//    absolute tolerances atol_i = absolute_tolerance × state_scale_i (IDASVtolerances), maximum
//    order `max_order` (2 by default: BDF3–5 are not A-stable, their stability regions miss a
//    part of the left half-plane next to the imaginary axis where the undamped structure's modes
//    ±iω lie; BDF2 is A-stable, at the price of damping high frequencies);
//  - the 3-stage Radau IIA method (core/dae_radau.hpp), fixed or adaptive steps, order 5 on the
//  differential
//    unknowns of an index-1 system.
// All three start from consistent initial conditions: given the differential unknowns of X, the
// algebraic unknowns of X and the differential unknowns of Ẋ are solved from F(t₀, X, Ẋ) = 0 (an
// index-1 DAE: that Jacobian is regular) — by the shared scaled Newton for every scheme, IDA
// included (core/dae_ida.cpp says why not IDACalcIC); a start that is already consistent is kept.
// IDA excludes the algebraic unknowns from its error test (IDASetSuppressAlg): they are functions
// of the differential state, and for a higher-index system (a statically indeterminate structure)
// their local error estimates do not shrink with the step.
//
// IDA callbacks are thin trampolines: SingularityError (a parameterization near its singular
// angle) or a non-finite residual returns 1 (recoverable: IDA cuts the step), any other exception
// −1; no C++ exception crosses into SUNDIALS. Failure is a status with the time and the step.
#pragma once

#include <functional>
#include <string>

#include "core/dae_system.hpp"
#include "core/static_driver.hpp"
#include "core/step_size_control.hpp"

namespace rotbeam {

inline NewtonSettings time_step_newton_settings() {
    NewtonSettings s;
    s.residual_tolerance = 1e-10;
    s.increment_tolerance = 1e-10;
    return s;
}

// The time steps' Newton settings of a run: the solver's tolerances where the case gives them,
// else the defaults above (DaeSettings::newton says why 1e-10), and its iteration limit.
inline NewtonSettings time_step_newton_settings(const SolverSettings& solver) {
    NewtonSettings s = time_step_newton_settings();
    s.residual_tolerance = solver.residual_tolerance.value_or(s.residual_tolerance);
    s.increment_tolerance = solver.increment_tolerance.value_or(s.increment_tolerance);
    s.max_iterations = solver.max_iterations;
    return s;
}

// The Newton settings of a run's steps: the mixed formulation's time steps above; the load steps,
// and the displacement formulation's time steps, the statics' (newton_settings_from).
inline NewtonSettings step_newton_settings(const Model& model) {
    if (model.analysis.kind == AnalysisKind::dynamic &&
        model.discretization.formulation == Formulation::mixed) {
        return time_step_newton_settings(model.solver);
    }
    return newton_settings_from(model.solver, model.analysis.statics);
}

struct DaeSettings {
    double start_time = 0.0;
    double end_time = 0.0;
    double time_step = 0.0;        // fixed step; IDA: the initial step hint
    double output_interval = 0.0;  // 0 = every fixed step (IDA: every time_step)
    // Fixed step and its initial conditions. 1e-10 (not the statics' 1e-12): a rate or momentum
    // unknown is resolved only as well as the forces it balances, and a stiff section's force is
    // known to ε·EA (2e-9 N on the free-vibration cantilever, EA = 2.1e7 N, against a 1 N load
    // scale): Ṗ = ΔF/h then carries 3e-8 and its scaled increment stalls near 1e-11. 1e-10 of the
    // state scale stays below the schemes' truncation errors in every test and case (the finest
    // step of the order test errs by 1e-8 m on a 1 m length scale).
    NewtonSettings newton = time_step_newton_settings();
    double relative_tolerance = 1e-6;  // IDA
    double absolute_tolerance = 1e-6;  // IDA, times state_scale_i
    int max_order = 2;                 // IDA
    long max_steps = 1000000;          // IDA, per output interval
    // Adaptive steps of the trapezoidal and Radau schemes when > 0 (core/step_size_control.hpp):
    // the tolerance on the global error of the configuration unknowns (DaeSystem::configuration)
    // over their state scales; the
    // runner gives IDA the same number as its relative and absolute tolerance.
    double time_tolerance = 0.0;
    // Fixed step: a step whose Newton fails is retried with h/2, at most this many times in a row.
    int max_cuts = kDynamicStepCuts;
};

struct DaeOutcome {
    SolveStatus status = SolveStatus::converged;
    std::string message;
    double last_time = 0.0;  // time of the state left in x, xdot
    long steps = 0;
    long newton_iterations = 0;
    long residual_evaluations = 0;
    long jacobian_evaluations = 0;
    long factorizations = 0;       // Radau IIA: the stage matrices' LU factorizations
    long error_test_failures = 0;  // IDA
    long nonlinear_failures = 0;   // IDA
    int last_order = 0;            // IDA
    StepControlRecord control;     // trapezoidal: cuts, adaptive steps
};

// Called at the start (after the initial conditions) and at every output time.
using DaeOutput =
    std::function<void(double t, const VecX& x, const VecX& xdot, int newton_iterations)>;

// True when F(t, x, xdot) vanishes to `tolerance` in the scaled max norm.
bool already_consistent(DaeSystem& dae, double t, const VecX& x, const VecX& xdot,
                        double tolerance);

// Consistent initial conditions at t (a start that is already consistent is kept as it is: a
// statically indeterminate structure makes the mixed DAE index 3, docs/mixed-dynamics.md, and the
// index-1 initial-condition system is then singular): keeps the differential unknowns of x, solves
// the algebraic unknowns of x and the differential unknowns of xdot (the algebraic entries of xdot
// are zeroed). `rate_time` scales the rates' Newton increments (state scale / rate_time; the time
// step).
NewtonOutcome consistent_initial_conditions(DaeSystem& dae, double t, VecX& x, VecX& xdot,
                                            const NewtonSettings& settings, double rate_time);

// An increment δx_j is resolvable only to the residual's accuracy: it changes row i by J_ij δx_j,
// so below min_i rscale_i / |J_ij| (times the tolerance) it is invisible in every scaled residual
// row. Raises scale_j to that resolution where the unknown's own scale is finer (an
// angular-momentum rate whose effect h Ḣ on a moment row is tiny against the moment scale; a
// stiff section's force), so the increment test asks for what round-off allows.
void raise_to_resolution(const SparseMatrix& J, const VecX& rscale, VecX& scale);

DaeOutcome integrate_trapezoidal(DaeSystem& dae, VecX& x, VecX& xdot, const DaeSettings& s,
                                 const DaeOutput& output);

DaeOutcome integrate_ida(DaeSystem& dae, VecX& x, VecX& xdot, const DaeSettings& s,
                         const DaeOutput& output);

// The 3-stage Radau IIA method, fixed or adaptive (s.time_tolerance > 0) steps with the step cut
// (core/dae_radau.hpp).
DaeOutcome integrate_radau_iia(DaeSystem& dae, VecX& x, VecX& xdot, const DaeSettings& s,
                               const DaeOutput& output);

}  // namespace rotbeam
