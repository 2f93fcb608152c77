// Wiener–Milenković parameters with GXBeam's continuous rescaling map, as a parameterization of
// its own (used by the mixed formulation, selected by discretization.wm_map: continuous; it is not
// in the registry's list, which names the parameterizations every formulation takes).
//
// The unknown θ is unbounded; the rotation is that of the WM parameters (seed 002 Eq. 14)
//     c(θ) = s θ,  s = 1 − 8m/|θ|,  m = round(|θ|/8)   (m = 0, c = θ for |θ| ≤ 4, i.e. φ ≤ π),
// so c = (|θ| − 8m) n with |c| ≤ 4: the angle φ(θ) = 2πm + 4 atan((|θ| − 8m)/4) grows
// continuously and monotonically with |θ| (C¹ along n: dφ/d|θ| = 1/2 on both sides of |θ| = 4),
// and R(θ) is defined for every θ (2π is reached at |θ| = 8, not at infinity as in plain WM).
// This is NOT WienerMilenkovic::rescale (the complementary set c' = −16c/cᵀc, same rotation,
// another chart, a jump of the unknowns): here the unknowns never jump, the map θ ↦ c changes.
//
// Chain rule in every derivative, with J = ∂c/∂θ = s I + (8m/|θ|) n nᵀ (J n = n):
//     H(θ) = H_WM(c) J,   H⁻¹(θ) = J⁻¹ H_WM⁻¹(c),   J⁻¹ = (1/s)(I − n nᵀ) + n nᵀ.
// J is singular where s = 0 (|θ| = 8m, φ = 2πm, c = 0): there the directions across n do not
// move the rotation to first order. So the tangent inverse is refused within kSingularGuard of
// φ = 2πm, m ≥ 1 (singular_angle() = 2π, as for the rotation vector); R and the tangent are not.
// The mixed formulation uses θ in the ±θ terms of Eq. 48, so Eq. 48 reads
// ±θ − (ΔL/2) J⁻¹ Q⁻¹(c) C^ab κ (the consistent discrete form of θ′ = H(θ)⁻¹ κ).
#pragma once

#include <cmath>

#include "parameterizations/detail.hpp"
#include "parameterizations/wiener_milenkovic.hpp"

namespace rotbeam::param {

struct WienerMilenkovicContinuous {
    using P = Params<3>;
    using WM = WienerMilenkovic;
    static constexpr int kSize = 3;
    static constexpr std::string_view kName = "wiener-milenkovic-continuous";
    static constexpr bool kCanRescale = false;  // the map itself replaces rescaling

    struct Map {
        double r = 0.0;  // |θ|
        double m = 0.0;  // full turns
        double s = 1.0;  // c = s θ
        Vec3 c = Vec3::Zero();
        Mat3 J = Mat3::Identity();
    };

    static Map map(const P& theta, const char* function) {
        detail::require_finite(theta, kName, function);
        Map q;
        q.r = theta.norm();
        q.m = q.r <= 4.0 ? 0.0 : std::round(q.r / 8.0);
        if (q.m == 0.0) {
            q.c = theta;
            return q;
        }
        q.s = 1.0 - 8.0 * q.m / q.r;
        q.c = q.s * theta;
        q.J = q.s * Mat3::Identity() + (8.0 * q.m / (q.r * q.r * q.r)) * theta * theta.transpose();
        return q;
    }

    // J⁻¹ with the guard at φ = 2πm (|c| = |θ| − 8m = 4 tan((φ − 2πm)/4) ≈ φ − 2πm).
    static Mat3 map_inverse(const P& theta, const Map& q, const char* function) {
        if (q.m == 0.0) return Mat3::Identity();
        const double dphi = 4.0 * std::atan(std::abs(q.r - 8.0 * q.m) / 4.0);
        if (dphi <= detail::kSingularGuard) {
            detail::refuse(kName, function, angle(theta), "map singular at 2πm");
        }
        const Mat3 nn = theta * theta.transpose() / (q.r * q.r);
        return (Mat3::Identity() - nn) / q.s + nn;
    }

    // ∂(J v)/∂θ at fixed v (m constant within a branch).
    static Mat3 map_derivative(const P& t, const Map& q, const Vec3& v) {
        if (q.m == 0.0) return Mat3::Zero();
        const double k = 8.0 * q.m, r3 = q.r * q.r * q.r, tv = t.dot(v);
        return (k / r3) * (v * t.transpose() + tv * Mat3::Identity() + t * v.transpose()) -
               (3.0 * k * tv / (r3 * q.r * q.r)) * t * t.transpose();
    }

    // ∂(J⁻¹ u)/∂θ at fixed u; J⁻¹ u = u/s + (1 − 1/s) θ (θ·u)/r².
    static Mat3 map_inverse_derivative(const P& t, const Map& q, const Vec3& u) {
        if (q.m == 0.0) return Mat3::Zero();
        const double r2 = q.r * q.r, tu = t.dot(u), a = 1.0 - 1.0 / q.s;
        const Vec3 d_inv_s = (-8.0 * q.m / (q.s * q.s * r2 * q.r)) * t;  // ∂(1/s)/∂θ
        return (u - t * (tu / r2)) * d_inv_s.transpose() +
               a * ((tu * Mat3::Identity() + t * u.transpose()) / r2 -
                    (2.0 * tu / (r2 * r2)) * t * t.transpose());
    }

    static P identity() { return P::Zero(); }
    static Mat3 matrix(const P& t) { return WM::matrix(map(t, "matrix").c); }
    static P compose(const P& a, const P& b) {
        return WM::rescale(WM::compose(map(a, "compose").c, map(b, "compose").c), P::Zero());
    }
    static P inverse(const P& t) { return -map(t, "inverse").c; }  // c(−θ) = −c(θ)

    static Tangent<3> spatial_tangent(const P& t) {
        const Map q = map(t, "spatial_tangent");
        return WM::spatial_tangent(q.c) * q.J;
    }
    static Tangent<3> material_tangent(const P& t) {
        const Map q = map(t, "material_tangent");
        return WM::material_tangent(q.c) * q.J;
    }
    static TangentInverse<3> spatial_tangent_inverse(const P& t) {
        const Map q = map(t, "spatial_tangent_inverse");
        return map_inverse(t, q, "spatial_tangent_inverse") * WM::spatial_tangent_inverse(q.c);
    }
    static TangentInverse<3> material_tangent_inverse(const P& t) {
        const Map q = map(t, "material_tangent_inverse");
        return map_inverse(t, q, "material_tangent_inverse") * WM::material_tangent_inverse(q.c);
    }
    // ∂(H_WM(c) J v)/∂θ = ∂(H_WM w)/∂c|_{w = Jv} J + H_WM ∂(J v)/∂θ.
    static Mat3 spatial_tangent_derivative(const P& t, const P& v) {
        const Map q = map(t, "spatial_tangent_derivative");
        return WM::spatial_tangent_derivative(q.c, q.J * v) * q.J +
               WM::spatial_tangent(q.c) * map_derivative(t, q, v);
    }
    static Mat3 material_tangent_derivative(const P& t, const P& v) {
        const Map q = map(t, "material_tangent_derivative");
        return WM::material_tangent_derivative(q.c, q.J * v) * q.J +
               WM::material_tangent(q.c) * map_derivative(t, q, v);
    }
    // ∂(J⁻¹ H_WM⁻¹(c) w)/∂θ = ∂(J⁻¹ u)/∂θ|_{u = H⁻¹w} + J⁻¹ ∂(H_WM⁻¹ w)/∂c J.
    static Mat3 spatial_tangent_inverse_derivative(const P& t, const Vec3& w) {
        const Map q = map(t, "spatial_tangent_inverse_derivative");
        const Mat3 Jinv = map_inverse(t, q, "spatial_tangent_inverse_derivative");
        return map_inverse_derivative(t, q, WM::spatial_tangent_inverse(q.c) * w) +
               Jinv * WM::spatial_tangent_inverse_derivative(q.c, w) * q.J;
    }
    static Mat3 material_tangent_inverse_derivative(const P& t, const Vec3& w) {
        const Map q = map(t, "material_tangent_inverse_derivative");
        const Mat3 Jinv = map_inverse(t, q, "material_tangent_inverse_derivative");
        return map_inverse_derivative(t, q, WM::material_tangent_inverse(q.c) * w) +
               Jinv * WM::material_tangent_inverse_derivative(q.c, w) * q.J;
    }

    // The continuous angle 2πm + 4 atan((|θ| − 8m)/4) (not reduced).
    static double angle(const P& t) {
        const Map q = map(t, "angle");
        return 2.0 * kPi * q.m + 4.0 * std::atan((q.r - 8.0 * q.m) / 4.0);
    }
    static double singular_angle() { return 2.0 * kPi; }
    static P rescale(const P& t, const P& /*reference*/) { return t; }

    // Inverse of angle(): |θ| = 8m + 4 tan((φ − 2πm)/4), m = round(φ/2π), any angle.
    static P from_rotation_vector(const Vec3& psi) {
        detail::require_finite(psi, kName, "from_rotation_vector");
        const double phi = psi.norm();
        if (phi == 0.0) return P::Zero();
        const double m = std::round(phi / (2.0 * kPi));
        return (8.0 * m + 4.0 * std::tan((phi - 2.0 * kPi * m) / 4.0)) / phi * psi;
    }
    static Vec3 to_rotation_vector(const P& t) {
        const double r = t.norm();
        return r == 0.0 ? Vec3::Zero() : Vec3(angle(t) / r * t);
    }
    static P from_matrix(const Mat3& R) { return WM::rescale(WM::from_matrix(R), P::Zero()); }
};

static_assert(RotationParameterization<WienerMilenkovicContinuous>);

}  // namespace rotbeam::param
