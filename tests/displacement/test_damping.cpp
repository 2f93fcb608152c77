// Sectional damping forces (formulations/displacement/calculate_damping_forces.hpp): every block of
// F^D1 and F^D2 against central differences at a rotated, moving, strained section with a full
// (coupled) stiffness-proportional damping matrix.
#include <boost/test/unit_test.hpp>

#include "core/so3.hpp"
#include "formulations/displacement/calculate_damping_forces.hpp"

using namespace rotbeam;
using rotbeam::form::DampingBlocks;
using rotbeam::form::DampingState;

namespace {

using Vec12 = Eigen::Matrix<double, 12, 1>;
using Mat12x6 = Eigen::Matrix<double, 12, 6>;

// The primal section variables; DampingState is derived from them as in the element loop.
struct Section {
    Mat3 Q = so3::exp_map(Vec3(-1.1, 0.7, 1.6));  // R R^r, |ψ| ≈ 2.1 rad
    Vec3 b = Vec3(0.9, 0.2, -0.3);                // (R R^r)ᵀ R x⁰′: material, fixed
    Vec3 kappa = Vec3(0.3, -0.5, 0.8);
    Vec3 omega = Vec3(1.2, -0.4, 0.9);
    Vec3 omega_prime = Vec3(-0.6, 0.5, 0.2);
    Vec3 u_dot_prime = Vec3(0.3, 0.8, -0.7);
    Vec3 x_prime = Vec3(1.05, 0.1, -0.2);
};

// μ C* with a full symmetric C* (elastic coupling) and unequal μ.
Mat6 damping_star() {
    Mat6 A;
    A << 4, 1, 0.5, 0.2, -0.3, 0.1, 1, 3, 0.2, 0.1, 0.4, -0.2, 0.5, 0.2, 5, -0.1, 0.2, 0.3, 0.2,
        0.1, -0.1, 2, 0.3, 0.1, -0.3, 0.4, 0.2, 0.3, 2.5, 0.2, 0.1, -0.2, 0.3, 0.1, 0.2, 1.5;
    const Vec6 mu(0.01, 0.02, 0.015, 0.03, 0.025, 0.02);
    return mu.asDiagonal() * A;  // not symmetric: D need not be
}

DampingState state_of(const Section& x) {
    Mat6 T = Mat6::Zero();
    T.topLeftCorner<3, 3>() = x.Q;
    T.bottomRightCorner<3, 3>() = x.Q;
    DampingState s;
    s.D = T * damping_star() * T.transpose();
    s.x_prime = x.x_prime;
    s.Rx0p = x.Q * x.b;
    s.kappa = x.kappa;
    s.omega = x.omega;
    s.omega_prime = x.omega_prime;
    s.u_dot_prime = x.u_dot_prime;
    return s;
}

Vec12 forces(const Section& x) {
    const DampingBlocks b = form::calculate_damping_blocks(state_of(x));
    Vec12 f;
    f << b.F1, b.F2;
    return f;
}

// Central differences (h = 1e-6) of [F^D1; F^D2] along the six directions of one unknown group.
// Truncation h²·O(10) ~ 1e-11, round-off ε·O(1)/h ~ 1e-10; tolerance 1e-7 relative to the
// block's scale (≥ 1) leaves a margin of ~1000, while any wrong term is O(μ) ~ 1e-2.
template <class Perturb>
double fd_error(const Mat12x6& A, const Perturb& perturb) {
    const double h = 1e-6;
    Mat12x6 fd;
    for (int k = 0; k < 6; ++k) {
        Vec6 d = Vec6::Zero();
        d(k) = h;
        fd.col(k) = (forces(perturb(Section{}, d)) - forces(perturb(Section{}, -d))) / (2.0 * h);
    }
    return (fd - A).cwiseAbs().maxCoeff() / std::max(1e-2, A.cwiseAbs().maxCoeff());
}

Mat12x6 stack(const Mat6& a, const Mat6& b) {
    Mat12x6 m;
    m << a, b;
    return m;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(damping)

BOOST_AUTO_TEST_CASE(damping_blocks_in_velocity_gradients_match_fd) {
    const DampingBlocks b = form::calculate_damping_blocks(state_of(Section{}));
    const double e = fd_error(stack(b.D1, b.D2), [](Section x, const Vec6& d) {
        x.u_dot_prime += d.head<3>();
        x.omega_prime += d.tail<3>();
        return x;
    });
    BOOST_TEST_MESSAGE("D^D vs FD: " << e);
    BOOST_TEST(e < 1e-7);
}

BOOST_AUTO_TEST_CASE(damping_gyroscopic_blocks_in_velocities_match_fd) {
    const DampingBlocks b = form::calculate_damping_blocks(state_of(Section{}));
    const double e = fd_error(stack(b.G1, b.G2), [](Section x, const Vec6& d) {
        x.omega += d.tail<3>();  // no dependence on u˙ (its FD columns are zero)
        return x;
    });
    BOOST_TEST_MESSAGE("G^D vs FD: " << e);
    BOOST_TEST(e < 1e-7);
}

BOOST_AUTO_TEST_CASE(damping_blocks_in_displacement_gradients_match_fd) {
    const DampingBlocks b = form::calculate_damping_blocks(state_of(Section{}));
    const double e = fd_error(stack(b.P1, b.P2), [](Section x, const Vec6& d) {
        x.x_prime += d.head<3>();
        x.kappa += d.tail<3>();  // δκ = δθ′ where δθ = 0 at the point: exact
        return x;
    });
    BOOST_TEST_MESSAGE("P^D vs FD: " << e);
    BOOST_TEST(e < 1e-7);
}

BOOST_AUTO_TEST_CASE(damping_stiffness_blocks_in_left_spin_match_fd) {
    const DampingBlocks b = form::calculate_damping_blocks(state_of(Section{}));
    const double e = fd_error(stack(b.K1, b.K2), [](Section x, const Vec6& d) {
        const Mat3 E = so3::exp_map(d.tail<3>());  // uniform spin: κ rotates exactly
        x.Q = E * x.Q;
        x.kappa = E * x.kappa;
        return x;
    });
    BOOST_TEST_MESSAGE("K^D vs FD: " << e);
    BOOST_TEST(e < 1e-7);
}

BOOST_AUTO_TEST_SUITE_END()
