// SO(3) helpers: exactness of the small-angle branches and of the extraction near π.
#include <boost/test/unit_test.hpp>

#include <cmath>

#include "core/so3.hpp"

using namespace rotbeam;

namespace {
const Vec3 kAxis = Vec3(0.3, -0.5, 0.81).normalized();

// Reference rotation matrix from the quaternion built in long double.
Mat3 reference_matrix(double phi, const Vec3& n) {
    const long double h = 0.5L * phi;
    const long double w = std::cos(h), s = std::sin(h);
    Vec4 q(static_cast<double>(w), static_cast<double>(s * n.x()), static_cast<double>(s * n.y()),
           static_cast<double>(s * n.z()));
    return so3::quat_to_matrix(q);
}
}  // namespace

BOOST_AUTO_TEST_SUITE(so3_helpers)

BOOST_AUTO_TEST_CASE(skew_is_cross_product_and_axial_inverts_it) {
    const Vec3 a(1.0, -2.0, 3.0), b(-0.5, 0.25, 4.0);
    BOOST_TEST((so3::skew(a) * b - a.cross(b)).norm() == 0.0);
    BOOST_TEST((so3::axial(so3::skew(a)) - a).norm() == 0.0);
}

BOOST_AUTO_TEST_CASE(exp_map_is_accurate_at_tiny_angles) {
    for (double phi : {1e-12, 1e-9, 1e-6, 1e-4, 2e-4}) {
        const Mat3 R = so3::exp_map(phi * kAxis);
        const Mat3 Rref = reference_matrix(phi, kAxis);
        // The off-diagonal part carries the information: relative error on (R − I).
        const double rel = (R - Rref).norm() / (Rref - Mat3::Identity()).norm();
        BOOST_TEST(rel < 1e-14, "phi " << phi << " rel " << rel);
    }
}

BOOST_AUTO_TEST_CASE(exp_map_is_orthogonal_with_unit_determinant) {
    for (double phi : {0.0, 0.3, 3.0, kPi, 5.0, 4.0 * kPi + 0.1}) {
        const Mat3 R = so3::exp_map(phi * kAxis);
        BOOST_TEST((R.transpose() * R - Mat3::Identity()).norm() < 1e-14);
        BOOST_TEST(std::abs(R.determinant() - 1.0) < 1e-14);
    }
}

BOOST_AUTO_TEST_CASE(log_map_inverts_exp_map_from_tiny_angles_to_pi) {
    for (double phi : {1e-12, 1e-9, 1e-5, 0.7, 2.0, kPi - 1e-6, kPi - 1e-10}) {
        const Vec3 psi = phi * kAxis;
        const Vec3 back = so3::log_map(so3::exp_map(psi));
        // Near π the rotation matrix determines the axis to ~ε/(π − φ) (DESIGN: robust, not
        // better than the conditioning allows); relative 1e-15 elsewhere.
        const double tol = phi > 3.0 ? 1e-15 / (kPi - phi) + 1e-14 : 2e-15;
        BOOST_TEST((back - psi).norm() / phi < tol, "phi " << phi);
    }
}

BOOST_AUTO_TEST_CASE(log_map_at_pi_returns_angle_pi) {
    const Vec3 psi = kPi * kAxis;
    const Vec3 back = so3::log_map(so3::exp_map(psi));
    BOOST_TEST(std::abs(back.norm() - kPi) < 1e-14);
    BOOST_TEST(std::abs(std::abs(back.normalized().dot(kAxis)) - 1.0) < 1e-14);
}

BOOST_AUTO_TEST_CASE(quaternion_and_matrix_round_trip_and_compose) {
    const Vec4 a = so3::quat_from_rotvec(1.3 * kAxis);
    const Vec4 b = so3::quat_from_rotvec(Vec3(-0.4, 2.0, 0.1));
    const Mat3 Rab = so3::quat_to_matrix(so3::quat_multiply(a, b));
    BOOST_TEST((Rab - so3::quat_to_matrix(a) * so3::quat_to_matrix(b)).norm() < 1e-15 * 10);
    const Vec4 back = so3::quat_from_matrix(so3::quat_to_matrix(b));
    BOOST_TEST(std::min((back - b).norm(), (back + b).norm()) < 1e-15 * 10);
    const Vec3 v(0.2, -1.0, 3.0);
    BOOST_TEST((so3::quat_rotate(a, v) - so3::quat_to_matrix(a) * v).norm() < 1e-14);
    BOOST_TEST((so3::quat_to_matrix(a) - so3::exp_map(1.3 * kAxis)).norm() < 1e-15 * 10);
}

BOOST_AUTO_TEST_CASE(rotation_angle_is_accurate_near_zero_and_pi) {
    for (double phi : {1e-9, 1e-3, 1.0, kPi - 1e-9}) {
        BOOST_TEST(std::abs(so3::rotation_angle(so3::exp_map(phi * kAxis)) - phi) < 1e-15 * 8,
                   "phi " << phi);
    }
}

BOOST_AUTO_TEST_CASE(unwrapping_follows_a_continuous_roll_up_past_two_turns) {
    Vec3 previous = Vec3::Zero();
    const int n = 400;
    for (int k = 1; k <= n; ++k) {
        const double phi = 4.0 * kPi * k / n;
        const Vec3 principal = so3::log_map(so3::exp_map(phi * kAxis));
        previous = so3::unwrap_rotation_vector(principal, previous);
        BOOST_TEST(std::abs(previous.norm() - phi) < 1e-10, "phi " << phi);
    }
}

BOOST_AUTO_TEST_SUITE_END()
