// The terms of a turning frame a in the mixed element (seed 002 Eqs. 45, 46, 49, 50 with ω_a ≠ 0
// and v_i ≠ 0; docs/rotating-frame.md, "Mixed formulation"), added to the momentum terms of
// mixed_dynamic_element.hpp.
//
// Frame a turns at constant angular velocity Ω (its own components, which equal the inertial
// ones at t = 0 and stay constant because Q(t) = exp(t Ω̃) fixes Ω) about the axis through c. The
// unknowns u, c are the motion relative to frame a in its axes; V, Ω_B (and so P, H) are the
// absolute velocities in the deformed section's axes. With A = R C^ab, h = ΔL/2 and the velocity of
// frame a at the element's reference mid-point v_i = Ω × (x^r_i − c):
//
//   f_u^∓  += h Ω̃ A P                       (45: ω̃_a C^T C^ab P)
//   f_ψ^∓  += h Ω̃ A H                       (46: ω̃_a C^T C^ab H)
//   f_P    −= Ω × (x^r_i + u_i − c)          (49: − v_i − ω̃_a u_i)
//   f_H    −= Aᵀ Ω                           (50: − C^ba C ω_a, ω_B)
//
// At rest in the frame (u̇ = ċ = 0, steady P, H) the first two are the centrifugal force
// m Ω × (Ω × r) and the gyroscopic moment Ω × (A ρ Aᵀ Ω) of the statics' F^I
// (calculate_rotating_frame_forces.hpp); in motion the Coriolis force comes through A P, whose
// V holds Ω × r + u̇. Derivatives (∂(R v)/∂c = −R ṽ H_m, ∂(Rᵀ w)/∂c = (Rᵀ w)~ H_m):
//
//   ∂f_u/∂c = −h Ω̃ R (C^ab P)~ H_m,   ∂f_u/∂P = h Ω̃ A,
//   ∂f_ψ/∂c = −h Ω̃ R (C^ab H)~ H_m,   ∂f_ψ/∂H = h Ω̃ A,
//   ∂f_P/∂u = −Ω̃,                      ∂f_H/∂c = −C^ba (Rᵀ Ω)~ H_m.
//
// None of them holds a rate: ∂/∂Ẋ is unchanged.
#pragma once

#include "core/so3.hpp"
#include "core/types.hpp"
#include "formulations/mixed/mixed_dynamic_element.hpp"
#include "formulations/mixed/mixed_layout.hpp"
#include "parameterizations/concept.hpp"

namespace rotbeam::form {

template <int K = 3>
struct MixedFrameResult {
    Vec3 fu = Vec3::Zero();    // added to f_u^− and f_u^+
    Vec3 fpsi = Vec3::Zero();  // added to f_ψ^− and f_ψ^+
    Vec3 fP = Vec3::Zero();    // added to Eq. 49
    Vec3 fH = Vec3::Zero();    // added to Eq. 50
    // Rows [fu; fpsi; fP; fH]; columns [u; c; P; H].
    Eigen::Matrix<double, 12, K + 9> J_x = Eigen::Matrix<double, 12, K + 9>::Zero();
};

// `r` is the element's mid-point position relative to the axis point, x^r_i + u_i − c, in the
// frame's axes; `omega` the frame's angular velocity. Jacobian only when `with_jacobian`.
template <param::RotationParameterization P>
void mixed_element_frame_terms(const MixedElement& el, const Vec3& omega, const Vec3& r,
                               const param::Params<P::kSize>& c, const Vec3& Pm, const Vec3& Hm,
                               bool with_jacobian, MixedFrameResult<P::kSize>& out) {
    constexpr int K = P::kSize;
    const double h = 0.5 * el.length;
    const Mat3 R = P::matrix(c);
    const Mat3 A = R * el.Cab;
    const Mat3 W = so3::skew(omega);
    out.fu = h * (W * (A * Pm));
    out.fpsi = h * (W * (A * Hm));
    out.fP = -(W * r);
    const Vec3 omega_R = R.transpose() * omega;
    out.fH = -(el.Cab.transpose() * omega_R);
    if (!with_jacobian) return;
    const param::Tangent<K> Ht = P::material_tangent(c);
    Eigen::Matrix<double, 12, K + 9>& J = out.J_x;
    J.setZero();
    J.template block<3, K>(0, 3) = -h * W * R * so3::skew(el.Cab * Pm) * Ht;
    J.template block<3, 3>(0, 3 + K) = h * W * A;
    J.template block<3, K>(3, 3) = -h * W * R * so3::skew(el.Cab * Hm) * Ht;
    J.template block<3, 3>(3, 6 + K) = h * W * A;
    J.template block<3, 3>(6, 0) = -W;
    J.template block<3, K>(9, 3) = -el.Cab.transpose() * so3::skew(omega_R) * Ht;
}

}  // namespace rotbeam::form
