// Runs of the undamped free vibration (cases/free-vibration.yaml, docs/benchmarks.md §8: the
// cantilever released at rest from its static deflection under a 1 N tip force) with every time
// integrator: the displacement formulation with the Lie-group generalized-α or Gauss–Legendre
// collocation (2 or 3 stages), the mixed one with the trapezoidal rule or the 3-stage Radau IIA
// method. Shared by the free-vibration time study (study_free_vibration_time.cpp) and its tests
// (tests/agreement/test_free_vibration_time.cpp). Holds the parameterization switch of these runs.
//
// Recorded at every output time, in the bending plane (x, z) of the release (the out-of-plane
// components stay zero; the axial ones carry the stretching at second order in the deflection):
// the tip's u_z and its rotation about y (from its rotation matrix: the same quantity for every
// parameterization), the velocity-level unknowns nearest the tip (displacement: the tip node's
// u̇_z, ω_y; mixed: the last element's momenta P_z, H_y), the root reaction F_z, M_y (the mixed
// formulation's supported-node unknowns, the displacement formulation's residual rows at the
// root), and the total energy (kinetic + strain).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "core/choices.hpp"
#include "core/model.hpp"
#include "core/types.hpp"

namespace rotbeam::cli {

struct FreeVibrationSpec {
    Formulation formulation = Formulation::displacement;
    ParameterizationId rotation{};  // parameterizations/registry.hpp
    WmMap wm_map = WmMap::plain;    // mixed WM
    // displacement: generalized-alpha | gauss-legendre-2 | gauss-legendre-3; mixed: trapezoidal
    // | radau-iia-3
    Integrator integrator = Integrator::generalized_alpha;
    double rho_infinity = 1.0;  // generalized-α
    int elements = 2;           // of the one member
    int order = 1;              // displacement: polynomial order p
    double dt = 1e-3;
    double end_time = 0.5;
    double output_interval = 0.05;
    // Newton (stage iteration) tolerance on the scaled residual and increment of every step.
    double newton_tolerance = 1e-12;
    // NewtonSettings::contraction_stop: false for the energy over many periods.
    bool contraction_stop = true;
    std::string label() const;  // e.g. "displacement/quaternion/gl3", "mixed/wiener-milenkovic/ta"
};

// The groups of recorded values, each measured on its own.
enum class FreeVibrationGroup { position, rotation, velocity, force };
constexpr int kFreeVibrationGroups = 4;
const char* group_name(FreeVibrationGroup g);

struct FreeVibrationRun {
    std::string status;  // converged | diverged | singular | unavailable ...
    std::string message;
    long steps = 0;
    long iterations = 0;
    double wall_seconds = 0.0;
    std::vector<double> times, energy;
    // Per output time: u_z, θ_y, the two velocity-level values, F_z, M_y.
    std::vector<std::array<double, 6>> values;
    bool ok() const;
};

// The model of a run: the catalog case with the spec's mesh, scheme and Newton tolerance.
Model free_vibration_model(const FreeVibrationSpec& spec);

FreeVibrationRun run_free_vibration(const FreeVibrationSpec& spec);

// Max over the common output times of |a − b| in the group's values, over the group's largest
// magnitude in b.
double group_difference(const FreeVibrationRun& a, const FreeVibrationRun& b, FreeVibrationGroup g);

// The energy record of a long run: (E − E0)/E0 averaged over windows of ten periods of the first
// mode (counted by the upward zero crossings of the tip's u_z, whose amplitude it dominates), the
// least-squares slope of those means per 1000 periods, the largest |E − E0|/E0.
struct EnergyDrift {
    double periods = 0.0;  // of the first mode in the run
    std::vector<double> window_periods, window_means;
    double drift_per_1000_periods = 0.0;
    double max_deviation = 0.0;
};
EnergyDrift energy_drift(const FreeVibrationRun& run);

}  // namespace rotbeam::cli
