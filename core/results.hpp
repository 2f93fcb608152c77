// The result schema of `run`, `reference`, the suite and the benchmarks (docs/architecture.md, The
// program and its results), and atomic writing of result files.
//
// A run result is one JSON object: case, rotation, formulation, elements, order, dofs, status
// (converged | stalled-at-round-off | diverged | singular | error | unstable-equilibrium,
// docs/solver-convergence.md),
// message, wall_seconds, version, options, counters, and `steps` (one per reported load step or
// output time) with, for every named point, displacement, rotation_matrix (R^c R^rᵀ),
// rotation_vector (principal value) and rotation_angle (the rotation vector continued along the
// beam from the root, core/beam_rotation.hpp); a static step also has `convergence` (criterion,
// scaled_residual, error_bound, round_off_floor) and `stability` (core/static_stability.hpp).
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/atomic_file.hpp"  // write_file_atomically
#include "core/model.hpp"
#include "core/static_state.hpp"

namespace rotbeam {

// The version of the JSON contract (docs/json-schema.md), written as `schema_version` into every
// JSON object the program writes: raised when a field is renamed, removed or changes meaning, so
// that a downstream script can refuse a file it does not know.
inline constexpr int kSchemaVersion = 3;

// {"displacement", "rotation_matrix", "rotation_vector", "rotation_angle"} of one point;
// rotation_angle is the norm of `continued_rotation_vector`.
nlohmann::json point_json(const PointState& state, const Vec3& continued_rotation_vector);

// One step entry: {"load_factor" | "time", "newton_iterations", "points": {name: point_json}}.
// `continued` holds each point's rotation vector continued along the beam
// (rotation_vectors_along_beam), indexed like `states`.
nlohmann::json step_json(const Model& model, std::optional<double> load_factor,
                         std::optional<double> time, int newton_iterations,
                         const std::vector<PointState>& states, const std::vector<Vec3>& continued);

nlohmann::json counters_json(const AssemblyCounters& c);

// True when every number in the document is finite (a result never prints NaN).
bool all_finite(const nlohmann::json& j);

}  // namespace rotbeam
