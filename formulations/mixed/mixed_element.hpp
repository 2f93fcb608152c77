// The static element equations of the mixed formulation in closed form: seed 002 Eqs. (45)–(48)
// without momentum terms, with the errata of docs/benchmarks.md (f_F^∓ = ∓… read f_F^± = ±u_i − …,
// f_M^± = ±c_i − …, consistent with Eqs. 33, 37), and their derivatives.
//
// Notation (docs/architecture.md): R = R(c) is the relative rotation (material → inertial, seed
// 002's Cᵀ), A = R C^ab the total rotation of the element (seed 002's Cᵀ C^ab), H = H_m(c) the
// material tangent (seed 002's Q, Eq. 24), H⁻¹ its inverse (Eq. 25). [γ; κ] = S [F; M] (Eq. 19
// inverted: the compliance may have zero rows, rigid modes). e = e1 + γ.
//
//   f_u^∓ = ∓A F − f̄^∓                                  (45)
//   f_ψ^∓ = ∓A M − (ΔL/2) A (e × F) − m̄^∓                (46)
//   f_F^± = ±u − (ΔL/2) (A e − C^ab e1)                 (47), (ΔL/2) C^ab e1 = Δr/2 (the chord)
//   f_M^± = ±c − (ΔL/2) H⁻¹ C^ab κ                       (48), using Q_a⁻¹ C^ab = C^ab Q⁻¹ C^ba
//   C^ab
//
// Loads (Eqs. 51–54) are constant per unit length over the element: f̄^∓ = (ΔL/2) f, m̄^∓ = (ΔL/2) m
// with f = f_dead + R f_follower (a follower load turns with the element's relative rotation).
// Derivatives use ∂(R w)/∂c = −R w̃ H (since Rᵀ δR = (H δc)~).
#pragma once

#include "core/so3.hpp"
#include "core/types.hpp"
#include "formulations/mixed/mixed_layout.hpp"
#include "parameterizations/concept.hpp"

namespace rotbeam::form {

using Mat3x9 = Eigen::Matrix<double, 3, 9>;
using Mat12 = Eigen::Matrix<double, 12, 12>;

struct MixedElementState {
    Vec3 u = Vec3::Zero();
    Vec3 c = Vec3::Zero();
    Vec3 F = Vec3::Zero();  // B-frame components
    Vec3 M = Vec3::Zero();
};

struct MixedElementResult {
    // Rows: f_u^−, f_ψ^− (to the start node's equilibrium), f_u^+, f_ψ^+ (end node).
    Vec3 fu_minus, fpsi_minus, fu_plus, fpsi_plus;
    // Kinematic rows of the element, without the node terms ∓û, ∓ĉ: f_F^−, f_M^−, f_F^+, f_M^+.
    Eigen::Matrix<double, 12, 1> kinematic;
    // ∂[f_u^∓; f_ψ^∓]/∂[c; F; M] (the u column is zero).
    Eigen::Matrix<double, 6, 9> J_minus, J_plus;
    // ∂ kinematic / ∂[u; c; F; M].
    Mat12 J_kinematic;
};

// Quantities of one element state shared by the residual and the Jacobian.
struct MixedElementKinematics {
    double h = 0.0;  // ΔL/2
    Mat3 R, A, Hinv;
    Vec3 e, kappa, g, Cab_kappa;  // e1 + γ, κ, e × F, C^ab κ
};

template <param::RotationParameterization P>
MixedElementKinematics mixed_element_kinematics(const MixedElement& el,
                                                const MixedElementState& x) {
    static_assert(P::kSize == 3, "the additive mixed kinematics need three rotation parameters");
    MixedElementKinematics k;
    k.h = 0.5 * el.length;
    k.R = P::matrix(x.c);
    k.A = k.R * el.Cab;
    k.Hinv = P::material_tangent_inverse(x.c);
    const Vec6 strain = el.S * (Vec6() << x.F, x.M).finished();  // Eq. 19 inverted
    k.e = Vec3::UnitX() + strain.head<3>();
    k.kappa = strain.tail<3>();
    k.g = k.e.cross(x.F);
    k.Cab_kappa = el.Cab * k.kappa;
    return k;
}

// ∂[f_u^∓; f_ψ^∓]/∂[c; F; M] (Eqs. 45–46).
template <param::RotationParameterization P>
void mixed_equilibrium_jacobian(const MixedElement& el, const MixedElementState& x,
                                const MixedElementKinematics& k, double lambda, const Mat3& H,
                                MixedElementResult& out) {
    const double h = k.h;
    const Mat3 Ftil = so3::skew(x.F);
    const Mat3 dAF_dc = -k.R * so3::skew(el.Cab * x.F) * H;
    const Mat3 dAM_dc = -k.R * so3::skew(el.Cab * x.M) * H;
    const Mat3 dload_dc = h * lambda * k.R * so3::skew(el.f_follower) * H;   // −∂f̄/∂c
    const Mat3 dmload_dc = h * lambda * k.R * so3::skew(el.m_follower) * H;  // −∂m̄/∂c
    const Mat3 darm_dc = h * k.R * so3::skew(el.Cab * k.g) * H;              // −∂(h A g)/∂c
    const Mat3 darm_dF = -h * k.A * (so3::skew(k.e) - Ftil * el.S.topLeftCorner<3, 3>());
    const Mat3 darm_dM = h * k.A * Ftil * el.S.topRightCorner<3, 3>();
    for (int side = 0; side < 2; ++side) {
        const double s = side == 0 ? -1.0 : 1.0;  // f^− carries −A F, f^+ carries +A F
        Eigen::Matrix<double, 6, 9>& J = side == 0 ? out.J_minus : out.J_plus;
        J.block<3, 3>(0, 0) = s * dAF_dc + dload_dc;
        J.block<3, 3>(0, 3) = s * k.A;
        J.block<3, 3>(0, 6).setZero();
        J.block<3, 3>(3, 0) = s * dAM_dc + darm_dc + dmload_dc;
        J.block<3, 3>(3, 3) = darm_dF;
        J.block<3, 3>(3, 6) = s * k.A + darm_dM;
    }
}

// ∂[f_F^−; f_M^−; f_F^+; f_M^+]/∂[u; c; F; M] (Eqs. 47–48).
template <param::RotationParameterization P>
void mixed_kinematic_jacobian(const MixedElement& el, const MixedElementState& x,
                              const MixedElementKinematics& k, const Mat3& H,
                              MixedElementResult& out) {
    const double h = k.h;
    const Mat3 dstretch_dc = -h * k.R * so3::skew(el.Cab * k.e) * H;
    const Mat3 dstretch_dF = h * k.A * el.S.topLeftCorner<3, 3>();
    const Mat3 dstretch_dM = h * k.A * el.S.topRightCorner<3, 3>();
    const Mat3 dtwist_dc = h * P::material_tangent_inverse_derivative(x.c, k.Cab_kappa);
    const Mat3 dtwist_dF = h * k.Hinv * el.Cab * el.S.bottomLeftCorner<3, 3>();
    const Mat3 dtwist_dM = h * k.Hinv * el.Cab * el.S.bottomRightCorner<3, 3>();
    Mat12& K = out.J_kinematic;
    for (int side = 0; side < 2; ++side) {
        const double s = side == 0 ? 1.0 : -1.0;  // f^− carries +u, +c (errata)
        const int r = 6 * side;
        K.block<3, 3>(r, 0) = s * Mat3::Identity();
        K.block<3, 3>(r, 3) = -dstretch_dc;
        K.block<3, 3>(r, 6) = -dstretch_dF;
        K.block<3, 3>(r, 9) = -dstretch_dM;
        K.block<3, 3>(r + 3, 0).setZero();
        K.block<3, 3>(r + 3, 3) = s * Mat3::Identity() - dtwist_dc;
        K.block<3, 3>(r + 3, 6) = -dtwist_dF;
        K.block<3, 3>(r + 3, 9) = -dtwist_dM;
    }
}

// Evaluates the element's static equations at load factor `lambda`; the Jacobian blocks only
// when `with_jacobian`.
template <param::RotationParameterization P>
void mixed_element_statics(const MixedElement& el, const MixedElementState& x, double lambda,
                           bool with_jacobian, MixedElementResult& out) {
    const MixedElementKinematics k = mixed_element_kinematics<P>(el, x);
    const double h = k.h;
    const Vec3 AF = k.A * x.F;
    const Vec3 AM = k.A * x.M;
    const Vec3 f_load = h * lambda * (el.f_dead + k.R * el.f_follower);
    const Vec3 m_load = h * lambda * (el.m_dead + k.R * el.m_follower);
    const Vec3 moment_arm = h * (k.A * k.g);
    const Vec3 stretch = h * (k.A * k.e) - 0.5 * el.chord;  // h (A e − C^ab e1)
    const Vec3 twist = h * (k.Hinv * k.Cab_kappa);
    out.fu_minus = -AF - f_load;
    out.fu_plus = AF - f_load;
    out.fpsi_minus = -AM - moment_arm - m_load;
    out.fpsi_plus = AM - moment_arm - m_load;
    out.kinematic << x.u - stretch, x.c - twist, -x.u - stretch, -x.c - twist;
    if (!with_jacobian) return;
    const Mat3 H = P::material_tangent(x.c);
    mixed_equilibrium_jacobian<P>(el, x, k, lambda, H, out);
    mixed_kinematic_jacobian<P>(el, x, k, H, out);
}

}  // namespace rotbeam::form
