// The concept every rotation parameterization satisfies (docs/parameterizations.md).
//
// A parameterization is a stateless struct with static functions. Notation: p are the parameters
// (kSize = 3 or 4 of them), R(p) maps material to inertial components.
//   spatial tangent   H_s(p): δR Rᵀ = (H_s δp)~      (seed 000's δψ = H_s δp)
//   material tangent  H_m(p): Rᵀ δR = (H_m δp)~      (seed 002's Q, Eq. 24; H_m = Rᵀ H_s)
// Their (right) inverses satisfy H H⁺ = I₃ (for the quaternion H⁺ H = I₄ − q qᵀ/|q|²).
// Derivatives are returned contracted with a vector, never as 3-index tensors:
//   spatial_tangent_derivative(p, v)  = ∂(H_s(p) v)/∂p            (3 × kSize, v ∈ R^kSize)
//   material_tangent_derivative(p, v) = ∂(H_m(p) v)/∂p            (3 × kSize)
//   spatial_tangent_inverse_derivative(p, w)  = ∂(H_s⁺(p) w)/∂p   (kSize × kSize, w ∈ R³)
//   material_tangent_inverse_derivative(p, w) = ∂(H_m⁺(p) w)/∂p   (kSize × kSize)
// Functions throw SingularityError at or beyond the singular set or on non-finite input.
#pragma once

#include <concepts>
#include <string_view>

#include "core/types.hpp"

namespace rotbeam::param {

template <int N>
using Params = Eigen::Matrix<double, N, 1>;
template <int N>
using Tangent = Eigen::Matrix<double, 3, N>;
template <int N>
using TangentInverse = Eigen::Matrix<double, N, 3>;

template <class P>
concept RotationParameterization = requires(const Params<P::kSize>& p, const Params<P::kSize>& q,
                                            const Vec3& w, const Mat3& R) {
    { P::kSize } -> std::convertible_to<int>;
    { P::kName } -> std::convertible_to<std::string_view>;
    { P::kCanRescale } -> std::convertible_to<bool>;
    { P::identity() } -> std::same_as<Params<P::kSize>>;
    { P::matrix(p) } -> std::same_as<Mat3>;
    { P::compose(p, q) } -> std::same_as<Params<P::kSize>>;  // R(compose(p,q)) = R(p) R(q)
    { P::inverse(p) } -> std::same_as<Params<P::kSize>>;
    { P::spatial_tangent(p) } -> std::same_as<Tangent<P::kSize>>;
    { P::material_tangent(p) } -> std::same_as<Tangent<P::kSize>>;
    { P::spatial_tangent_inverse(p) } -> std::same_as<TangentInverse<P::kSize>>;
    { P::material_tangent_inverse(p) } -> std::same_as<TangentInverse<P::kSize>>;
    { P::spatial_tangent_derivative(p, q) } -> std::same_as<Tangent<P::kSize>>;
    { P::material_tangent_derivative(p, q) } -> std::same_as<Tangent<P::kSize>>;
    {
        P::spatial_tangent_inverse_derivative(p, w)
    } -> std::same_as<Eigen::Matrix<double, P::kSize, P::kSize>>;
    {
        P::material_tangent_inverse_derivative(p, w)
    } -> std::same_as<Eigen::Matrix<double, P::kSize, P::kSize>>;
    { P::angle(p) } -> std::same_as<double>;           // rotation angle φ ≥ 0 (not reduced)
    { P::singular_angle() } -> std::same_as<double>;   // +∞ when there is none
    { P::rescale(p, q) } -> std::same_as<Params<P::kSize>>;  // same R, chart nearest reference q
    { P::from_rotation_vector(w) } -> std::same_as<Params<P::kSize>>;
    { P::to_rotation_vector(p) } -> std::same_as<Vec3>;
    { P::from_matrix(R) } -> std::same_as<Params<P::kSize>>;
};

}  // namespace rotbeam::param
