// The static element equations of the mixed formulation with four rotation unknowns (the
// quaternion): seed 002 Eqs. (45)–(47) as in mixed_element.hpp, and Eq. (48) in
// four components with the right inverse of the material tangent (docs/architecture.md):
//
//   f_M^± = ±q − (ΔL/2) H_m⁺(q) C^ab κ            (48), four rows per side
//
// For the quaternion H_m⁺(q) = Gᵀ(q)/2, so H_m⁺ a = ½ q ⊗ (0, a) and (48) is the midpoint form of
// q′ = ½ q ⊗ κ̄ (norm-preserving: mixed_quaternion_layout.hpp). R(q) = C(q)/|q|² is homogeneous of
// degree 0 (quaternion.hpp Q1), H_m(q) = 2G/|q|² its exact tangent, also off the unit sphere, so
// ∂(R w)/∂q = −R w̃ H_m holds at every q ≠ 0 and the element never normalizes.
//
// Everything goes through the parameterization (matrix, material_tangent, material_tangent_inverse
// and its derivative); this header is generic in P::kSize but only the quaternion uses it. It
// repeats the equilibrium blocks of mixed_element.hpp with a 3 × kSize tangent rather than
// templating that header's fixed 3 × 3 types, which the dynamics work builds on.
#pragma once

#include "core/so3.hpp"
#include "core/types.hpp"
#include "formulations/mixed/mixed_layout.hpp"
#include "parameterizations/concept.hpp"

namespace rotbeam::form {

template <int K>
struct MixedHomogeneousState {
    Vec3 u = Vec3::Zero();
    param::Params<K> q = param::Params<K>::Zero();
    Vec3 F = Vec3::Zero();  // B-frame components
    Vec3 M = Vec3::Zero();
};

template <int K>
struct MixedHomogeneousResult {
    static constexpr int kRows = 6 + 2 * K;  // f_F^−, f_M^−, f_F^+, f_M^+
    static constexpr int kCols = 9 + K;      // u, q, F, M
    Vec3 fu_minus, fpsi_minus, fu_plus, fpsi_plus;
    // Kinematic rows without the node terms ∓û, ∓q̂.
    Eigen::Matrix<double, kRows, 1> kinematic;
    // ∂[f_u^∓; f_ψ^∓]/∂[q; F; M] (the u column is zero).
    Eigen::Matrix<double, 6, 6 + K> J_minus, J_plus;
    // ∂ kinematic / ∂[u; q; F; M].
    Eigen::Matrix<double, kRows, kCols> J_kinematic;
};

// ∂[f_u^∓; f_ψ^∓]/∂[q; F; M] (Eqs. 45–46) with ∂(R w)/∂q = −R w̃ H_m.
template <param::RotationParameterization P>
void mixed_homogeneous_equilibrium_jacobian(const MixedElement& el,
                                            const MixedHomogeneousState<P::kSize>& x, const Mat3& R,
                                            const Vec3& e, const Vec3& g, double lambda,
                                            MixedHomogeneousResult<P::kSize>& out) {
    constexpr int K = P::kSize;
    using Tan = param::Tangent<K>;
    const double h = 0.5 * el.length;
    const Mat3 A = R * el.Cab;
    const Tan H = P::material_tangent(x.q);
    const Tan dAF_dq = -R * so3::skew(el.Cab * x.F) * H;
    const Tan dAM_dq = -R * so3::skew(el.Cab * x.M) * H;
    const Tan dload_dq = h * lambda * R * so3::skew(el.f_follower) * H;   // −∂f̄/∂q
    const Tan dmload_dq = h * lambda * R * so3::skew(el.m_follower) * H;  // −∂m̄/∂q
    const Tan darm_dq = h * R * so3::skew(el.Cab * g) * H;                // −∂(h A g)/∂q
    const Mat3 Ftil = so3::skew(x.F);
    const Mat3 darm_dF = -h * A * (so3::skew(e) - Ftil * el.S.topLeftCorner<3, 3>());
    const Mat3 darm_dM = h * A * Ftil * el.S.topRightCorner<3, 3>();
    for (int side = 0; side < 2; ++side) {
        const double s = side == 0 ? -1.0 : 1.0;  // f^− carries −A F, f^+ carries +A F
        Eigen::Matrix<double, 6, 6 + K>& J = side == 0 ? out.J_minus : out.J_plus;
        J.template block<3, K>(0, 0) = s * dAF_dq + dload_dq;
        J.template block<3, 3>(0, K) = s * A;
        J.template block<3, 3>(0, K + 3).setZero();
        J.template block<3, K>(3, 0) = s * dAM_dq + darm_dq + dmload_dq;
        J.template block<3, 3>(3, K) = darm_dF;
        J.template block<3, 3>(3, K + 3) = s * A + darm_dM;
    }
}

// ∂[f_F^−; f_M^−; f_F^+; f_M^+]/∂[u; q; F; M] (Eqs. 47–48).
template <param::RotationParameterization P>
void mixed_homogeneous_kinematic_jacobian(const MixedElement& el,
                                          const MixedHomogeneousState<P::kSize>& x, const Mat3& R,
                                          const Vec3& e, const Vec3& Cab_kappa,
                                          MixedHomogeneousResult<P::kSize>& out) {
    constexpr int K = P::kSize;
    const double h = 0.5 * el.length;
    const Mat3 A = R * el.Cab;
    const param::TangentInverse<K> Hinv = P::material_tangent_inverse(x.q);
    const param::Tangent<K> dstretch_dq = -h * R * so3::skew(el.Cab * e) * P::material_tangent(x.q);
    const Mat3 dstretch_dF = h * A * el.S.topLeftCorner<3, 3>();
    const Mat3 dstretch_dM = h * A * el.S.topRightCorner<3, 3>();
    const Eigen::Matrix<double, K, K> dtwist_dq =
        h * P::material_tangent_inverse_derivative(x.q, Cab_kappa);
    const param::TangentInverse<K> dtwist_dF = h * Hinv * el.Cab * el.S.bottomLeftCorner<3, 3>();
    const param::TangentInverse<K> dtwist_dM = h * Hinv * el.Cab * el.S.bottomRightCorner<3, 3>();
    auto& J = out.J_kinematic;
    for (int side = 0; side < 2; ++side) {
        const double s = side == 0 ? 1.0 : -1.0;  // f^− carries +u, +q (errata)
        const int r = (3 + K) * side;
        J.template block<3, 3>(r, 0) = s * Mat3::Identity();
        J.template block<3, K>(r, 3) = -dstretch_dq;
        J.template block<3, 3>(r, 3 + K) = -dstretch_dF;
        J.template block<3, 3>(r, 6 + K) = -dstretch_dM;
        J.template block<K, 3>(r + 3, 0).setZero();
        J.template block<K, K>(r + 3, 3) = s * Eigen::Matrix<double, K, K>::Identity() - dtwist_dq;
        J.template block<K, 3>(r + 3, 3 + K) = -dtwist_dF;
        J.template block<K, 3>(r + 3, 6 + K) = -dtwist_dM;
    }
}

// Evaluates the element's static equations at load factor `lambda`; the Jacobian blocks only
// when `with_jacobian`.
template <param::RotationParameterization P>
void mixed_homogeneous_element_statics(const MixedElement& el,
                                       const MixedHomogeneousState<P::kSize>& x, double lambda,
                                       bool with_jacobian, MixedHomogeneousResult<P::kSize>& out) {
    const double h = 0.5 * el.length;
    const Mat3 R = P::matrix(x.q);  // C(q)/|q|², homogeneous
    const Mat3 A = R * el.Cab;
    const Vec6 strain = el.S * (Vec6() << x.F, x.M).finished();  // Eq. 19 inverted
    const Vec3 e = Vec3::UnitX() + strain.head<3>();
    const Vec3 g = e.cross(x.F);
    const Vec3 Cab_kappa = el.Cab * strain.tail<3>();
    const Vec3 AF = A * x.F;
    const Vec3 AM = A * x.M;
    const Vec3 f_load = h * lambda * (el.f_dead + R * el.f_follower);
    const Vec3 m_load = h * lambda * (el.m_dead + R * el.m_follower);
    const Vec3 moment_arm = h * (A * g);
    const Vec3 stretch = h * (A * e) - 0.5 * el.chord;  // h (A e − C^ab e1)
    const param::Params<P::kSize> twist = h * (P::material_tangent_inverse(x.q) * Cab_kappa);
    out.fu_minus = -AF - f_load;
    out.fu_plus = AF - f_load;
    out.fpsi_minus = -AM - moment_arm - m_load;
    out.fpsi_plus = AM - moment_arm - m_load;
    out.kinematic << x.u - stretch, x.q - twist, -x.u - stretch, -x.q - twist;
    if (!with_jacobian) return;
    mixed_homogeneous_equilibrium_jacobian<P>(el, x, R, e, g, lambda, out);
    mixed_homogeneous_kinematic_jacobian<P>(el, x, R, e, Cab_kappa, out);
}

}  // namespace rotbeam::form
