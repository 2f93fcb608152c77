// The beam model shared by every formulation, the continuum reference solver and the case loader.
//
// A model is plain data: named points, members between points (with a reference line, twist and
// sections), constraints, loads, the analysis and the discretization/solver options. The case
// loader (cases/loader) builds it from YAML and validates it; formulations read it and never change
// it.
//
// Conventions (docs/architecture.md): sections are 6×6, order [F1, F2, F3, M1, M2, M3], against
// [ε11, 2ε12, 2ε13, κ1, κ2, κ3], in material axes (e1 along the reference line tangent). The
// reference frame R^r(s) = [e1 e2 e3] maps material to inertial components.
//
// Default material axes: e1 = tangent; e2 = normalize(ẑ × e1) (or ŷ projected when e1 ∥ ẑ),
// e3 = e1 × e2 — for a beam along +x that is e2 = +y, e3 = +z. A circular arc uses its plane
// normal as e3 (e2 points toward the centre). `twist` rotates e2, e3 about e1.
#pragma once

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/choices.hpp"
#include "core/types.hpp"

namespace rotbeam {

struct Point {
    std::string name;
    Vec3 position = Vec3::Zero();
};

enum class LineKind { straight, arc, keypoints };

struct ReferenceLine {
    LineKind kind = LineKind::straight;
    // arc: the circle's centre; the arc runs from the member's start to its end point the short
    // way round (< π) unless `normal` fixes the plane/sense (right-handed about normal).
    Vec3 center = Vec3::Zero();
    std::optional<Vec3> normal;
    // keypoints: interior points between start and end, in order (the curve is a natural cubic
    // spline through start, keypoints, end, re-parameterized by arc length).
    std::vector<Vec3> keypoints;
    // Optional hint for e2 (projected onto the plane normal to the tangent); overrides the default.
    std::optional<Vec3> e2_hint;
};

struct Section {
    std::string name;  // the case file's section name (for messages and `rotbeam check`)
    // Material-axis 6×6 matrices. `compliance` is always set; `stiffness` is set when the
    // compliance is invertible (it may have zero rows: rigid modes).
    Mat6 compliance = Mat6::Zero();
    std::optional<Mat6> stiffness;
    std::optional<Mat6> mass;  // [m I, m η̃ᵀ; m η̃, ρ] in material axes
    // Stiffness-proportional damping coefficients μ (seed 000 Eq. 10), zero = undamped.
    Vec6 damping = Vec6::Zero();
    bool has_damping() const { return damping.cwiseAbs().maxCoeff() > 0.0; }
};

struct SectionStation {
    double s_fraction = 0.0;  // position along the member, s/L in [0, 1]
    Section section;
};

struct Member {
    std::string name;
    int start_point = -1;  // index into Model::points
    int end_point = -1;
    ReferenceLine line;
    // Twist of the material axes about e1, radians, linear from start to end; or, when
    // twist_values holds n > 2 angles, the polynomial of degree n − 1 through them at equally
    // spaced s/L = i/(n − 1) (twist_start and twist_end are then its first and last value).
    double twist_start = 0.0;
    double twist_end = 0.0;
    std::vector<double> twist_values;
    // One station = constant section; several = linear interpolation in s/L.
    std::vector<SectionStation> sections;
    int elements = 1;
};

// Scalar function of time (dynamics) multiplying a load or prescribed motion.
struct TimeFunction {
    enum class Kind { constant, ramp, sine, table };
    Kind kind = Kind::constant;
    double value = 1.0;          // constant value; amplitude of sine; final value of ramp
    double start = 0.0;          // ramp start time; sine start time (0 before)
    double duration = 0.0;       // ramp duration
    double omega = 0.0;          // sine circular frequency [rad/time]
    double phase = 0.0;          // sine phase
    std::vector<double> times;   // table abscissae (increasing)
    std::vector<double> values;  // table ordinates
    double operator()(double t) const;
};

enum class LoadFrame { dead, follower };

struct PointLoad {
    int point = -1;
    Vec3 force = Vec3::Zero();
    Vec3 moment = Vec3::Zero();
    // dead: fixed inertial direction; follower: the given vector is the load in the reference
    // configuration and turns with the point's rotation, f = R f0 (R relative to reference).
    LoadFrame frame = LoadFrame::dead;
    TimeFunction time;
};

struct DistributedLoad {
    int member = -1;
    Vec3 force = Vec3::Zero();  // per unit reference length, constant along the member
    Vec3 moment = Vec3::Zero();
    LoadFrame frame = LoadFrame::dead;
    TimeFunction time;
};

// A dead distributed load given as a function of the arc length s along one member (from its
// start): force and moment per unit reference length, inertial components. It is built in code,
// not read from case files: the load of a manufactured solution (core/oracles/manufactured.hpp,
// manufactured_motion.hpp), which must vary along the member and in λ or t in a way no case-file
// load can. Two forms, one of which is set:
//  - `density(s, λ)`: a static field, already scaled (λ is not applied again); dynamic analyses
//    see it at λ = 1, constant in time;
//  - `density_in_time(s, t)`: a field in time (the inertial loads of a manufactured motion);
//    statics take it at the analysis time (0 unless a dynamic analysis set one) times λ.
struct LoadField {
    int member = -1;
    std::function<void(double s, double lambda, Vec3& force, Vec3& moment)> density;
    std::function<void(double s, double t, Vec3& force, Vec3& moment)> density_in_time;
    // The load at s for load factor λ at time t, whichever form is set.
    void evaluate(double s, double lambda, double t, Vec3& force, Vec3& moment) const {
        if (density_in_time) {
            density_in_time(s, t, force, moment);
            force *= lambda;
            moment *= lambda;
            return;
        }
        density(s, lambda, force, moment);
    }
};

struct Constraint {
    enum class Kind { clamped, prescribed };
    int point = -1;
    Kind kind = Kind::clamped;
    Vec3 displacement = Vec3::Zero();  // prescribed: u = load/time factor × displacement
    Vec3 rotation = Vec3::Zero();      // prescribed: rotation vector (relative to reference)
    TimeFunction time;
};

// A steady rotation of the whole beam at constant angular velocity Ω (inertial components, rad per
// time unit) about the axis through `center` (case key `rotating_frame`, docs/rotating-frame.md).
// Statics and modal analysis are then solved in the frame turning with the beam: every section
// carries the d'Alembert force of its rigid rotation, −F^I with u¨ = Ω × (Ω × r), ω = Ω, ω˙ = 0
// (centrifugal force, its mass-offset moment and the gyroscopic moment Ω × ρΩ), a load that
// depends on the configuration and is multiplied by the load factor λ like gravity (λ scales
// Ω²). The Coriolis terms 2Ω × u˙ vanish at a steady state; the modal analysis leaves them out
// (modes of K(Ω) − ω²M, stated in its result).
struct RotatingFrame {
    Vec3 angular_velocity = Vec3::Zero();
    Vec3 center = Vec3::Zero();
    bool active() const { return angular_velocity.squaredNorm() > 0.0; }
};

enum class AnalysisKind { static_, dynamic, modal };

struct StaticSettings {
    std::vector<double> load_factors;  // reported steps; loads are multiplied by the factor
    int substeps = 1;                  // initial equal sub-steps between reported factors
    int max_step_cuts = 12;            // consecutive bisections: smallest sub-step / 2^this
};

struct DynamicSettings {
    double time_step = 0.0;
    double end_time = 0.0;
    double output_interval = 0.0;                   // 0 = every step
    double rho_infinity = 1.0;                      // generalized-α spectral radius at infinity
    Integrator integrator = Integrator::automatic;  // which a formulation takes: combinations/
    // IDA (integrator "ida"): relative tolerance and absolute tolerance per unit of each unknown's
    // state scale (IDASVtolerances, docs/mixed-dynamics.md).
    double relative_tolerance = 1e-6;
    double absolute_tolerance = 1e-6;
    // Adaptive time steps when > 0 (analysis.time_tolerance): the tolerance on the global time
    // error of the configuration over the window, translations relative to the model's reference
    // length, rotations in rad (core/step_size_control.hpp). What holds per integrator: the
    // Gauss-Legendre step doubling is checked against the global error (docs/displacement-
    // dynamics.md "Time step control"); generalized-alpha's estimate is dominated by unresolved
    // high modes where the motion excites them (same section, "Measured"); the mixed trapezoidal
    // scheme has the same caveat; Radau IIA's embedded estimate (core/dae_radau.hpp) gave a
    // global error below the tolerance on the free vibration at 1e-4 but at a large cost
    // (docs/mixed-dynamics.md "Radau IIA"); IDA takes it as its relative and absolute tolerance.
    // time_step is then the first step.
    double time_tolerance = 0.0;
    // A time step whose Newton fails is retried with h/2, at most this many times in a row
    // (analysis.max_step_cuts; 0: off). On by default: a result whose step was cut says so.
    int max_step_cuts = 10;
    Vec3 initial_velocity = Vec3::Zero();
    // `rest`: start from the reference configuration at rest; `static`: start at rest from the
    // static equilibrium under the loads evaluated at t = 0 (a release, docs/benchmarks.md §8).
    InitialState initial_state = InitialState::rest;
};

struct ModalSettings {
    int modes = 5;
    bool about_static_state = true;  // linearize about the static solution of the loads
};

struct Analysis {
    AnalysisKind kind = AnalysisKind::static_;
    StaticSettings statics;
    DynamicSettings dynamics;
    ModalSettings modal;
    // `rotbeam run` estimates the discretization error (docs/error-estimates.md) unless false;
    // `run --estimate on|off` overrides it.
    bool estimate = true;
    // The estimate's companions: finer (default) or coarser than the run (docs/error-estimates.md,
    // "Coarser companions"); analysis.estimate_companions.
    CompanionSide estimate_companions = CompanionSide::finer;
    // `rotbeam run` refines the discretization until every estimate is at most accuracy / 2
    // relative to its scale (docs/accuracy-control.md); 0 = run the discretization as given.
    // `run --accuracy TOL` sets it.
    double accuracy = 0.0;
};

// The displacement formulation's stiffness quadrature (formulations/displacement/mesh.hpp);
// `trapezoidal` places its points at the member's section stations (BeamDyn's `quadrature = 2`).
enum class Quadrature { automatic, reduced, full, gll, trapezoidal };

// The displacement formulation's own options (docs/displacement-formulation.md).
struct DisplacementOptions {
    Interpolation interpolation = Interpolation::relative;
    Update update = Update::multiplicative;
    bool rescale = true;
    MassRule mass_rule = MassRule::consistent;
    // Mixed-integration-point Newton (statics, formulations/displacement/mip_stresses.hpp; case
    // key solver.mip): same solution, the geometric stiffness from the predicted resultants.
    bool mip = false;
};

// The mixed formulation's own options (docs/mixed-formulation.md).
struct MixedOptions {
    // With Wiener–Milenković: `plain` (seed 002 as published; singular at φ = 2π) or
    // `continuous` (GXBeam's continuous rescaling map,
    // parameterizations/wiener_milenkovic_continuous.hpp).
    WmMap wm_map = WmMap::plain;
    MassRule mass_rule = MassRule::consistent;  // consistent | midpoint (no nodal masses to lump)
};

// What both formulations share, and each formulation's options. The case loader sets only the
// options of the chosen formulation and refuses a case that gives the other's. The mesh keys
// (order, quadrature) are shared: a case file gives them once for every formulation it is run in;
// the mixed element is linear with its one mid-point and reads neither.
struct Discretization {
    Formulation formulation = Formulation::displacement;
    ParameterizationId rotation{};  // parameterizations/registry.hpp; {} = the quaternion
    int order = 1;                  // element polynomial order p
    Quadrature quadrature = Quadrature::automatic;
    int quadrature_points = 0;  // > 0 overrides the rule's point count
    int refine = 1;             // trapezoidal: equal divisions of each interval between stations
    DisplacementOptions displacement;
    MixedOptions mixed;
    // The chosen formulation's mass rule.
    MassRule mass_rule() const {
        return formulation == Formulation::mixed ? mixed.mass_rule : displacement.mass_rule;
    }
    // discretization.accuracy: per formulation, the accuracy the case's own discretization is
    // meant to reach, in the sense of analysis.accuracy (every estimate ≤ half of it relative to
    // its scale, docs/accuracy-control.md); a statement checked by the tests, not a target.
    std::map<Formulation, double> stated_accuracy;
};

struct SolverSettings {
    // On the scaled residual (force/moment scales below) and the scaled Newton increment. Unset,
    // each solve takes its own default: 1e-12 (NewtonSettings, core/static_driver.hpp), 1e-10 for
    // the mixed formulation's time steps (time_step_newton_settings, core/dae_driver.hpp); a value
    // the case or --set gives applies to every solve of the run.
    std::optional<double> residual_tolerance;
    std::optional<double> increment_tolerance;
    int max_iterations = 50;
    bool line_search = true;
    LinearSolver linear_solver = LinearSolver::sparse;  // core/sparse_lu.hpp
    Driver driver = Driver::newton;
    double force_scale = 0.0;   // 0 = derive from the model (loads and stiffness)
    double length_scale = 0.0;  // 0 = derive from the model (total length)
    // Assemble every term a formulation has, also those the scene makes zero or needless (inertia
    // and damping in a static analysis, damping of an undamped section, the load stiffness of a
    // dead load), with zero coefficients: the results are those of the default to round-off. It
    // exists to measure what "model only what the scene requires" saves (docs/studies.md).
    bool assemble_all_terms = false;
};

struct ReferenceValue {
    std::string id;        // unique within the case
    std::string quantity;  // displacement | rotation_angle | frequency | ...
    std::string point;     // for point quantities
    std::optional<double> load_factor;
    std::optional<double> time;
    int mode = 0;  // for frequencies (1-based)
    std::vector<double> value;
    std::vector<int> components;  // which components `value` lists (empty: all)
    double tolerance = 0.0;
    bool relative = false;  // tolerance relative to |value| (else absolute, case units)
    bool gated = true;      // false: recorded, not gated (docs/benchmarks.md §1)
    std::string justification;
    std::string source;
    std::optional<int> published_iterations;  // the source's Newton iterations (reported only)
    // The discretization the number is checked with: formulation, rotation, interpolation,
    // wm_map select combinations (unnamed ones: every combination); elements, order, quadrature,
    // ... set the mesh and rule. `scope` says why named combination keys leave others out.
    std::map<std::string, std::string> applies_to;
    std::string scope;
    // The same number checked with further discretizations, each with its own tolerance
    // (`also`: e.g. an exact value on the mixed formulation's coarser mesh).
    struct Check {
        std::map<std::string, std::string> applies_to;
        std::string scope;
        double tolerance = 0.0;
        std::string justification;
    };
    std::vector<Check> also;
};

// A combination that must stop on the way (docs/case-format.md, "Expected stops"): converged up
// to `reaches`, no converged step at or past `stops_before`, ending with `status` (a status name
// of the results, kept as data so that new statuses need no code here).
struct ExpectedStop {
    std::string id;
    std::map<std::string, std::string> applies_to;  // as ReferenceValue::applies_to
    std::optional<double> reaches;
    double stops_before = 0.0;
    std::string status;
    std::string justification;
};

struct Model {
    std::string name;
    std::string description;
    std::string units;  // e.g. "in, lbf" — documentation only
    std::vector<Point> points;
    std::vector<Member> members;
    std::vector<Constraint> constraints;
    std::vector<PointLoad> point_loads;
    std::vector<DistributedLoad> distributed_loads;
    std::vector<LoadField> load_fields;  // manufactured solutions only (see LoadField)
    Vec3 gravity = Vec3::Zero();
    RotatingFrame rotating_frame;
    Analysis analysis;
    Discretization discretization;
    SolverSettings solver;
    std::vector<ReferenceValue> references;
    std::vector<ExpectedStop> expected_stops;

    int point_index(const std::string& name) const;  // −1 when absent
    bool has_follower_loads() const;
    bool has_damping() const;
    bool needs_inertia() const { return analysis.kind != AnalysisKind::static_; }
};

}  // namespace rotbeam
