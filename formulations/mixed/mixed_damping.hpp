// Stiffness-proportional damping in the mixed element: BeamDyn's law (seed 000 Eq. 10), the one the
// displacement formulation assembles (calculate_damping_forces.hpp), written in the mixed
// element's unknowns, and its derivatives with respect to X and Ẋ.
//
// BeamDyn's damping force is D [ε˙; κ˙] with D = Q μC* Qᵀ (Q = A the section's total rotation,
// μ = diag(μ₁…μ₆) scaling the rows of the material stiffness C*) and the spatial rates
// ε˙ = u˙′ − ω̃(Rx⁰′), κ˙ = ω′ + ω̃κ. These are the time derivatives of the spatial strain vectors
// ε = Qγ, κ = Qk (k, γ: material components), so ε˙ = Q(γ˙ + Ω̃γ) and κ˙ = Q(k˙ + Ω̃k) with
// Ω = Qᵀω the angular velocity in material (deformed-frame B) components. In those components the
// damping force is therefore
//
//   [f_d; m_d] = μC* ([γ˙; k˙] + [Ω × γ; Ω × k]),   [γ; k] = S [F; M],
//
// the material rate plus the spin term of BeamDyn's non-objective rates (docs/displacement-
// dynamics.md, "Damping under a superposed rigid spin"). The mixed element's strains are
// S [F; M] (F, M the elastic section resultants, the kinematic rows of Eqs. 47–48 unchanged), so
// the material rate is S [Ḟ; Ṁ], and with C* = S⁻¹ (the element's compliance at mid-length)
// μC* S [Ḟ; Ṁ] = μ [Ḟ; Ṁ]. Ω is the element's angular velocity from its momenta (Eq. 18,
// [V; Ω] = I⁻¹ [P; H]); with a turning root the frame's angular velocity is taken out,
// Ω − Aᵀω_a, as the displacement formulation damps the rates relative to the frame
// (docs/rotating-frame.md).
//
// The total resultants F + f_d, M + m_d replace F, M in the equilibrium rows (Eqs. 45–46), the
// moment arm with the elastic strain (e = e1 + γ), as F^D2 = x̃′ᵀ f does in the displacement
// formulation:
//
//   f_u^∓ += ∓A f_d,   f_ψ^∓ += ∓A m_d − (ΔL/2) A (e × f_d).
//
// F and M with μᵢ > 0 become differential unknowns (their rates appear); they stay fixed by the
// kinematic rows given u and c, so the damped DAE is a Kelvin–Voigt model in the resultants
// (docs/mixed-dynamics.md, "Damping").
#pragma once

#include <type_traits>

#include "core/so3.hpp"
#include "core/types.hpp"
#include "formulations/mixed/mixed_layout.hpp"
#include "parameterizations/concept.hpp"

namespace rotbeam::form {

// One element's damping: μ at mid-length (linear between stations) and C* = S⁻¹.
struct MixedDampingSection {
    Vec6 mu = Vec6::Zero();
    Mat6 stiffness = Mat6::Zero();
    bool active() const { return mu.cwiseAbs().maxCoeff() > 0.0; }
};

template <int K = 3>
struct MixedDampingResult {
    Vec6 minus = Vec6::Zero(), plus = Vec6::Zero();  // added to [f_u; f_ψ] of the start, end node
    // Columns of ∂/∂X: c (K), F, M (6), P, H (6); of ∂/∂Ẋ: Ḟ, Ṁ (6).
    Eigen::Matrix<double, 6, K + 12> J_minus, J_plus;
    Mat6 Jd_minus = Mat6::Zero(), Jd_plus = Mat6::Zero();
};

// The damping terms of one element at resultants F, M (B frame), rotation parameters c, momenta
// P, H and resultant rates Ḟ, Ṁ; `omega_frame` is the turning frame's angular velocity (zero
// without one).
template <param::RotationParameterization P>
void mixed_element_damping(const MixedElement& el, const MixedDampingSection& d,
                           const Mat6& mass_inverse, const param::Params<P::kSize>& c,
                           const Vec6& FM, const Vec6& PH, const Vec6& FM_dot,
                           const Vec3& omega_frame, bool with_jacobian,
                           MixedDampingResult<P::kSize>& out) {
    constexpr int K = P::kSize;
    const double h = 0.5 * el.length;
    const Mat3 R = P::matrix(c);
    const Mat3 A = R * el.Cab;
    const Vec6 strain = el.S * FM;
    const Vec3 gamma = strain.head<3>();
    const Vec3 kappa = strain.tail<3>();
    const Vec3 e = Vec3::UnitX() + gamma;
    const Vec3 frame_in_R = R.transpose() * omega_frame;
    const Vec3 Omega = (mass_inverse * PH).tail<3>() - el.Cab.transpose() * frame_in_R;
    const Mat6 Dm = d.mu.asDiagonal() * d.stiffness;  // μC*
    Vec6 spin;
    spin << Omega.cross(gamma), Omega.cross(kappa);
    const Vec6 fd = d.mu.cwiseProduct(FM_dot) + Dm * spin;
    const Vec3 f = fd.head<3>();
    const Vec3 m = fd.tail<3>();
    const Vec3 arm = h * (A * e.cross(f));
    out.minus << -A * f, -A * m - arm;
    out.plus << A * f, A * m - arm;
    if (!with_jacobian) return;
    const Mat3 et = so3::skew(e);
    // Rows [f_u; f_ψ] on side s for a column map Z = ∂[f_d; m_d]/∂(columns), holding A fixed.
    auto rows = [&](double s, const auto& Z) {
        Eigen::Matrix<double, 6, std::decay_t<decltype(Z)>::ColsAtCompileTime> out_rows;
        out_rows.topRows(3) = s * A * Z.topRows(3);
        out_rows.bottomRows(3) = s * A * Z.bottomRows(3) - h * A * et * Z.topRows(3);
        return out_rows;
    };
    Mat6 spin_of_strain = Mat6::Zero();  // ∂[Ω × γ; Ω × k]/∂[γ; k]
    spin_of_strain.topLeftCorner<3, 3>() = so3::skew(Omega);
    spin_of_strain.bottomRightCorner<3, 3>() = so3::skew(Omega);
    Eigen::Matrix<double, 6, 3> spin_of_omega;  // ∂[Ω × γ; Ω × k]/∂Ω
    spin_of_omega << -so3::skew(gamma), -so3::skew(kappa);
    const Eigen::Matrix<double, 6, 3> d_omega = Dm * spin_of_omega;
    const param::Tangent<K> H = P::material_tangent(c);
    // ∂Ω/∂c = −C^ba ∂(Rᵀω_a)/∂c = −C^ba (Rᵀω_a)~ H.
    const param::Tangent<K> dOmega_dc = -el.Cab.transpose() * so3::skew(frame_in_R) * H;
    const Eigen::Matrix<double, 6, K> dfd_dc = d_omega * dOmega_dc;
    const Mat6 dfd_dFM = Dm * spin_of_strain * el.S;
    const Mat6 dfd_dPH = d_omega * mass_inverse.bottomRows<3>();
    const Mat6 dfd_dFMdot = d.mu.asDiagonal();
    for (int side = 0; side < 2; ++side) {
        const double s = side == 0 ? -1.0 : 1.0;
        Eigen::Matrix<double, 6, K + 12>& J = side == 0 ? out.J_minus : out.J_plus;
        // c: A turns (∂(A z)/∂c = −R (C^ab z)~ H) and Ω with it when the frame turns.
        J.template leftCols<K>() = rows(s, dfd_dc);
        J.template block<3, K>(0, 0) += -s * R * so3::skew(el.Cab * f) * H;
        J.template block<3, K>(3, 0) +=
            -s * R * so3::skew(el.Cab * m) * H + h * R * so3::skew(el.Cab * e.cross(f)) * H;
        // F, M: through the spin term, and the moment arm's elastic strain (∂e/∂FM = S_top).
        J.template middleCols<6>(K) = rows(s, dfd_dFM);
        J.template block<3, 6>(3, K) += h * A * so3::skew(f) * el.S.topRows<3>();
        J.template rightCols<6>() = rows(s, dfd_dPH);
        (side == 0 ? out.Jd_minus : out.Jd_plus) = rows(s, dfd_dFMdot);
    }
}

}  // namespace rotbeam::form
