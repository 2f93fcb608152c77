// Quaternion parameterization of rotations (docs/architecture.md, Shared conventions).
//
// Definition: q = (w, v) = (cos φ/2, sin φ/2 n), scalar first, kSize = 4. q and −q are the same
// rotation; there is no singular angle (singular_angle() = +∞).
// R maps material to inertial components. matrix(q) is the homogeneous form, valid for any
// q ≠ 0 and equal to the usual one for |q| = 1:
//     R(q) = ((w² − v·v) I + 2 v vᵀ + 2 w ṽ) / |q|²                                  (Q1)
// (the mixed formulation evaluates C(q)/|q|², seed 002 Eq. 12 with (c0, c) ← (w, v) being the
// same homogeneous form, transposed). R(q) = R(q/|q|), so every tangent below is the exact
// derivative of (Q1), also off the unit sphere. With E(q) = [−v, wI + ṽ], G(q) = [−v, wI − ṽ]:
//     spatial  H_s = 2 E(q)/|q|²   (δR Rᵀ = (H_s δq)~, seed 000's δψ)                 (Q2)
//     material H_m = 2 G(q)/|q|²   (Rᵀ δR = (H_m δq)~, H_m = Rᵀ H_s)                  (Q3)
// and, since E Eᵀ = |q|² I₃ and Eᵀ E = |q|² I₄ − q qᵀ (likewise G), the right inverses
//     H_s⁺ = Eᵀ(q)/2,  H_m⁺ = Gᵀ(q)/2:  H H⁺ = I₃,  H⁺ H = I₄ − q qᵀ/|q|².           (Q4)
// H⁺ maps a rotation increment into the tangent plane of the sphere at q (no radial part).
// compose is the Hamilton product (R(a ⊗ b) = R(a) R(b); norms multiply, nothing normalizes);
// inverse is q*/|q|² so that compose(q, inverse(q)) = identity exactly.
// Rescale: normalize and pick the sign (hemisphere) nearest a reference quaternion; the chart of
// a quaternion never ends, rescaling only keeps neighbouring nodes on one hemisphere.
// Refused (SingularityError): non-finite input; |q| < kMinNorm (q = 0 is no rotation).
#pragma once

#include <cmath>
#include <limits>

#include "core/so3.hpp"
#include "parameterizations/concept.hpp"
#include "parameterizations/detail.hpp"

namespace rotbeam::param {

struct Quaternion {
    static constexpr int kSize = 4;
    static constexpr std::string_view kName = "quaternion";
    static constexpr bool kCanRescale = true;
    using P = Params<4>;

    // Below this norm q is treated as zero: |q|² would underflow long before (Q1) means anything.
    static constexpr double kMinNorm = 1e-100;
    // Below |v|/w < kSeriesRatio, to_rotation_vector uses atan(x)/x = 1 − x²/3 + x⁴/5 (next term
    // x⁶/7 < 1e-24 relative) instead of dividing the angle by |v|.
    static constexpr double kSeriesRatio = 1e-4;

    static P identity() { return P(1.0, 0.0, 0.0, 0.0); }

    // Refuses non-finite q and |q| < kMinNorm; returns |q|².
    static double checked_squared_norm(const P& q, const char* function) {
        detail::require_finite(q, kName, function);
        const double s = q.squaredNorm();
        if (!(s >= kMinNorm * kMinNorm)) detail::refuse(kName, function, detail::kNaN, "q = 0");
        return s;
    }

    // (Q1). Refuses what checked_squared_norm refuses.
    static Mat3 matrix(const P& q) {
        const double s = checked_squared_norm(q, "matrix");
        const double w = q[0];
        const Vec3 v = q.tail<3>();
        Mat3 R = (w * w - v.squaredNorm()) * Mat3::Identity() + 2.0 * v * v.transpose() +
                 2.0 * w * detail::hat(v);
        return R / s;
    }

    // Hamilton product a ⊗ b: R(compose(a, b)) = R(a) R(b). Refuses non-finite or zero input.
    static P compose(const P& a, const P& b) {
        checked_squared_norm(a, "compose");
        checked_squared_norm(b, "compose");
        const Vec3 av = a.tail<3>();
        const Vec3 bv = b.tail<3>();
        P r;
        r[0] = a[0] * b[0] - av.dot(bv);
        r.tail<3>() = a[0] * bv + b[0] * av + av.cross(bv);
        return r;
    }

    // q*/|q|², so that q ⊗ inverse(q) = (1, 0, 0, 0) for any q ≠ 0.
    static P inverse(const P& q) {
        const double s = checked_squared_norm(q, "inverse");
        return P(q[0] / s, -q[1] / s, -q[2] / s, -q[3] / s);
    }

    // E(q) (sign = +1) or G(q) (sign = −1) of (Q2)/(Q3).
    static Tangent<4> e_or_g(const P& q, double sign) {
        Tangent<4> m;
        m.col(0) = -q.tail<3>();
        m.rightCols<3>() = q[0] * Mat3::Identity() + sign * detail::hat(q.tail<3>());
        return m;
    }

    // (Q2), (Q3). Refuse non-finite or zero q.
    static Tangent<4> spatial_tangent(const P& q) {
        const double s = checked_squared_norm(q, "spatial_tangent");
        return (2.0 / s) * e_or_g(q, 1.0);
    }
    static Tangent<4> material_tangent(const P& q) {
        const double s = checked_squared_norm(q, "material_tangent");
        return (2.0 / s) * e_or_g(q, -1.0);
    }

    // (Q4). Refuse non-finite or zero q.
    static TangentInverse<4> spatial_tangent_inverse(const P& q) {
        checked_squared_norm(q, "spatial_tangent_inverse");
        return 0.5 * e_or_g(q, 1.0).transpose();
    }
    static TangentInverse<4> material_tangent_inverse(const P& q) {
        checked_squared_norm(q, "material_tangent_inverse");
        return 0.5 * e_or_g(q, -1.0).transpose();
    }

    // ∂(H(q) u)/∂q for H = 2 E(q)/|q|² (sign +1) or 2 G(q)/|q|² (sign −1). E(q) u is linear in
    // q: E(q) u = F(u) q with F(u) = [u_v, −u_0 I − sign ũ_v]; the quotient rule adds the
    // derivative of 1/|q|², −2 (E u) qᵀ/|q|⁴.
    static Tangent<4> tangent_derivative(const P& q, const P& u, double sign, const char* fn) {
        const double s = checked_squared_norm(q, fn);
        detail::require_finite(u, kName, fn);
        Tangent<4> F;
        F.col(0) = u.tail<3>();
        F.rightCols<3>() = -u[0] * Mat3::Identity() - sign * detail::hat(u.tail<3>());
        const Vec3 Eu = e_or_g(q, sign) * u;
        return (2.0 / s) * (F - (2.0 / s) * Eu * q.transpose());
    }
    static Tangent<4> spatial_tangent_derivative(const P& q, const P& u) {
        return tangent_derivative(q, u, 1.0, "spatial_tangent_derivative");
    }
    static Tangent<4> material_tangent_derivative(const P& q, const P& u) {
        return tangent_derivative(q, u, -1.0, "material_tangent_derivative");
    }

    // ∂(H⁺(q) a)/∂q: H⁺ a = ½ [−v·a; w a − sign v × a] is linear in q.
    static Mat4 tangent_inverse_derivative(const P& q, const Vec3& a, double sign, const char* fn) {
        checked_squared_norm(q, fn);
        detail::require_finite(a, kName, fn);
        Mat4 D = Mat4::Zero();
        D.block<1, 3>(0, 1) = -0.5 * a.transpose();
        D.block<3, 1>(1, 0) = 0.5 * a;
        D.block<3, 3>(1, 1) = 0.5 * sign * detail::hat(a);
        return D;
    }
    static Mat4 spatial_tangent_inverse_derivative(const P& q, const Vec3& a) {
        return tangent_inverse_derivative(q, a, 1.0, "spatial_tangent_inverse_derivative");
    }
    static Mat4 material_tangent_inverse_derivative(const P& q, const Vec3& a) {
        return tangent_inverse_derivative(q, a, -1.0, "material_tangent_inverse_derivative");
    }

    // φ = 2 atan2(|v|, w) ∈ [0, 2π]: the hemisphere w < 0 holds the angles past π.
    static double angle(const P& q) {
        checked_squared_norm(q, "angle");
        return 2.0 * std::atan2(q.tail<3>().norm(), q[0]);
    }

    static double singular_angle() { return std::numeric_limits<double>::infinity(); }

    // The unit quaternion ±q/|q| on the hemisphere of `reference` (q·reference ≥ 0); same R.
    // Refuses non-finite or zero q or reference.
    static P rescale(const P& q, const P& reference) {
        const double s = checked_squared_norm(q, "rescale");
        checked_squared_norm(reference, "rescale");
        const double sign = q.dot(reference) < 0.0 ? -1.0 : 1.0;
        return (sign / std::sqrt(s)) * q;
    }

    // (cos φ/2, sin φ/2 n) for any angle: the hemisphere follows φ (w < 0 for φ ∈ (π, 3π)).
    // Refuses non-finite ψ.
    static P from_rotation_vector(const Vec3& psi) {
        detail::require_finite(psi, kName, "from_rotation_vector");
        return so3::quat_from_rotvec(psi);
    }

    // φ n with φ = angle(q) ∈ [0, 2π] (so the round trip from_rotation_vector → here is exact
    // for |ψ| < 2π; near 2π the axis is ill-conditioned, error ~ ε/(2π − φ)). At v = 0 the
    // axis is undefined and the result is 0 (R = I). Refuses non-finite or zero q.
    static Vec3 to_rotation_vector(const P& q) {
        checked_squared_norm(q, "to_rotation_vector");
        const Vec3 v = q.tail<3>();
        const double sn = v.norm();
        if (sn == 0.0) return Vec3::Zero();
        if (q[0] > 0.0 && sn < kSeriesRatio * q[0]) {
            const double x2 = (sn / q[0]) * (sn / q[0]);
            return (2.0 / q[0]) * (1.0 - x2 / 3.0 + x2 * x2 / 5.0) * v;
        }
        return (2.0 * std::atan2(sn, q[0]) / sn) * v;
    }

    // Shepperd's extraction, w ≥ 0 (angle ≤ π). Refuses a non-finite matrix.
    static P from_matrix(const Mat3& R) {
        detail::require_finite(R, kName, "from_matrix");
        return so3::quat_from_matrix(R);
    }

    // compose(from_rotation_vector(dpsi), q): the spatial update R ← exp(dψ~) R.
    static P retract_spatial(const P& q, const Vec3& dpsi) {
        return compose(from_rotation_vector(dpsi), q);
    }
};

static_assert(RotationParameterization<Quaternion>);

}  // namespace rotbeam::param
