// Sectional inertial forces (formulations/displacement/calculate_inertial_forces.hpp): every
// tangent block against central differences at a rotated, MOVING state with a full mass matrix
// (offset centre of mass, anisotropic, coupled ρ).
#include <boost/test/unit_test.hpp>

#include "core/so3.hpp"
#include "formulations/displacement/calculate_inertial_forces.hpp"

using namespace rotbeam;
using rotbeam::form::InertialBlocks;
using rotbeam::form::InertialState;

namespace {

// Material mass with m = 2.3, η* = (0.1, −0.25, 0.4) and a full symmetric positive ρ*.
Mat6 full_mass() {
    const double m = 2.3;
    const Vec3 eta(0.1, -0.25, 0.4);
    Mat3 rho;
    rho << 1.7, 0.2, -0.1, 0.2, 0.9, 0.15, -0.1, 0.15, 1.2;
    Mat6 M = Mat6::Zero();
    M.topLeftCorner<3, 3>() = m * Mat3::Identity();
    M.topRightCorner<3, 3>() = m * so3::skew(eta).transpose();
    M.bottomLeftCorner<3, 3>() = m * so3::skew(eta);
    M.bottomRightCorner<3, 3>() = rho;
    return M;
}

InertialState moving_state() {
    InertialState s;
    s.u_ddot = Vec3(0.7, -1.3, 2.1);
    s.omega = Vec3(-0.9, 1.4, 0.6);
    s.omega_dot = Vec3(1.1, 0.3, -1.7);
    s.Q = so3::exp_map(Vec3(0.8, -1.2, 1.9));  // |ψ| ≈ 2.4 rad
    return s;
}

Vec6 force(const Mat6& M_star, const InertialState& s) {
    return form::calculate_inertial_blocks(M_star, s).F;
}

// The perturbation of the state's vector `field` by d.
auto along(Vec3 InertialState::*field) {
    return [field](InertialState x, const Vec3& d) {
        x.*field += d;
        return x;
    };
}

// Max-norm relative error of an analytic 6×3 column block against its central-difference estimate.
// h = 1e-6: truncation h²|F'''| ~ 1e-12·O(10), round-off ε|F|/h ~ 1e-10·O(10); 1e-7 relative to
// the largest entry of F's scale leaves a margin of ~100 and still catches any wrong term (O(1)).
template <class Perturb>
double fd_error(const Mat6& M_star, const InertialState& s, const Eigen::Matrix<double, 6, 3>& A,
                const Perturb& perturb) {
    const double h = 1e-6;
    Eigen::Matrix<double, 6, 3> fd;
    for (int k = 0; k < 3; ++k) {
        const Vec3 d = h * Vec3::Unit(k);
        fd.col(k) = (force(M_star, perturb(s, d)) - force(M_star, perturb(s, -d))) / (2.0 * h);
    }
    return (fd - A).cwiseAbs().maxCoeff() / std::max(1.0, A.cwiseAbs().maxCoeff());
}

}  // namespace

BOOST_AUTO_TEST_SUITE(inertia)

// F^I is formed from rotated vectors (calculate_inertial_force); against the rotated-mass form
// F^I = M [u¨; ω˙] + [ω̃ω̃ a; ω̃ ρ ω], M = rotate_mass(M*, Q), a = m η and ρ read from M. Both are
// sums of O(10) terms of size O(10) here, so they agree to ~1e-14 of |F|; 1e-13 asserted.
BOOST_AUTO_TEST_CASE(force_from_rotated_vectors_equals_the_rotated_mass_form) {
    const Mat6 Ms = full_mass();
    const InertialState s = moving_state();
    const Mat6 M = form::rotate_mass(Ms, s.Q);
    const Vec3 a = so3::axial(M.bottomLeftCorner<3, 3>());
    const Mat3 rho = M.bottomRightCorner<3, 3>();
    Vec6 acceleration;
    acceleration << s.u_ddot, s.omega_dot;
    Vec6 expected = M * acceleration;
    expected.head<3>() += s.omega.cross(s.omega.cross(a));
    expected.tail<3>() += s.omega.cross(rho * s.omega);
    const Vec6 F = form::calculate_inertial_force(Ms, s);
    BOOST_TEST((F - expected).cwiseAbs().maxCoeff() <= 1e-13 * expected.cwiseAbs().maxCoeff());
    BOOST_TEST((form::calculate_inertial_blocks(Ms, s).F - F).cwiseAbs().maxCoeff() == 0.0);
}

BOOST_AUTO_TEST_CASE(mass_block_matches_fd_in_linear_and_angular_acceleration) {
    const Mat6 Ms = full_mass();
    const InertialState s = moving_state();
    const InertialBlocks b = form::calculate_inertial_blocks(Ms, s);
    const double e_u = fd_error(Ms, s, b.M.leftCols<3>(), along(&InertialState::u_ddot));
    const double e_w = fd_error(Ms, s, b.M.rightCols<3>(), along(&InertialState::omega_dot));
    BOOST_TEST_MESSAGE("M vs FD: " << e_u << " (u¨), " << e_w << " (ω˙)");
    BOOST_TEST(e_u < 1e-7);
    BOOST_TEST(e_w < 1e-7);
}

BOOST_AUTO_TEST_CASE(gyroscopic_block_matches_fd_in_angular_velocity) {
    const Mat6 Ms = full_mass();
    const InertialState s = moving_state();
    const InertialBlocks b = form::calculate_inertial_blocks(Ms, s);
    const double e = fd_error(Ms, s, b.G.rightCols<3>(), along(&InertialState::omega));
    BOOST_TEST_MESSAGE("G vs FD: " << e);
    BOOST_TEST(e < 1e-7);
    BOOST_TEST(b.G.leftCols<3>().isZero(0.0));  // F^I does not depend on the linear velocity
}

BOOST_AUTO_TEST_CASE(inertial_stiffness_matches_fd_in_left_spin_of_the_section) {
    const Mat6 Ms = full_mass();
    const InertialState s = moving_state();
    const InertialBlocks b = form::calculate_inertial_blocks(Ms, s);
    const double e = fd_error(Ms, s, b.K.rightCols<3>(), [](InertialState x, const Vec3& d) {
        x.Q = so3::exp_map(d) * x.Q;
        return x;
    });
    BOOST_TEST_MESSAGE("K^I vs FD: " << e);
    BOOST_TEST(e < 1e-7);
    BOOST_TEST(b.K.leftCols<3>().isZero(0.0));  // F^I does not depend on the position
    // The gyroscopic and stiffness blocks are not symmetric in general: a symmetric solver must
    // not be used on a dynamic tangent (this state shows it).
    BOOST_TEST((b.K - b.K.transpose()).cwiseAbs().maxCoeff() > 1e-3);
}

BOOST_AUTO_TEST_CASE(rotated_mass_is_symmetric_and_keeps_the_section_mass) {
    const InertialState s = moving_state();
    const Mat6 M = form::rotate_mass(full_mass(), s.Q);
    BOOST_TEST((M - M.transpose()).cwiseAbs().maxCoeff() < 1e-14);
    BOOST_TEST(std::abs(M(0, 0) - 2.3) < 1e-14);
    // ρ eigenvalues are invariant under the rotation.
    const Eigen::SelfAdjointEigenSolver<Mat3> a(full_mass().bottomRightCorner<3, 3>());
    const Eigen::SelfAdjointEigenSolver<Mat3> b(M.bottomRightCorner<3, 3>());
    BOOST_TEST((a.eigenvalues() - b.eigenvalues()).cwiseAbs().maxCoeff() < 1e-13);
}

BOOST_AUTO_TEST_SUITE_END()
