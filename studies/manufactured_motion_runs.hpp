// Runs of the manufactured motion (core/oracles/manufactured_motion.hpp) with every time
// integrator: the displacement formulation with the Lie-group generalized-α or Gauss–Legendre
// collocation (2 or 3 stages), the mixed one with
// the fixed-step trapezoidal scheme, the 3-stage Radau IIA method or IDA. Shared by the
// time-convergence study (study_manufactured_time.cpp) and its verification test (tests/agreement/
// test_manufactured_motion.cpp). This file holds the parameterization switch for these runs, as
// make_problem.cpp does for the case runs.
//
// Initial conditions come from the exact solution at t = 0:
//  - displacement: every node's u, R (any chart: the nodes are composed, not differenced) and
//    velocity [u̇; ω]; the integrator then solves the consistent acceleration M v˙₀ = −r
//    (run_generalized_alpha), which differs from the exact v˙ by the space error only;
//  - mixed (MixedDynamicsOf<P>: three parameters or the quaternion, whose free rod carries one
//    norm row, formulations/mixed/mixed_layout.hpp): the differential unknowns u, c (on the
//    continuous branch of the rotation vector, so a chart past π sees no jump along the rod), P, H
//    = M*[Rᵀu̇; Rᵀω] at the element mid-points and the node û, ĉ exactly; F, M and the rates (u̇, ċ =
//    H_m⁻¹Ω, Ṗ, Ḣ) exactly as the starting guess of the drivers' consistent initialization, which
//    keeps the differential unknowns and solves the rest from F(t₀, X, Ẋ) = 0.
// Errors are measured at the named points root, q1, mid, q3, tip at ten output times.
#pragma once

#include <string>
#include <vector>

#include "core/choices.hpp"
#include "core/model.hpp"
#include "core/oracles/manufactured_motion.hpp"
#include "core/static_driver.hpp"
#include "core/types.hpp"

namespace rotbeam::cli {

struct MotionRunSpec {
    Formulation formulation = Formulation::displacement;
    ParameterizationId rotation{};  // parameterizations/registry.hpp
    WmMap wm_map = WmMap::plain;    // mixed WM
    // displacement: generalized-alpha | gauss-legendre-2 | gauss-legendre-3; mixed: trapezoidal
    // | radau-iia-3 | ida (automatic: the first)
    Integrator integrator = Integrator::automatic;
    int elements = 2;  // per member (four members)
    int order = 1;     // displacement: polynomial order p
    double dt = 0.01;  // fixed step (IDA: the initial step hint)
    double end_time = 1.0;
    double rho_infinity = 0.5;  // generalized-α
    double tolerance = 1e-6;    // IDA: rtol = atol (atol times the state scales)
    // Adaptive steps with this global tolerance when > 0, dt then being the first step:
    // displacement, translations over the motion's length and rotations in rad
    // (core/step_size_control.hpp); mixed (the trapezoidal rule, Radau IIA), the configuration
    // unknowns over their state scales (core/dae_driver.hpp).
    double time_tolerance = 0.0;
    // Output times this far apart; 0: end_time / kMotionOutputs.
    double output_interval = 0.0;
    // Newton (stage iteration) tolerance on the scaled residual and increment of every step when
    // > 0; 0 keeps the drivers' defaults (displacement: the model's 1e-12, mixed: 1e-10).
    double newton_tolerance = 0.0;
    oracle::ManufacturedMotion motion;
    // The manufactured solution of the semi-discrete equations (studies/semi_discrete_forcing.hpp):
    // the run is forced by −R_h(t, y_h, ẏ_h, ÿ_h), y_h the mesh's exact trajectory (displacement:
    // the nodal interpolant of the motion; mixed: every unknown at its exact value, as the start
    // above), and started at y_h(0); MotionRunResult::semi_discrete_error is then its time error.
    bool semi_discrete = false;
    std::string label() const;  // e.g. "displacement/quaternion/p3/ga0.5", ".../p3/gl2"
};

// Per component: positions, rotations, velocity-level unknowns, internal forces, and the
// velocity-level unknowns' translational and rotational halves, each relative to its own
// magnitude (displacement: u̇ and ω at the nodes; mixed: the element momenta P and H). The halves
// tell which one sets the velocity's order where it departs from the scheme's.
struct ComponentDifferences {
    double u = 0.0, R = 0.0, velocity = 0.0, forces = 0.0;
    double translational = 0.0, rotational = 0.0;
};

// The components in table order (u, R, v, F, then v's halves) and their short names ("u", "R",
// "v", "F", "vt", "vr").
constexpr int kMotionComponents = 6;
double& component(ComponentDifferences& d, int k);
double component(const ComponentDifferences& d, int k);
const char* component_name(int k);

struct MotionRunResult {
    std::string status;  // converged | diverged | singular | unavailable
    std::string message;
    int dofs = 0;
    long steps = 0;
    long newton_iterations = 0;
    double wall_seconds = 0.0;
    // Max over the output times and points of ‖u_h − u‖/L and of the angle of R_hᵀR.
    double error_u = 0.0;
    double error_R = 0.0;
    // The output times, and the point states at them (for differences between two runs).
    std::vector<double> times;
    std::vector<Vec3> u;
    std::vector<Mat3> R;
    // Per output time: the velocity-level unknowns (displacement: every free node's [u̇; ω];
    // mixed: every element's momenta [P; H]) and, mixed only, every element's internal forces
    // [F; M] (the index-3 multipliers of a closed loop; algebraic on a free rod).
    std::vector<VecX> velocity, forces;
    // Semi-discrete runs: the error against y_h(t) per component, max over the output times (u
    // over the length and rotation angle at every node — mixed: and element —, the velocity-level
    // unknowns and the mixed internal forces relative to their largest magnitude in y_h).
    ComponentDifferences semi_discrete_error;
    bool ok() const { return has_solution(status); }
};

// Output times per run by default: end_time / 10 apart, and t = 0.
constexpr int kMotionOutputs = 10;

// The model of a run: the manufactured motion's with the spec's discretization and time scheme.
Model motion_run_model(const MotionRunSpec& spec);

MotionRunResult run_manufactured_motion(const MotionRunSpec& spec);

// The motion each combination can follow: the default (spin 1.5π → 2.45π, through 2π) for the
// displacement formulation with every parameterization but Rodrigues, and for the mixed
// quaternion (four unknowns, no chart boundary); the mixed three-parameter types cannot pass 2π
// about a varying axis (docs/reference-solutions.md §6), so theirs spins 0.5π → 1.45π; Rodrigues
// (singular at π) 0 → 2.0 rad (largest angle 2.7 rad).
oracle::ManufacturedMotion motion_within_reach(Formulation formulation,
                                               ParameterizationId rotation);

// Max over the common output times and points of ‖u_a − u_b‖/L and of the angle of R_aᵀR_b: the
// time error of `a` when `b` is the same mesh at a much smaller Δt (the space error cancels).
void run_difference(const MotionRunResult& a, const MotionRunResult& b, double length, double& du,
                    double& dR);

// The time error of `a` against `b` per component: positions (as run_difference), the
// velocity-level unknowns and the internal forces, each the max over the common output times of
// the max-norm difference over the largest magnitude of that component in `b` (0 when a run has
// none, e.g. forces of the displacement formulation).
ComponentDifferences component_differences(const MotionRunResult& a, const MotionRunResult& b,
                                           double length);

}  // namespace rotbeam::cli
