// The continuum reference solver: static Cosserat rod, shooting from the clamped root
// (docs/reference-solutions.md §5). It reads core/model.hpp and shares no code with the finite
// elements or core/geometry.
//
// Supported: one member, clamped at its start point; point forces/moments (dead or follower) at
// any named point on the member; constant distributed forces/moments (dead or follower); straight
// or circular-arc reference lines with linear twist; one constant 6×6 section given by its
// compliance (zero rows = rigid modes). Anything else returns status "error" with the reason.
#pragma once

#include <string>
#include <vector>

#include "core/model.hpp"
#include "core/static_state.hpp"
#include "core/types.hpp"

namespace rotbeam {

struct ContinuumOptions {
    double ode_tolerance = 1e-13;       // rk8pd absolute = relative tolerance, scaled state
    double residual_tolerance = 1e-11;  // ‖free-end residual‖∞ in units of EI/L², EI/L,
                                        // times the load size (at least 1e-3)
    int max_iterations = 60;            // multiroot iterations per load increment
    int max_step_cuts = 30;             // consecutive bisections of one load increment
    double max_turn = 0.5;  // [rad] largest rotation change of a section per accepted increment
    int centreline_samples = 41;  // equally spaced in s, ends included
    // Sections, equally spaced in s, ends included, along which the reported rotation angle is
    // continued (core/beam_rotation.hpp): 4π over 400 intervals is 0.03 rad apart.
    int rotation_samples = 401;
};

struct ContinuumStep {
    double load_factor = 0.0;
    int iterations = 0;     // multiroot iterations, summed over the sub-steps of this step
    int substeps = 0;       // load increments taken to reach this step from the previous one
    double residual = 0.0;  // final ‖free-end residual‖∞ (scaled)
    std::vector<PointState> points;    // indexed like model.points
    Vec3 root_force = Vec3::Zero();    // internal force n(0) at the root, inertial components
    Vec3 root_moment = Vec3::Zero();   // internal moment m(0)
    std::vector<double> centreline_s;  // reference arc length of the samples
    std::vector<Vec3> centreline;      // deformed centreline x(s)
    // R(s) R^r(s)ᵀ at `rotation_samples` sections from root to tip (member 0).
    std::vector<StaticProblem::RotationStation> rotations;
};

struct ContinuumOutcome {
    std::string status = "error";  // converged | diverged | error
    std::string message;
    std::vector<ContinuumStep> steps;  // the reported steps reached (all when converged)
};

ContinuumOutcome solve_continuum(const Model& model, const ContinuumOptions& options = {});

}  // namespace rotbeam
