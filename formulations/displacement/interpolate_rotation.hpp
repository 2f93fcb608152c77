// Rotation interpolation of the displacement formulation. Two strategies (docs/displacement-
// formulation.md §Rotation interpolation).
//
// `direct` (as Kynema): the nodal parameters of an element, aligned to one chart, are interpolated
// component-wise,
//   p̄(s) = Σ_j N_j(s) σ_j p_j,   R(s) = R(p̄(s)),   κ(s) = axial(R′Rᵀ) = H_s(p̄) p̄′,
// with σ_j = ±1 the quaternion sign alignment to the element's first node (σ_j = 1 for the
// three-parameter types). For the quaternion R(·) is the homogeneous form R(q) = R(q/|q|)
// (parameterizations/quaternion.hpp (Q1)), so normalizing p̄ is implicit and exact, and H_s is the
// exact derivative of that form off the unit sphere.
//
// Exact linearization. A nodal increment δψ_j changes p_j by H_s⁺(p_j) δψ_j (the derivative of
// the retraction p_j ← exp(δψ_j) ⊗ p_j), hence with M_j = σ_j H_s⁺(p_j):
//   δψ(s) = Σ_j A_j δψ_j,  A_j = N_j H_s(p̄) M_j
//   δκ(s) = Σ_j K_j δψ_j,  K_j = N_j ∂(H_s(p̄) p̄′)/∂p̄ M_j + N_j′ H_s(p̄) M_j
// (the interpolated-spin approximation would use A_j = N_j I, K_j = N_j′ I − N_j κ̃).
//
// `relative` (as BeamDyn; objective): with R_0 the element's first node, r_j the parameters of
// R_0ᵀ R_j (r_0 = identity; chart of r_j nearest r_{j−1}, so the chart follows the element),
//   r̄(s) = Σ_j N_j r_j,   R(s) = R_0 R(r̄),   κ(s) = R_0 H_s(r̄) r̄′.
// δψ_j changes R_0ᵀ R_j by the spatial increment R_0ᵀ (δψ_j − δψ_0), hence with
// M_j = σ_j H_s⁺(r_j) and the `direct` maps Â_j, K̂_j of r̄ (above):
//   A_j = R_0 Â_j R_0ᵀ,  K_j = R_0 K̂_j R_0ᵀ  for every j, then
//   A_0 += I − Σ_j A_j,  K_0 += −κ̃ − Σ_j K_j   (δR Rᵀ ∋ δψ_0, δκ ∋ δψ_0 × κ).
// A superposed rigid rotation Q (R_j → Q R_j) leaves every r_j unchanged, so R → Q R and
// κ → Q κ exactly: material strains are invariant (objective). A parameterization is singular only
// when the rotation *inside one element* reaches its singular angle; nodal parameters are used only
// through R_j.
#pragma once

#include "core/so3.hpp"
#include "parameterizations/concept.hpp"

namespace rotbeam::form {

template <param::RotationParameterization P>
struct InterpolatedRotation {
    param::Params<P::kSize> p_bar;
    param::Params<P::kSize> p_bar_prime;
    Mat3 R;
    Vec3 kappa;
    param::Tangent<P::kSize> Hs;
};

// σ_j: flip quaternions into the hemisphere of p_0; identity for other parameterizations.
template <param::RotationParameterization P>
double chart_sign(const param::Params<P::kSize>& p, const param::Params<P::kSize>& p0) {
    if constexpr (P::kSize == 4) {
        return p.dot(p0) < 0.0 ? -1.0 : 1.0;
    } else {
        return 1.0;
    }
}

// p: aligned nodal parameters σ_j p_j; N, dN: shape functions and their s-derivatives.
template <param::RotationParameterization P>
void interpolate_rotation(const param::Params<P::kSize>* p, const double* N, const double* dN,
                          int nodes, InterpolatedRotation<P>& out) {
    out.p_bar.setZero();
    out.p_bar_prime.setZero();
    for (int j = 0; j < nodes; ++j) {
        out.p_bar += N[j] * p[j];
        out.p_bar_prime += dN[j] * p[j];
    }
    out.R = P::matrix(out.p_bar);
    out.Hs = P::spatial_tangent(out.p_bar);
    out.kappa = out.Hs * out.p_bar_prime;
}

// R(s) = R(p̄(s)) alone, by interpolate_rotation's arithmetic (the same bits), for a kernel that
// reads neither κ nor H_s (the inertial terms of a residual).
template <param::RotationParameterization P>
Mat3 interpolated_rotation_matrix(const param::Params<P::kSize>* p, const double* N, int nodes) {
    param::Params<P::kSize> p_bar = param::Params<P::kSize>::Zero();
    for (int j = 0; j < nodes; ++j) p_bar += N[j] * p[j];
    return P::matrix(p_bar);
}

// T = ∂(H_s(p̄) p̄′)/∂p̄ for the curvature map K_j (computed once per quadrature point).
template <param::RotationParameterization P>
param::Tangent<P::kSize> curvature_tangent(const InterpolatedRotation<P>& r) {
    return P::spatial_tangent_derivative(r.p_bar, r.p_bar_prime);
}

// A_j and K_j for one node; M = σ_j H_s⁺(p_j).
template <param::RotationParameterization P>
void rotation_maps(const InterpolatedRotation<P>& r, const param::Tangent<P::kSize>& T,
                   const param::TangentInverse<P::kSize>& M, double N, double dN, Mat3& A,
                   Mat3& K) {
    const Mat3 HM = r.Hs * M;
    A = N * HM;
    K = N * (T * M) + dN * HM;
}

// Relative interpolation: interpolate the relative parameters r (as `direct`) and rotate back.
// out.Hs stays H_s(r̄) (the relative tangent) for rotation_maps.
template <param::RotationParameterization P>
void interpolate_relative(const param::Params<P::kSize>* r, const double* N, const double* dN,
                          int nodes, const Mat3& R0, InterpolatedRotation<P>& out) {
    interpolate_rotation<P>(r, N, dN, nodes, out);
    out.R = R0 * out.R;
    out.kappa = R0 * out.kappa;
}

// Turns the `direct` maps of r̄ (A[j], K[j] for j < nodes, computed with M_j = σ_j H_s⁺(r_j))
// into the maps of the relative strategy; kappa is the (rotated) curvature κ = R_0 κ_r.
inline void relative_maps(const Mat3& R0, const Vec3& kappa, int nodes, Mat3* A, Mat3* K) {
    Mat3 sumA = Mat3::Zero();
    Mat3 sumK = Mat3::Zero();
    for (int j = 0; j < nodes; ++j) {
        A[j] = R0 * A[j] * R0.transpose();
        K[j] = R0 * K[j] * R0.transpose();
        sumA += A[j];
        sumK += K[j];
    }
    A[0] += Mat3::Identity() - sumA;
    K[0] -= so3::skew(kappa) + sumK;
}

// Relative parameters of the element's nodes: r_j = params(R_0ᵀ R_j) in the chart nearest
// r_{j−1} (quaternion: hemisphere of r_{j−1}; WM/rotation vector: rescale; Rodrigues has one).
template <param::RotationParameterization P>
void relative_parameters(const param::Params<P::kSize>* p, int nodes, param::Params<P::kSize>* r) {
    const param::Params<P::kSize> inv0 = P::inverse(p[0]);
    r[0] = P::identity();
    for (int j = 1; j < nodes; ++j) {
        r[j] = P::compose(inv0, p[j]);
        if constexpr (P::kSize == 4) {
            r[j] *= chart_sign<P>(r[j], r[j - 1]);
        } else if constexpr (P::kCanRescale) {
            r[j] = P::rescale(r[j], r[j - 1]);
        }
    }
}

}  // namespace rotbeam::form
