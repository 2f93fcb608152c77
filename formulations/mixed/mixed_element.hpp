// The static element equations of the mixed formulation in closed form: seed 002 Eqs. (45)–(48)
// without momentum terms, with the errata of docs/benchmarks.md (f_F^∓ = ∓… read f_F^± = ±u_i − …,
// f_M^± = ±c_i − …, consistent with Eqs. 33, 37), and their derivatives, for K = P::kSize rotation
// parameters.
//
// Notation (docs/architecture.md): R = R(c) is the relative rotation (material → inertial, seed
// 002's Cᵀ), A = R C^ab the total rotation of the element (seed 002's Cᵀ C^ab), H = H_m(c) the
// material tangent (seed 002's Q, Eq. 24, 3 × K), H⁻¹ its (right) inverse (Eq. 25; K × 3).
// [γ; κ] = S [F; M] (Eq. 19 inverted: the compliance may have zero rows, rigid modes). e = e1 + γ.
//
//   f_u^∓ = ∓A F − f̄^∓                                  (45)
//   f_ψ^∓ = ∓A M − (ΔL/2) A (e × F) − m̄^∓                (46)
//   f_F^± = ±u − (ΔL/2) (A e − C^ab e1)                 (47), (ΔL/2) C^ab e1 = Δr/2 (the chord)
//   f_M^± = ±c − (ΔL/2) H⁻¹ C^ab κ                       (48), K rows per side, using
//                                                             Q_a⁻¹ C^ab = C^ab Q⁻¹ C^ba C^ab
//
// Loads (Eqs. 51–54) are constant per unit length over the element: f̄^∓ = (ΔL/2) f, m̄^∓ = (ΔL/2) m
// with f = f_dead + R f_follower (a follower load turns with the element's relative rotation).
// Derivatives use ∂(R w)/∂c = −R w̃ H (since Rᵀ δR = (H δc)~).
//
// The quaternion (K = 4, docs/mixed-formulation.md): H⁻¹ is the right inverse H_m⁺(q) = Gᵀ(q)/2,
// H_m⁺ a = ½ q ⊗ (0, a), so (48) is the midpoint form of q′ = ½ q ⊗ κ̄ (norm-preserving:
// mixed_layout.hpp). R(q) = C(q)/|q|² is homogeneous of degree 0 (quaternion.hpp Q1) and
// H_m(q) = 2G/|q|² its exact tangent, also off the unit sphere, so ∂(R w)/∂q = −R w̃ H_m holds at
// every q ≠ 0 and the element never normalizes. Everything goes through the parameterization
// (matrix, material_tangent, material_tangent_inverse and its derivative).
#pragma once

#include "core/so3.hpp"
#include "core/types.hpp"
#include "formulations/mixed/mixed_layout.hpp"
#include "parameterizations/concept.hpp"

namespace rotbeam::form {

template <int K = 3>
struct MixedElementState {
    Vec3 u = Vec3::Zero();
    param::Params<K> c = param::Params<K>::Zero();  // rotation parameters
    Vec3 F = Vec3::Zero();                          // B-frame components
    Vec3 M = Vec3::Zero();
};

template <int K = 3>
struct MixedElementResult {
    static constexpr int kRows = 6 + 2 * K;  // f_F^−, f_M^−, f_F^+, f_M^+
    static constexpr int kCols = 9 + K;      // u, q, F, M
    // Rows: f_u^−, f_ψ^− (to the start node's equilibrium), f_u^+, f_ψ^+ (end node).
    Vec3 fu_minus, fpsi_minus, fu_plus, fpsi_plus;
    // Kinematic rows of the element, without the node terms ∓û, ∓ĉ: f_F^−, f_M^−, f_F^+, f_M^+.
    Eigen::Matrix<double, kRows, 1> kinematic;
    // ∂[f_u^∓; f_ψ^∓]/∂[c; F; M] (the u column is zero).
    Eigen::Matrix<double, 6, 6 + K> J_minus, J_plus;
    // ∂ kinematic / ∂[u; c; F; M].
    Eigen::Matrix<double, kRows, kCols> J_kinematic;
};

// ∂[f_u^∓; f_ψ^∓]/∂[c; F; M] (Eqs. 45–46) with ∂(R w)/∂c = −R w̃ H_m.
template <param::RotationParameterization P>
void mixed_equilibrium_jacobian(const MixedElement& el, const MixedElementState<P::kSize>& x,
                                const Mat3& R, const Vec3& e, const Vec3& g, double lambda,
                                MixedElementResult<P::kSize>& out) {
    constexpr int K = P::kSize;
    using Tan = param::Tangent<K>;
    const double h = 0.5 * el.length;
    const Mat3 A = R * el.Cab;
    const Tan H = P::material_tangent(x.c);
    const Tan dAF_dc = -R * so3::skew(el.Cab * x.F) * H;
    const Tan dAM_dc = -R * so3::skew(el.Cab * x.M) * H;
    const Tan dload_dc = h * lambda * R * so3::skew(el.f_follower) * H;   // −∂f̄/∂c
    const Tan dmload_dc = h * lambda * R * so3::skew(el.m_follower) * H;  // −∂m̄/∂c
    const Tan darm_dc = h * R * so3::skew(el.Cab * g) * H;                // −∂(h A g)/∂c
    const Mat3 Ftil = so3::skew(x.F);
    const Mat3 darm_dF = -h * A * (so3::skew(e) - Ftil * el.S.topLeftCorner<3, 3>());
    const Mat3 darm_dM = h * A * Ftil * el.S.topRightCorner<3, 3>();
    for (int side = 0; side < 2; ++side) {
        const double s = side == 0 ? -1.0 : 1.0;  // f^− carries −A F, f^+ carries +A F
        Eigen::Matrix<double, 6, 6 + K>& J = side == 0 ? out.J_minus : out.J_plus;
        J.template block<3, K>(0, 0) = s * dAF_dc + dload_dc;
        J.template block<3, 3>(0, K) = s * A;
        J.template block<3, 3>(0, K + 3).setZero();
        J.template block<3, K>(3, 0) = s * dAM_dc + darm_dc + dmload_dc;
        J.template block<3, 3>(3, K) = darm_dF;
        J.template block<3, 3>(3, K + 3) = s * A + darm_dM;
    }
}

// ∂[f_F^−; f_M^−; f_F^+; f_M^+]/∂[u; c; F; M] (Eqs. 47–48).
template <param::RotationParameterization P>
void mixed_kinematic_jacobian(const MixedElement& el, const MixedElementState<P::kSize>& x,
                              const Mat3& R, const Vec3& e, const Vec3& Cab_kappa,
                              MixedElementResult<P::kSize>& out) {
    constexpr int K = P::kSize;
    const double h = 0.5 * el.length;
    const Mat3 A = R * el.Cab;
    const param::TangentInverse<K> Hinv = P::material_tangent_inverse(x.c);
    const param::Tangent<K> dstretch_dc = -h * R * so3::skew(el.Cab * e) * P::material_tangent(x.c);
    const Mat3 dstretch_dF = h * A * el.S.topLeftCorner<3, 3>();
    const Mat3 dstretch_dM = h * A * el.S.topRightCorner<3, 3>();
    const Eigen::Matrix<double, K, K> dtwist_dc =
        h * P::material_tangent_inverse_derivative(x.c, Cab_kappa);
    const param::TangentInverse<K> dtwist_dF = h * Hinv * el.Cab * el.S.bottomLeftCorner<3, 3>();
    const param::TangentInverse<K> dtwist_dM = h * Hinv * el.Cab * el.S.bottomRightCorner<3, 3>();
    auto& J = out.J_kinematic;
    for (int side = 0; side < 2; ++side) {
        const double s = side == 0 ? 1.0 : -1.0;  // f^− carries +u, +c (errata)
        const int r = (3 + K) * side;
        J.template block<3, 3>(r, 0) = s * Mat3::Identity();
        J.template block<3, K>(r, 3) = -dstretch_dc;
        J.template block<3, 3>(r, 3 + K) = -dstretch_dF;
        J.template block<3, 3>(r, 6 + K) = -dstretch_dM;
        J.template block<K, 3>(r + 3, 0).setZero();
        J.template block<K, K>(r + 3, 3) = s * Eigen::Matrix<double, K, K>::Identity() - dtwist_dc;
        J.template block<K, 3>(r + 3, 3 + K) = -dtwist_dF;
        J.template block<K, 3>(r + 3, 6 + K) = -dtwist_dM;
    }
}

// Evaluates the element's static equations at load factor `lambda`; the Jacobian blocks only
// when `with_jacobian`.
template <param::RotationParameterization P>
void mixed_element_statics(const MixedElement& el, const MixedElementState<P::kSize>& x,
                           double lambda, bool with_jacobian, MixedElementResult<P::kSize>& out) {
    const double h = 0.5 * el.length;
    const Mat3 R = P::matrix(x.c);  // for the quaternion C(q)/|q|², homogeneous
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
    const param::Params<P::kSize> twist = h * (P::material_tangent_inverse(x.c) * Cab_kappa);
    out.fu_minus = -AF - f_load;
    out.fu_plus = AF - f_load;
    out.fpsi_minus = -AM - moment_arm - m_load;
    out.fpsi_plus = AM - moment_arm - m_load;
    out.kinematic << x.u - stretch, x.c - twist, -x.u - stretch, -x.c - twist;
    if (!with_jacobian) return;
    mixed_equilibrium_jacobian<P>(el, x, R, e, g, lambda, out);
    mixed_kinematic_jacobian<P>(el, x, R, e, Cab_kappa, out);
}

}  // namespace rotbeam::form
