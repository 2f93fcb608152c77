// The difference between two result JSON states of one named point (core/results.hpp step_json):
// the norm of the displacement difference and the angle of R_aᵀ R_b (radians).
#pragma once

#include <nlohmann/json.hpp>

namespace rotbeam::estimate {

struct PointDifference {
    double displacement = 0.0;  // ‖u_a − u_b‖
    double rotation = 0.0;      // angle of R_aᵀ R_b
};

PointDifference point_difference(const nlohmann::json& a, const nlohmann::json& b);

}  // namespace rotbeam::estimate
