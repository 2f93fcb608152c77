#include "core/results.hpp"

#include <cmath>

#include "core/so3.hpp"

namespace rotbeam {

namespace {
nlohmann::json vec_json(const Vec3& v) { return {v.x(), v.y(), v.z()}; }
}  // namespace

nlohmann::json point_json(const PointState& state, const Vec3& continued_rotation_vector) {
    nlohmann::json R = nlohmann::json::array();
    for (int r = 0; r < 3; ++r) {
        R.push_back({state.rotation(r, 0), state.rotation(r, 1), state.rotation(r, 2)});
    }
    return {{"displacement", vec_json(state.displacement)},
            {"rotation_matrix", R},
            {"rotation_vector", vec_json(so3::log_map(state.rotation))},
            {"rotation_angle", continued_rotation_vector.norm()}};
}

nlohmann::json step_json(const Model& model, std::optional<double> load_factor,
                         std::optional<double> time, int newton_iterations,
                         const std::vector<PointState>& states,
                         const std::vector<Vec3>& continued) {
    nlohmann::json step;
    if (load_factor) step["load_factor"] = *load_factor;
    if (time) step["time"] = *time;
    step["newton_iterations"] = newton_iterations;
    nlohmann::json points = nlohmann::json::object();
    for (size_t i = 0; i < model.points.size() && i < states.size(); ++i) {
        points[model.points[i].name] = point_json(states[i], continued.at(i));
    }
    step["points"] = points;
    return step;
}

nlohmann::json counters_json(const AssemblyCounters& c) {
    return {{"residual_evaluations", c.residual_evaluations},
            {"jacobian_evaluations", c.jacobian_evaluations},
            {"elastic_terms", c.elastic_terms},
            {"inertial_terms", c.inertial_terms},
            {"damping_terms", c.damping_terms},
            {"follower_stiffness", c.follower_stiffness},
            {"distributed_load_terms", c.distributed_load_terms},
            {"gravity_terms", c.gravity_terms}};
}

bool all_finite(const nlohmann::json& j) {
    if (j.is_number_float()) return std::isfinite(j.get<double>());
    if (j.is_array() || j.is_object()) {
        for (const auto& item : j) {
            if (!all_finite(item)) return false;
        }
    }
    return true;
}

}  // namespace rotbeam
