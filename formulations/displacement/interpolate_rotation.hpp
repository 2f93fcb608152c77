// Rotation interpolation of the displacement formulation, `direct` strategy (as Kynema): the
// nodal parameters of an element, aligned to one chart, are interpolated component-wise,
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
#pragma once

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

}  // namespace rotbeam::form
