// Shape and content of the rotation study.
#include <boost/test/unit_test.hpp>

#include "parameterizations/rotation_study.hpp"
#include "samples.hpp"

namespace rotbeam::test {
namespace {

// The row of parameterization `name` at sample i of a study.
const nlohmann::json& row(const nlohmann::json& study, const std::string& name, int i) {
    for (const nlohmann::json& p : study["parameterizations"]) {
        if (p["name"] == name) return p["samples"][i];
    }
    BOOST_FAIL("no parameterization " << name);
    return study;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(parameterization_rotation_study)

// 9 samples: φ = 0, π/2, π, …, 4π (sample i at iπ/2, exact in binary).
BOOST_AUTO_TEST_CASE(study_has_one_row_per_angle_and_parameterization) {
    const nlohmann::json study = param::rotation_study(9);
    BOOST_TEST(study["angles"].size() == 9u);
    BOOST_TEST(study["angles"][8].get<double>() == 4.0 * kPi);
    BOOST_TEST(study["parameterizations"].size() == param::parameterization_names().size());
    for (const nlohmann::json& p : study["parameterizations"]) {
        BOOST_TEST(p["samples"].size() == 9u);
        for (const char* key :
             {"angle", "defined", "parameter_norm", "matrix_error", "round_trip_error",
              "tangent_defined", "sigma_min", "tangent_inverse_norm", "condition", "fd_error"}) {
            BOOST_TEST(p["samples"][3].contains(key), key);
        }
    }
}

BOOST_AUTO_TEST_CASE(study_marks_rodrigues_undefined_at_pi_and_wm_at_2pi) {
    const nlohmann::json study = param::rotation_study(9);
    BOOST_TEST(row(study, "rodrigues", 1)["defined"].get<bool>());
    BOOST_TEST(!row(study, "rodrigues", 2)["defined"].get<bool>());
    BOOST_TEST(row(study, "rodrigues", 2)["refused_by"] == "from_rotation_vector");
    BOOST_TEST(row(study, "wiener-milenkovic", 3)["defined"].get<bool>());
    BOOST_TEST(!row(study, "wiener-milenkovic", 4)["defined"].get<bool>());
    BOOST_TEST(row(study, "wiener-milenkovic", 4)["sigma_min"].is_null());
    // The rotation vector's R exists at 2π, its tangent does not; at 3π both do.
    BOOST_TEST(row(study, "rotation-vector", 4)["defined"].get<bool>());
    BOOST_TEST(!row(study, "rotation-vector", 4)["tangent_defined"].get<bool>());
    BOOST_TEST(row(study, "rotation-vector", 6)["tangent_defined"].get<bool>());
    for (int i = 0; i < 9; ++i)
        BOOST_TEST(row(study, "quaternion", i)["tangent_defined"].get<bool>());
}

BOOST_AUTO_TEST_CASE(study_shows_wm_sigma_min_falling_towards_2pi) {
    // σ_min(Q) = 2/(4 − c0) = cos²(φ/4) for WM: 1 at 0, 1/2 at π, 0 at 2π.
    const nlohmann::json study = param::rotation_study(17);  // steps of π/4
    const double at_pi = row(study, "wiener-milenkovic", 4)["sigma_min"].get<double>();
    const double at_7pi_4 = row(study, "wiener-milenkovic", 7)["sigma_min"].get<double>();
    BOOST_TEST(at_pi == 0.5, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(at_7pi_4 == std::pow(std::cos(7.0 * kPi / 16.0), 2),
               boost::test_tools::tolerance(1e-12));
    BOOST_TEST(row(study, "wiener-milenkovic", 7)["condition"].get<double>() == 1.0,
               boost::test_tools::tolerance(1e-12));
    for (int i = 0; i < 8; ++i) {
        BOOST_TEST(row(study, "wiener-milenkovic", i)["fd_error"].get<double>() <= 1e-8);
        BOOST_TEST(row(study, "wiener-milenkovic", i)["matrix_error"].get<double>() <= 1e-14);
    }
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace rotbeam::test
