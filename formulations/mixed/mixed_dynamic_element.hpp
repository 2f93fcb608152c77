// The momentum terms of the mixed element (seed 002 Eqs. 45, 46, 49, 50 with the errata of
// docs/benchmarks.md) in closed form and their derivatives with respect to the unknowns X and their
// rates Ẋ. The static part of Eqs. 45–48 is mixed_element.hpp's; the dynamic element adds
// these terms to it.
//
// The frame a of seed 002 is inertial here (ω_a = 0, v = 0); a turning frame adds its terms
// (mixed_frame_terms.hpp). With
// R = R(c) the relative rotation (seed 002's Cᵀ), A = R C^ab the element's total rotation,
// H = H_m(c) the material tangent (seed 002's Q_a, Eq. 24), h = ΔL/2, and the momenta P, H_B in
// deformed-frame components (Eq. 18, missing from the text: {P; H} = I {V; Ω}, I the 6×6 section
// mass in material axes, fully populated; inverted here, so [V; Ω] = I⁻¹ [P; H]):
//
//   inertial part of f_u^∓  = h d/dt(A P)                 (45; the overbar is d/dt, errata)
//   inertial part of f_ψ^∓  = h [d/dt(A H_B) + A (V × P)]  (46)
//   f_P = A V − u̇                                         (49)
//   f_H = Ω − C^ba H ċ                                     (50, "C_ba O_a" read C^ba Q_a)
//
// d/dt(A w) = A ẇ + Ṙ C^ab w and Ṙ C^ab w = −R (C^ab w)~ H ċ (from ∂(R v)/∂c = −R ṽ H). The
// time derivative of the product is taken with ċ itself (not Ω), as the overbar says, so the
// residual is exact for any (X, Ẋ); at a solution f_H = 0 makes the two agree (C^ba H ċ = Ω).
// Both halves f^− and f^+ carry the same inertial term (each half-element's momentum).
//
// Generic in the parameter count K: for the quaternion (K = 4, docs/mixed-formulation.md) H_m is
// 3 × 4 and ċ enters only through H_m ċ, so the radial part of the rate (H_m q = 0) enters nowhere
// and R = C(q)/|q|² needs no unit norm.
#pragma once

#include "core/so3.hpp"
#include "core/types.hpp"
#include "formulations/mixed/mixed_layout.hpp"
#include "parameterizations/concept.hpp"

namespace rotbeam::form {

// Rates of the element unknowns u, c, P, H (the kinematic unknowns F, M have none).
template <int K = 3>
struct MixedElementRates {
    Vec3 u_dot = Vec3::Zero();
    param::Params<K> c_dot = param::Params<K>::Zero();
    Vec3 P_dot = Vec3::Zero();
    Vec3 H_dot = Vec3::Zero();
};

template <int K = 3>
struct MixedInertiaResult {
    Vec3 fu = Vec3::Zero();    // added to f_u^− and f_u^+
    Vec3 fpsi = Vec3::Zero();  // added to f_ψ^− and f_ψ^+
    Vec3 fP = Vec3::Zero();    // Eq. 49
    Vec3 fH = Vec3::Zero();    // Eq. 50
    // Rows [fu; fpsi; fP; fH]; columns [c; P; H] (x) and [u̇; ċ; Ṗ; Ḣ] (xdot).
    Eigen::Matrix<double, 12, K + 6> J_x = Eigen::Matrix<double, 12, K + 6>::Zero();
    Eigen::Matrix<double, 12, K + 9> J_xdot = Eigen::Matrix<double, 12, K + 9>::Zero();
};

// Evaluates the momentum terms of one element. `mass_inverse` is I⁻¹ (material axes of the
// element). Jacobians only when `with_jacobian`.
template <param::RotationParameterization P>
void mixed_element_inertia(const MixedElement& el, const Mat6& mass_inverse,
                           const param::Params<P::kSize>& c, const Vec3& Pm, const Vec3& Hm,
                           const MixedElementRates<P::kSize>& rate, bool with_jacobian,
                           MixedInertiaResult<P::kSize>& out) {
    constexpr int K = P::kSize;
    using Tan = param::Tangent<K>;
    const double h = 0.5 * el.length;
    const Mat3 R = P::matrix(c);
    const Mat3 A = R * el.Cab;
    const Tan Ht = P::material_tangent(c);
    const Vec6 W = mass_inverse * (Vec6() << Pm, Hm).finished();  // [V; Ω], Eq. 18 inverted
    const Vec3 V = W.head<3>();
    const Vec3 Omega = W.tail<3>();
    const Vec3 y = Ht * rate.c_dot;  // Rᵀ Ṙ = ỹ: the relative rotation's material rate
    const Vec3 wP = el.Cab * Pm;
    const Vec3 wH = el.Cab * Hm;
    const Vec3 VxP = V.cross(Pm);
    out.fu = h * (A * rate.P_dot + R * y.cross(wP));  // −R w̃_P y = R ỹ w_P
    out.fpsi = h * (A * rate.H_dot + R * y.cross(wH) + A * VxP);
    out.fP = A * V - rate.u_dot;
    out.fH = Omega - el.Cab.transpose() * y;
    if (!with_jacobian) return;
    const Mat3 ytil = so3::skew(y);
    const Tan D = P::material_tangent_derivative(c, rate.c_dot);  // ∂(H ċ)/∂c
    const Mat3 dV_dP = mass_inverse.topLeftCorner<3, 3>();
    const Mat3 dV_dH = mass_inverse.topRightCorner<3, 3>();
    const Mat3 dW_dP = mass_inverse.bottomLeftCorner<3, 3>();
    const Mat3 dW_dH = mass_inverse.bottomRightCorner<3, 3>();
    const Mat3 Ptil = so3::skew(Pm);
    Eigen::Matrix<double, 12, K + 6>& J = out.J_x;
    // ∂/∂c of R z with z(c): −R z̃ H + R ∂z/∂c. Columns: c (K), P (3), H (3).
    J.template block<3, K>(0, 0) = h * (-R * so3::skew(el.Cab * rate.P_dot) * Ht +
                                        R * so3::skew(wP.cross(y)) * Ht - R * so3::skew(wP) * D);
    J.template block<3, 3>(0, K) = h * R * ytil * el.Cab;
    J.template block<3, 3>(0, K + 3).setZero();
    J.template block<3, K>(3, 0) =
        h * (-R * so3::skew(el.Cab * rate.H_dot) * Ht + R * so3::skew(wH.cross(y)) * Ht -
             R * so3::skew(wH) * D - R * so3::skew(el.Cab * VxP) * Ht);
    J.template block<3, 3>(3, K) = h * A * (so3::skew(V) - Ptil * dV_dP);
    J.template block<3, 3>(3, K + 3) = h * (R * ytil * el.Cab - A * Ptil * dV_dH);
    J.template block<3, K>(6, 0) = -R * so3::skew(el.Cab * V) * Ht;
    J.template block<3, 3>(6, K) = A * dV_dP;
    J.template block<3, 3>(6, K + 3) = A * dV_dH;
    J.template block<3, K>(9, 0) = -el.Cab.transpose() * D;
    J.template block<3, 3>(9, K) = dW_dP;
    J.template block<3, 3>(9, K + 3) = dW_dH;
    // Columns of ∂/∂Ẋ: u̇ (3), ċ (K), Ṗ (3), Ḣ (3).
    Eigen::Matrix<double, 12, K + 9>& Kd = out.J_xdot;
    Kd.setZero();
    Kd.template block<3, K>(0, 3) = -h * R * so3::skew(wP) * Ht;
    Kd.template block<3, 3>(0, 3 + K) = h * A;
    Kd.template block<3, K>(3, 3) = -h * R * so3::skew(wH) * Ht;
    Kd.template block<3, 3>(3, 6 + K) = h * A;
    Kd.template block<3, 3>(6, 0) = -Mat3::Identity();
    Kd.template block<3, K>(9, 3) = -el.Cab.transpose() * Ht;
}

}  // namespace rotbeam::form
