#include "parameterizations/rotation_study.hpp"

#include <cmath>
#include <limits>
#include <string>

#include "core/errors.hpp"
#include "core/results.hpp"
#include "core/so3.hpp"
#include "parameterizations/registry.hpp"

namespace rotbeam::param {
namespace {

Vec3 study_axis() { return Vec3(1.0, -2.0, 3.0).normalized(); }

// max_j ‖H_m e_j − axial(Rᵀ FD(∂R/∂p_j))‖ / ‖H_m‖, central differences with h = ∛ε max(1, ‖p‖).
template <class P>
double tangent_fd_error(const typename P::P& p, const Tangent<P::kSize>& H) {
    const double h = std::cbrt(std::numeric_limits<double>::epsilon()) * std::max(1.0, p.norm());
    const Mat3 R = P::matrix(p);
    double worst = 0.0;
    for (int j = 0; j < P::kSize; ++j) {
        const typename P::P e = P::P::Unit(j);
        const Mat3 dR =
            (P::matrix(typename P::P(p + h * e)) - P::matrix(typename P::P(p - h * e))) / (2.0 * h);
        worst = std::max(worst, (so3::axial(R.transpose() * dR) - H.col(j)).norm());
    }
    return worst / H.norm();
}

// The tangent columns of one sample; leaves them null (tangent_defined = false) if refused.
template <class P>
void add_tangent(const typename P::P& p, nlohmann::json& row) {
    try {
        const Tangent<P::kSize> H = P::material_tangent(p);
        const TangentInverse<P::kSize> Hi = P::material_tangent_inverse(p);
        const Eigen::JacobiSVD<Tangent<P::kSize>> svd(H);
        const Eigen::JacobiSVD<TangentInverse<P::kSize>> svd_inverse(Hi);
        const double sigma_min = svd.singularValues()(2);
        row["tangent_defined"] = true;
        row["sigma_min"] = sigma_min;
        row["tangent_inverse_norm"] = svd_inverse.singularValues()(0);
        row["condition"] = svd.singularValues()(0) / sigma_min;
        row["fd_error"] = tangent_fd_error<P>(p, H);
    } catch (const SingularityError& e) {
        row["tangent_defined"] = false;
        row["refused_by"] = e.function();
        row["message"] = e.what();
    }
}

template <class P>
nlohmann::json study_sample(double angle) {
    nlohmann::json row = {{"angle", angle},
                          {"defined", false},
                          {"parameter_norm", nullptr},
                          {"matrix_error", nullptr},
                          {"round_trip_error", nullptr},
                          {"tangent_defined", false},
                          {"sigma_min", nullptr},
                          {"tangent_inverse_norm", nullptr},
                          {"condition", nullptr},
                          {"fd_error", nullptr}};
    const Vec3 psi = angle * study_axis();
    try {
        const typename P::P p = P::from_rotation_vector(psi);
        row["defined"] = true;
        row["parameter_norm"] = p.norm();
        row["matrix_error"] = (P::matrix(p) - so3::exp_map(psi)).norm();
        const Vec3 back = RotationVector::rescale(P::to_rotation_vector(p), psi);
        row["round_trip_error"] = (back - psi).norm();
    } catch (const SingularityError& e) {
        row["refused_by"] = e.function();
        row["message"] = e.what();
        return row;
    }
    add_tangent<P>(P::from_rotation_vector(psi), row);
    return row;
}

}  // namespace

nlohmann::json rotation_study(int samples) {
    ROTBEAM_VERIFY(samples >= 2, "rotation_study needs at least 2 samples");
    nlohmann::json angles = nlohmann::json::array();
    for (int i = 0; i < samples; ++i) angles.push_back(4.0 * kPi * i / (samples - 1));
    const Vec3 axis = study_axis();
    nlohmann::json result = {{"schema_version", kSchemaVersion},
                             {"axis", {axis.x(), axis.y(), axis.z()}},
                             {"angles", angles}};
    nlohmann::json list = nlohmann::json::array();
    for_each_parameterization([&]<class P>() {
        nlohmann::json rows = nlohmann::json::array();
        for (const nlohmann::json& angle : angles)
            rows.push_back(study_sample<P>(angle.get<double>()));
        const double singular = P::singular_angle();
        list.push_back({{"name", std::string(P::kName)},
                        {"singular_angle", std::isfinite(singular) ? nlohmann::json(singular)
                                                                   : nlohmann::json(nullptr)},
                        {"samples", rows}});
    });
    result["parameterizations"] = list;
    return result;
}

}  // namespace rotbeam::param
