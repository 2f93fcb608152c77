// Sectional inertial forces of the displacement formulation and their tangent blocks (seed 000,
// inertial force Eq. for F^I with the mass matrix M, gyroscopic G^I and inertial stiffness K^I).
//
// State at a quadrature point (all in inertial axes): linear acceleration u¨, angular velocity ω,
// angular acceleration ω˙, and the section rotation Q (material → inertial). The material mass
// M* = [m I, m η̃*ᵀ; m η̃*, ρ*] is rotated: η = Q η*, ρ = Q ρ* Qᵀ.
//   F^I = [ m u¨ + (ω˙~ + ω̃ω̃) m η ;  m η̃ u¨ + ρ ω˙ + ω̃ ρ ω ].
// Tangents, with the rotation perturbed on the left, Q → exp(δθ̃) Q (the spatial spin unknown of
// the displacement formulation), so that a := m η → a + δθ × a and ρ → ρ + δθ̃ ρ − ρ δθ̃:
//   ∂F/∂(u¨, ω˙) = M (rotated 6×6 mass),
//   G^I = ∂F/∂(u˙, ω) = [0, −(ω̃ a)~ − ω̃ ã ; 0, ω̃ ρ − (ρ ω)~],
//   K^I = ∂F/∂(u, δθ) = [0, −(ω˙~ + ω̃ω̃) ã ; 0, ũ¨ ã + ρ ω˙~ − (ρ ω˙)~ + ω̃ ρ ω̃ − ω̃ (ρ ω)~].
// The printed seed-000 blocks are written with the same structure; here every block was derived
// from F^I directly and is checked against central differences
// (tests/displacement/test_inertia.cpp) — finite differences are the arbiter (docs/benchmarks.md
// §Errata). Header-only, fixed-size, no heap.
#pragma once

#include "core/so3.hpp"
#include "core/types.hpp"

namespace rotbeam::form {

struct InertialState {
    Vec3 u_ddot = Vec3::Zero();     // linear acceleration (inertial axes)
    Vec3 omega = Vec3::Zero();      // angular velocity (inertial axes)
    Vec3 omega_dot = Vec3::Zero();  // angular acceleration (inertial axes)
    Mat3 Q = Mat3::Identity();      // section rotation, material → inertial
};

struct InertialBlocks {
    Vec6 F = Vec6::Zero();  // F^I
    Mat6 M = Mat6::Zero();  // rotated mass
    Mat6 G = Mat6::Zero();  // gyroscopic ∂F/∂(u˙, ω)
    Mat6 K = Mat6::Zero();  // inertial stiffness ∂F/∂(u, δθ)
};

// The material mass M* rotated to inertial axes by Q (every 3×3 block transforms as Q B Qᵀ).
inline Mat6 rotate_mass(const Mat6& M_star, const Mat3& Q) {
    Mat6 M;
    M.topLeftCorner<3, 3>() = Q * M_star.topLeftCorner<3, 3>() * Q.transpose();
    M.topRightCorner<3, 3>() = Q * M_star.topRightCorner<3, 3>() * Q.transpose();
    M.bottomLeftCorner<3, 3>() = Q * M_star.bottomLeftCorner<3, 3>() * Q.transpose();
    M.bottomRightCorner<3, 3>() = Q * M_star.bottomRightCorner<3, 3>() * Q.transpose();
    return M;
}

// F^I and its three tangent blocks at one section (formulas in the header comment).
inline InertialBlocks calculate_inertial_blocks(const Mat6& M_star, const InertialState& s) {
    InertialBlocks b;
    b.M = rotate_mass(M_star, s.Q);
    const double m = b.M(0, 0);
    // m η̃ is the lower-left block of the rotated mass; a = m η is its axial vector.
    const Mat3 a_tilde = b.M.bottomLeftCorner<3, 3>();
    const Vec3 a = so3::axial(a_tilde);
    const Mat3 rho = b.M.bottomRightCorner<3, 3>();
    const Mat3 w = so3::skew(s.omega);
    const Mat3 wd = so3::skew(s.omega_dot);
    const Mat3 ud = so3::skew(s.u_ddot);
    const Vec3 rho_w = rho * s.omega;
    const Vec3 rho_wd = rho * s.omega_dot;
    const Mat3 wdww = wd + w * w;
    b.F.head<3>() = m * s.u_ddot + wdww * a;
    b.F.tail<3>() = a_tilde * s.u_ddot + rho_wd + w * rho_w;
    b.G.topRightCorner<3, 3>() = -so3::skew(w * a) - w * a_tilde;
    b.G.bottomRightCorner<3, 3>() = w * rho - so3::skew(rho_w);
    b.K.topRightCorner<3, 3>() = -wdww * a_tilde;
    b.K.bottomRightCorner<3, 3>() =
        ud * a_tilde + rho * wd - so3::skew(rho_wd) + w * rho * w - w * so3::skew(rho_w);
    return b;
}

}  // namespace rotbeam::form
