// Wiener–Milenković (WM) parameterization of rotations (seed 002 §II B, Eqs. 9–15, 24, 25).
//
// Definition: c = 4 tan(φ/4) n (Eqs. 9, 10), kSize = 3, c0 = 2 − cᵀc/8 (Eq. 13). With
// D = (4 − c0)² = c0² + cᵀc, (c0, c)/(4 − c0) is the unit quaternion (cos φ/2, sin φ/2 n):
// WM is the stereographic projection of the quaternion sphere from (−1, 0).
// R maps material to inertial components. Seed 002's C (Eqs. 12, 14) is Rᵀ, so
//     R(c) = C(c)ᵀ = [(c0² − cᵀc) I + 2 c0 c̃ + 2 c cᵀ] / D                              (W1)
// Tangents (derived from (W1) through the quaternion's (Q2)/(Q3); checked against finite
// differences of R in tests/parameterizations):
//     material H_m = 2 [c0 I − c̃ + c cᵀ/4] / D = seed 002's Q, Eq. (24)  (Rᵀ δR = (H_m δc)~)
//     spatial  H_s = R H_m = 2 [c0 I + c̃ + c cᵀ/4] / D                   (δR Rᵀ = (H_s δc)~)
//     H_m⁻¹ = (1 − cᵀc/16) I + c̃/2 + c cᵀ/8 = seed 002's Q⁻¹, Eq. (25)
//     H_s⁻¹ = (1 − cᵀc/16) I − c̃/2 + c cᵀ/8
// Note: the transposition C = Rᵀ and Q = H_m are consistent: seed 002 writes the material
// curvature κ = Q c' (Eq. 22 inverted), and Rᵀ R' = (H_m c')~ is exactly that.
// Singular set: φ = 2π (|c| → ∞, Eq. 10's remark); every finite c has φ = 4 atan(|c|/4) < 2π.
// Refused (SingularityError): non-finite input; parameters within detail::kSingularGuard of 2π
// (|c| > 4 / tan(kSingularGuard/4) ≈ 1.6e13); rotation vectors with |ψ| ≥ 2π − guard;
// compositions whose result is at 2π.
// Rescale: past π the complementary parameters c' = 4 tan((φ − 2π)/4) n = −16 c/(cᵀc) describe
// the same R with angle 2π − φ < π; rescale(c, ref) returns whichever of c, c' is nearest ref.
// compose is the closed-form WM composition (quaternion product written in (c0, c)), never via
// matrices; it does not rescale (a caller that wants the short chart calls rescale).
#pragma once

#include <cmath>

#include "core/so3.hpp"
#include "parameterizations/concept.hpp"
#include "parameterizations/detail.hpp"

namespace rotbeam::param {

struct WienerMilenkovic {
    static constexpr int kSize = 3;
    static constexpr std::string_view kName = "wiener-milenkovic";
    static constexpr bool kCanRescale = true;
    using P = Params<3>;

    // Below |c| < kSeriesNorm (φ < kSeriesNorm), tan/atan ratios use their series (next terms
    // ~φ⁶/1e4 < 1e-27 relative) instead of dividing by a vanishing norm.
    static constexpr double kSeriesNorm = 1e-4;

    static P identity() { return P::Zero(); }

    // |c| beyond which φ is within kSingularGuard of 2π: 2π − φ = 4 atan(4/|c|), so the limit is
    // 4/tan(kSingularGuard/4) = 16/kSingularGuard (tan x = x to 1e-25 relative at x ~ 1e-12).
    // Comparing norms keeps atan out of every call; it is evaluated only to report a refusal.
    static constexpr double kMaxNorm = 16.0 / detail::kSingularGuard;

    // Refuses non-finite c and c within kSingularGuard of φ = 2π; returns cᵀc.
    static double checked_squared_norm(const P& c, const char* function) {
        detail::require_finite(c, kName, function);
        const double s = c.squaredNorm();
        if (!(s < kMaxNorm * kMaxNorm)) {
            const double distance = 4.0 * std::atan2(4.0, std::sqrt(s));  // 2π − φ
            detail::refuse(kName, function, 2.0 * kPi - distance, "at the singular angle 2π");
        }
        return s;
    }

    // (W1). Refuses what checked_squared_norm refuses.
    static Mat3 matrix(const P& c) {
        const double s = checked_squared_norm(c, "matrix");
        const double c0 = 2.0 - s / 8.0;
        const double d = (4.0 - c0) * (4.0 - c0);
        const Mat3 R =
            (c0 * c0 - s) * Mat3::Identity() + 2.0 * c0 * detail::hat(c) + 2.0 * c * c.transpose();
        return R / d;
    }

    // R(compose(a, b)) = R(a) R(b) through the quaternion product of (a0, a) and (b0, b): with
    // Δ1 = (4 − a0)(4 − b0) (its norm), Δ2 = a0 b0 − a·b (its scalar part) and
    // v = b0 a + a0 b + a × b (its vector part), c = 4 v/(Δ1 + Δ2) (Bauchau's formula). When
    // Δ2 < 0 (composite past π) Δ1 + Δ2 cancels, so there c = 4 v (Δ1 − Δ2)/|v|², the same
    // value since Δ1² − Δ2² = |v|². Refuses non-finite or singular input and a result at 2π.
    static P compose(const P& a, const P& b) {
        const double sa = checked_squared_norm(a, "compose");
        const double sb = checked_squared_norm(b, "compose");
        const double a0 = 2.0 - sa / 8.0;
        const double b0 = 2.0 - sb / 8.0;
        const double d1 = (4.0 - a0) * (4.0 - b0);
        const double d2 = a0 * b0 - a.dot(b);
        const P v = b0 * a + a0 * b + a.cross(b);
        const double v2 = v.squaredNorm();
        if (d2 < 0.0 && !(v2 > 0.0)) detail::refuse(kName, "compose", 2.0 * kPi, "result at 2π");
        const P c = d2 >= 0.0 ? P((4.0 / (d1 + d2)) * v) : P((4.0 * (d1 - d2) / v2) * v);
        checked_squared_norm(c, "compose");
        return c;
    }

    static P inverse(const P& c) {
        checked_squared_norm(c, "inverse");
        return -c;
    }

    // 2 [c0 I + sign c̃ + c cᵀ/4]/D: sign +1 spatial, −1 material (Eq. 24).
    static Mat3 tangent(const P& c, double sign, const char* function) {
        const double s = checked_squared_norm(c, function);
        const double c0 = 2.0 - s / 8.0;
        const double d = (4.0 - c0) * (4.0 - c0);
        const Mat3 m = c0 * Mat3::Identity() + sign * detail::hat(c) + 0.25 * c * c.transpose();
        return (2.0 / d) * m;
    }
    static Tangent<3> spatial_tangent(const P& c) { return tangent(c, 1.0, "spatial_tangent"); }
    static Tangent<3> material_tangent(const P& c) { return tangent(c, -1.0, "material_tangent"); }

    // (1 − cᵀc/16) I − sign c̃/2 + c cᵀ/8 (Eq. 25 for sign −1).
    static Mat3 tangent_inverse(const P& c, double sign, const char* function) {
        const double s = checked_squared_norm(c, function);
        return (1.0 - s / 16.0) * Mat3::Identity() - 0.5 * sign * detail::hat(c) +
               0.125 * c * c.transpose();
    }
    static TangentInverse<3> spatial_tangent_inverse(const P& c) {
        return tangent_inverse(c, 1.0, "spatial_tangent_inverse");
    }
    static TangentInverse<3> material_tangent_inverse(const P& c) {
        return tangent_inverse(c, -1.0, "material_tangent_inverse");
    }

    // ∂(H v)/∂c for H = 2 N/D, N v = c0 v + sign c × v + c (c·v)/4, with ∂c0/∂c = −cᵀ/4 and
    // ∂D/∂c = (4 − c0) cᵀ/2.
    static Mat3 tangent_derivative(const P& c, const Vec3& v, double sign, const char* fn) {
        const double s = checked_squared_norm(c, fn);
        detail::require_finite(v, kName, fn);
        const double c0 = 2.0 - s / 8.0;
        const double d = (4.0 - c0) * (4.0 - c0);
        const double cv = c.dot(v);
        const Vec3 n = c0 * v + sign * c.cross(v) + 0.25 * cv * c;
        const Mat3 dn = -0.25 * v * c.transpose() - sign * detail::hat(v) +
                        0.25 * (cv * Mat3::Identity() + c * v.transpose());
        return (2.0 / d) * (dn - n * c.transpose() / (2.0 * (4.0 - c0)));
    }
    static Mat3 spatial_tangent_derivative(const P& c, const P& v) {
        return tangent_derivative(c, v, 1.0, "spatial_tangent_derivative");
    }
    static Mat3 material_tangent_derivative(const P& c, const P& v) {
        return tangent_derivative(c, v, -1.0, "material_tangent_derivative");
    }

    // ∂(H⁻¹ w)/∂c of H⁻¹ w = (1 − cᵀc/16) w − sign c × w/2 + c (c·w)/8.
    static Mat3 tangent_inverse_derivative(const P& c, const Vec3& w, double sign, const char* fn) {
        checked_squared_norm(c, fn);
        detail::require_finite(w, kName, fn);
        return -0.125 * w * c.transpose() + 0.5 * sign * detail::hat(w) +
               0.125 * (c.dot(w) * Mat3::Identity() + c * w.transpose());
    }
    static Mat3 spatial_tangent_inverse_derivative(const P& c, const Vec3& w) {
        return tangent_inverse_derivative(c, w, 1.0, "spatial_tangent_inverse_derivative");
    }
    static Mat3 material_tangent_inverse_derivative(const P& c, const Vec3& w) {
        return tangent_inverse_derivative(c, w, -1.0, "material_tangent_inverse_derivative");
    }

    // φ = 4 atan(|c|/4) ∈ [0, 2π).
    static double angle(const P& c) {
        checked_squared_norm(c, "angle");
        return 4.0 * std::atan(0.25 * c.norm());
    }

    static double singular_angle() { return 2.0 * kPi; }

    // Of c and its complement −16 c/(cᵀc) (same R, angle 2π − φ), the one nearest reference.
    // Refuses non-finite or singular c or reference.
    static P rescale(const P& c, const P& reference) {
        const double s = checked_squared_norm(c, "rescale");
        checked_squared_norm(reference, "rescale");
        if (s == 0.0) return c;
        const P complement = (-16.0 / s) * c;
        if (!(complement.squaredNorm() < kMaxNorm * kMaxNorm)) {
            return c;
        }
        return (complement - reference).squaredNorm() < (c - reference).squaredNorm() ? complement
                                                                                      : c;
    }

    // 4 tan(φ/4) n (Eqs. 9, 10). Refuses non-finite ψ and |ψ| ≥ 2π − kSingularGuard (reduce ψ by
    // 2π first: the rotation is representable, but not on this continuation of the chart).
    static P from_rotation_vector(const Vec3& psi) {
        detail::require_finite(psi, kName, "from_rotation_vector");
        const double phi = psi.norm();
        if (!(phi < 2.0 * kPi - detail::kSingularGuard)) {
            detail::refuse(kName, "from_rotation_vector", phi,
                           "at or beyond the singular angle 2π");
        }
        if (phi < kSeriesNorm) {
            const double p2 = phi * phi;
            return (1.0 + p2 / 48.0 + p2 * p2 / 1920.0) * psi;
        }
        // tan may round |p| just past the norm limit right at the guard: check the result too.
        const P p = (4.0 * std::tan(0.25 * phi) / phi) * psi;
        checked_squared_norm(p, "from_rotation_vector");
        return p;
    }

    // φ n with φ = 4 atan(|c|/4) ∈ [0, 2π). Refuses non-finite or singular c.
    static Vec3 to_rotation_vector(const P& c) {
        const double s = checked_squared_norm(c, "to_rotation_vector");
        const double n = std::sqrt(s);
        if (n < kSeriesNorm) return (1.0 - s / 48.0 + s * s / 1280.0) * c;
        return (4.0 * std::atan(0.25 * n) / n) * c;
    }

    // Through Shepperd's quaternion (w ≥ 0): c = 4 v/(1 + w), φ ≤ π. Refuses a non-finite R.
    static P from_matrix(const Mat3& R) {
        detail::require_finite(R, kName, "from_matrix");
        const Vec4 q = so3::quat_from_matrix(R);
        return (4.0 / (1.0 + q[0])) * q.tail<3>();
    }

    // compose(from_rotation_vector(dpsi), c): the spatial update R ← exp(dψ~) R.
    static P retract_spatial(const P& c, const Vec3& dpsi) {
        return compose(from_rotation_vector(dpsi), c);
    }
};

static_assert(RotationParameterization<WienerMilenkovic>);

}  // namespace rotbeam::param
