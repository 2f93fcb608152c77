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

// The blocks of the material mass M* rotated to inertial axes by Q that F^I reads (every 3×3
// block transforms as Q B Qᵀ): all but the upper right m η̃ᵀ, which only the tangent ∂F/∂(u¨, ω˙)
// holds; that block of M is left as it was.
inline void rotate_mass_force_blocks(const Mat6& M_star, const Mat3& Q, Mat6& M) {
    M.topLeftCorner<3, 3>() = Q * M_star.topLeftCorner<3, 3>() * Q.transpose();
    M.bottomLeftCorner<3, 3>() = Q * M_star.bottomLeftCorner<3, 3>() * Q.transpose();
    M.bottomRightCorner<3, 3>() = Q * M_star.bottomRightCorner<3, 3>() * Q.transpose();
}

// The material mass M* rotated to inertial axes by Q.
inline Mat6 rotate_mass(const Mat6& M_star, const Mat3& Q) {
    Mat6 M;
    rotate_mass_force_blocks(M_star, Q, M);
    M.topRightCorner<3, 3>() = Q * M_star.topRightCorner<3, 3>() * Q.transpose();
    return M;
}

// The terms of F^I at one section, which the tangent blocks reuse: m, a = m η (a_tilde = m η̃ the
// rotated mass's lower-left block), ρ, ω̃, ω˙~, ω˙~ + ω̃ω̃, ρ ω and ρ ω˙.
struct InertialTerms {
    double m = 0.0;
    Mat3 a_tilde, rho, w, wd, wdww;
    Vec3 a, rho_w, rho_wd;
    Vec6 F;  // F^I
};

// From the rotated mass's force blocks (rotate_mass_force_blocks) and the state.
inline InertialTerms inertial_terms(const Mat6& M, const InertialState& s) {
    InertialTerms t;
    t.m = M(0, 0);
    t.a_tilde = M.bottomLeftCorner<3, 3>();
    t.a = so3::axial(t.a_tilde);
    t.rho = M.bottomRightCorner<3, 3>();
    t.w = so3::skew(s.omega);
    t.wd = so3::skew(s.omega_dot);
    t.rho_w = t.rho * s.omega;
    t.rho_wd = t.rho * s.omega_dot;
    t.wdww = t.wd + t.w * t.w;
    t.F.head<3>() = t.m * s.u_ddot + t.wdww * t.a;
    t.F.tail<3>() = t.a_tilde * s.u_ddot + t.rho_wd + t.w * t.rho_w;
    return t;
}

// F^I alone, for a residual without its tangent: the same arithmetic as
// calculate_inertial_blocks(M_star, s).F (the same bits), without the upper-right mass block and
// the blocks G^I, K^I.
inline Vec6 calculate_inertial_force(const Mat6& M_star, const InertialState& s) {
    Mat6 M;
    rotate_mass_force_blocks(M_star, s.Q, M);
    return inertial_terms(M, s).F;
}

// F^I and its three tangent blocks at one section (formulas in the header comment).
inline InertialBlocks calculate_inertial_blocks(const Mat6& M_star, const InertialState& s) {
    InertialBlocks b;
    b.M = rotate_mass(M_star, s.Q);
    const InertialTerms t = inertial_terms(b.M, s);
    const Mat3 ud = so3::skew(s.u_ddot);
    b.F = t.F;
    b.G.topRightCorner<3, 3>() = -so3::skew(t.w * t.a) - t.w * t.a_tilde;
    b.G.bottomRightCorner<3, 3>() = t.w * t.rho - so3::skew(t.rho_w);
    b.K.topRightCorner<3, 3>() = -t.wdww * t.a_tilde;
    b.K.bottomRightCorner<3, 3>() = ud * t.a_tilde + t.rho * t.wd - so3::skew(t.rho_wd) +
                                    t.w * t.rho * t.w - t.w * so3::skew(t.rho_w);
    return b;
}

}  // namespace rotbeam::form
