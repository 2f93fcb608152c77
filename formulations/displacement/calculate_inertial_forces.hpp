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

// F^I from rotated vectors, without the rotated mass: a = m η = Q (m η*) (m η* the axial vector
// of M*'s lower-left block m η̃*), ρ ω = Q ρ* Qᵀ ω and ρ ω˙ likewise; ã u¨ = a × u¨. Three
// products of Q with a vector and two of Qᵀ instead of three Q B Qᵀ: the residual's inertial
// term costs about a third of the rotated-mass form. The tangent's F (calculate_inertial_blocks)
// is this one, so a residual is the same to the bit with or without its tangent.
inline Vec6 calculate_inertial_force(const Mat6& M_star, const InertialState& s) {
    const Mat3 Qt = s.Q.transpose();
    const Vec3 a = s.Q * so3::axial(M_star.bottomLeftCorner<3, 3>());
    const Vec3 w_star = Qt * s.omega;
    const Vec3 wd_star = Qt * s.omega_dot;
    const Vec3 rho_w = s.Q * (M_star.bottomRightCorner<3, 3>() * w_star);
    const Vec3 rho_wd = s.Q * (M_star.bottomRightCorner<3, 3>() * wd_star);
    Vec6 F;
    F.head<3>() = M_star(0, 0) * s.u_ddot + s.omega_dot.cross(a) + s.omega.cross(s.omega.cross(a));
    F.tail<3>() = a.cross(s.u_ddot) + rho_wd + s.omega.cross(rho_w);
    return F;
}

// The terms of the tangent blocks at one section: a = m η (a_tilde = m η̃ the rotated mass's
// lower-left block), ρ, ω̃, ω˙~, ω˙~ + ω̃ω̃, ρ ω and ρ ω˙.
struct InertialTerms {
    Mat3 a_tilde, rho, w, wd, wdww;
    Vec3 a, rho_w, rho_wd;
};

// From the rotated mass and the state.
inline InertialTerms inertial_terms(const Mat6& M, const InertialState& s) {
    InertialTerms t;
    t.a_tilde = M.bottomLeftCorner<3, 3>();
    t.a = so3::axial(t.a_tilde);
    t.rho = M.bottomRightCorner<3, 3>();
    t.w = so3::skew(s.omega);
    t.wd = so3::skew(s.omega_dot);
    t.rho_w = t.rho * s.omega;
    t.rho_wd = t.rho * s.omega_dot;
    t.wdww = t.wd + t.w * t.w;
    return t;
}

// F^I and its three tangent blocks at one section (formulas in the header comment).
inline InertialBlocks calculate_inertial_blocks(const Mat6& M_star, const InertialState& s) {
    InertialBlocks b;
    b.M = rotate_mass(M_star, s.Q);
    const InertialTerms t = inertial_terms(b.M, s);
    const Mat3 ud = so3::skew(s.u_ddot);
    b.F = calculate_inertial_force(M_star, s);
    b.G.topRightCorner<3, 3>() = -so3::skew(t.w * t.a) - t.w * t.a_tilde;
    b.G.bottomRightCorner<3, 3>() = t.w * t.rho - so3::skew(t.rho_w);
    b.K.topRightCorner<3, 3>() = -t.wdww * t.a_tilde;
    b.K.bottomRightCorner<3, 3>() = ud * t.a_tilde + t.rho * t.wd - so3::skew(t.rho_wd) +
                                    t.w * t.rho * t.w - t.w * so3::skew(t.rho_w);
    return b;
}

}  // namespace rotbeam::form
