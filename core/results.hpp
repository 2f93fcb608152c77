// The result schema shared by `run`, `reference`, the suite and the benchmarks (DESIGN.md §Program
// and results contract), and atomic writing of result files.
//
// A run result is one JSON object: case, rotation, formulation, elements, order, dofs, status,
// message, wall_seconds, version, options, counters, and `steps` (one per reported load step or
// output time) with, for every named point, displacement, rotation_matrix (R^c R^rᵀ),
// rotation_vector (principal value) and rotation_angle (unwrapped along the path).
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/atomic_file.hpp"  // write_file_atomically
#include "core/model.hpp"
#include "core/nonlinear_system.hpp"

namespace rotbeam {

// Tracks each named point's rotation along a load or time path so that the reported angle is
// continuous (a full roll-up reads 2π, not 0).
class RotationUnwrapper {
  public:
    explicit RotationUnwrapper(size_t points) : previous_(points, Vec3::Zero()) {}
    // Returns the unwrapped rotation vector of point i for rotation R and remembers it.
    Vec3 update(size_t i, const Mat3& R);

  private:
    std::vector<Vec3> previous_;
};

// {"displacement", "rotation_matrix", "rotation_vector", "rotation_angle"} of one point.
nlohmann::json point_json(const PointState& state, const Vec3& unwrapped_rotation_vector);

// One step entry: {"load_factor" | "time", "newton_iterations", "points": {name: point_json}}.
nlohmann::json step_json(const Model& model, std::optional<double> load_factor,
                         std::optional<double> time, int newton_iterations,
                         const std::vector<PointState>& states, RotationUnwrapper& unwrapper);

nlohmann::json counters_json(const AssemblyCounters& c);

// True when every number in the document is finite (a result never prints NaN).
bool all_finite(const nlohmann::json& j);

}  // namespace rotbeam
