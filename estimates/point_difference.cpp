#include "estimates/point_difference.hpp"

#include "core/so3.hpp"
#include "core/types.hpp"

namespace rotbeam::estimate {

namespace {

Vec3 vec3(const nlohmann::json& j) {
    return {j[0].get<double>(), j[1].get<double>(), j[2].get<double>()};
}

Mat3 mat3(const nlohmann::json& j) {
    Mat3 R;
    for (int r = 0; r < 3; ++r) R.row(r) = vec3(j[static_cast<std::size_t>(r)]).transpose();
    return R;
}

}  // namespace

PointDifference point_difference(const nlohmann::json& a, const nlohmann::json& b) {
    return {
        (vec3(a["displacement"]) - vec3(b["displacement"])).norm(),
        so3::rotation_angle(mat3(a["rotation_matrix"]).transpose() * mat3(b["rotation_matrix"]))};
}

}  // namespace rotbeam::estimate
