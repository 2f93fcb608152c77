// Euler angles of the Tait–Bryan sequence z-y′-x″ (yaw, pitch, roll), docs/euler-angles.md.
//
// Definition: p = (a1, a2, a3), kSize = 3, a_i the angle about the material axis e_i; the
// rotation is applied as yaw a3 about z, then pitch a2 about the new y′, then roll a1 about the
// newest x″ (intrinsic z-y′-x″, the same matrix as extrinsic x-y-z). With R_i(a) the rotation by
// a about e_i and c_i = cos a_i, s_i = sin a_i, R maps material to inertial components:
//     R(p) = R3(a3) R2(a2) R1(a1)                                                       (E1)
//          = [ c3c2   c3s2s1 − s3c1   c3s2c1 + s3s1 ]
//            [ s3c2   s3s2s1 + c3c1   s3s2c1 − c3s1 ]
//            [ −s2    c2s1            c2c1          ]
// Storing the angle about e_i in component i makes p = ψ + O(φ²) near the identity (H(0) = I), as
// for the other three-parameter charts. Tangents (columns: the axis each angle turns about, seen
// in the inertial frame for H_s and in the material frame for H_m):
//     H_s = [R3R2 e1, R3 e2, e3] = [c3c2 −s3 0; s3c2 c3 0; −s2 0 1]        (δR Rᵀ = (H_s δp)~) (E2)
//     H_m = [e1, R1ᵀ e2, R1ᵀR2ᵀ e3] = [1 0 −s2; 0 c1 s1c2; 0 −s1 c1c2]    (Rᵀ δR = (H_m δp)~) (E3)
//     det H_s = det H_m = c2
//     H_s⁻¹ = [c3/c2 s3/c2 0; −s3 c3 0; c3t2 s3t2 1],  t2 = tan a2                          (E4)
//     H_m⁻¹ = [1 s1t2 c1t2; 0 c1 −s1; 0 s1/c2 c1/c2]                                       (E5)
// Singular set (gimbal lock): c2 = 0, the middle angle a2 = ±π/2 (+ kπ): the first and the last
// axis coincide, only a1 ∓ a3 is determined, and H loses rank. It is not a set of rotation angles:
// the smallest rotation on it is a quarter turn about the middle axis y, so singular_angle() =
// π/2. A bend about y (the roll-up, cases/cantilever-moment.yaml) reaches it at a tip rotation of
// π/2; a rotation about x or z never does. gimbal_distance(p) is the distance of a2 to the nearest
// ±π/2 (rad), the measure comparable with the other charts' singular_angle() − φ.
// Refused (SingularityError): non-finite input everywhere; the tangents, their inverses and their
// derivatives within detail::kSingularGuard of gimbal lock (the error carries the rotation angle
// of R(p); its detail names the middle angle). R, compose, inverse and the conversions are defined
// for every finite input (at gimbal lock from_matrix picks a1 = 0 of the possible splits).
// Rescale: the same R has the parameters (a1 + 2πk1, a2 + 2πk2, a3 + 2πk3) and
// (a1 + π + 2πk1, π − a2 + 2πk2, a3 + π + 2πk3) (R3(π) R2(π − a2) R1(π) = R2(a2)); rescale returns
// the one nearest the reference. angle(p) is the principal rotation angle of R(p) in [0, π]:
// Euler angles carry no count of full turns.
// compose and inverse go through the matrix (there is no closed-form Euler composition): compose
// returns the parameters nearest a + b, inverse those nearest −p; from_matrix and
// from_rotation_vector return the principal ones, a2 ∈ [−π/2, π/2], a1, a3 ∈ (−π, π].
#pragma once

#include <cmath>
#include <sstream>
#include <string>

#include "core/so3.hpp"
#include "parameterizations/concept.hpp"
#include "parameterizations/detail.hpp"

namespace rotbeam::param {

struct EulerAngles {
    static constexpr int kSize = 3;
    static constexpr std::string_view kName = "euler-angles";
    static constexpr bool kCanRescale = true;
    using P = Params<3>;

    struct Trig {
        double c1, s1, c2, s2, c3, s3;
    };

    static P identity() { return P::Zero(); }

    static Trig trig(const P& p) {
        return {std::cos(p[0]), std::sin(p[0]), std::cos(p[1]),
                std::sin(p[1]), std::cos(p[2]), std::sin(p[2])};
    }

    // Distance (rad) of the middle angle a2 to the nearest ±π/2 + kπ: asin|cos a2|, accurate
    // where it matters (near 0, where cos a2 is computed to full relative accuracy).
    static double gimbal_distance(const P& p) {
        return std::asin(std::min(1.0, std::abs(std::cos(p[1]))));
    }

    static Trig checked(const P& p, const char* function) {
        detail::require_finite(p, kName, function);
        return trig(p);
    }

    // Also refuses p within kSingularGuard of gimbal lock (|cos a2| ≤ sin(guard) = guard).
    static Trig checked_tangent(const P& p, const char* function) {
        const Trig t = checked(p, function);
        if (!(std::abs(t.c2) > detail::kSingularGuard)) {
            std::ostringstream s;
            s << "gimbal lock: middle angle a2 = " << p[1] << " rad, cos a2 = " << t.c2;
            throw SingularityError(std::string(kName), function, so3::rotation_angle(matrix(p)),
                                   s.str());
        }
        return t;
    }

    // (E1).
    static Mat3 matrix(const P& p) {
        const Trig t = checked(p, "matrix");
        Mat3 R;
        R << t.c3 * t.c2, t.c3 * t.s2 * t.s1 - t.s3 * t.c1, t.c3 * t.s2 * t.c1 + t.s3 * t.s1,
            t.s3 * t.c2, t.s3 * t.s2 * t.s1 + t.c3 * t.c1, t.s3 * t.s2 * t.c1 - t.c3 * t.s1, -t.s2,
            t.c2 * t.s1, t.c2 * t.c1;
        return R;
    }

    // Principal parameters of R, stable at gimbal lock: a1 from the last row (c2 ≥ 0), then
    // M = R R1(a1)ᵀ = R3(a3) R2(a2) = [c3c2 −s3 c3s2; s3c2 c3 s3s2; −s2 0 c2] gives a3 and a2
    // from entries of size one, so R(p) reproduces R to round-off even where a1 and a3 are
    // individually undetermined (at lock R32 = R33 = 0 and a1 = atan2(0, 0) = 0).
    static P principal(const Mat3& R) {
        const double a1 = std::atan2(R(2, 1), R(2, 2));
        const double c1 = std::cos(a1);
        const double s1 = std::sin(a1);
        // Columns 1 and 2 of M = R R1(a1)ᵀ (R1ᵀ has rows (1,0,0), (0,c1,s1), (0,−s1,c1)).
        const Vec3 m1 = c1 * R.col(1) - s1 * R.col(2);
        const Vec3 m2 = s1 * R.col(1) + c1 * R.col(2);
        return P(a1, std::atan2(-R(2, 0), m2[2]), std::atan2(-m1[0], m1[1]));
    }

    static P from_matrix(const Mat3& R) {
        detail::require_finite(R, kName, "from_matrix");
        return principal(R);
    }

    // R(compose(a, b)) = R(a) R(b), the parameters nearest a + b (as the rotation vector's
    // compose), so that an update compose(δ, p) by a small δ never jumps branch or full turn.
    static P compose(const P& a, const P& b) {
        checked(a, "compose");
        checked(b, "compose");
        return nearest(principal(matrix(a) * matrix(b)), a + b);
    }

    // The parameters of R(p)ᵀ nearest −p (−p itself when p turns about one axis only).
    static P inverse(const P& p) {
        checked(p, "inverse");
        return nearest(principal(matrix(p).transpose()), -p);
    }

    // (E2).
    static Tangent<3> spatial_tangent(const P& p) {
        const Trig t = checked_tangent(p, "spatial_tangent");
        Mat3 H;
        H << t.c3 * t.c2, -t.s3, 0.0, t.s3 * t.c2, t.c3, 0.0, -t.s2, 0.0, 1.0;
        return H;
    }

    // (E3).
    static Tangent<3> material_tangent(const P& p) {
        const Trig t = checked_tangent(p, "material_tangent");
        Mat3 H;
        H << 1.0, 0.0, -t.s2, 0.0, t.c1, t.s1 * t.c2, 0.0, -t.s1, t.c1 * t.c2;
        return H;
    }

    // (E4).
    static TangentInverse<3> spatial_tangent_inverse(const P& p) {
        const Trig t = checked_tangent(p, "spatial_tangent_inverse");
        const double t2 = t.s2 / t.c2;
        Mat3 Hi;
        Hi << t.c3 / t.c2, t.s3 / t.c2, 0.0, -t.s3, t.c3, 0.0, t.c3 * t2, t.s3 * t2, 1.0;
        return Hi;
    }

    // (E5).
    static TangentInverse<3> material_tangent_inverse(const P& p) {
        const Trig t = checked_tangent(p, "material_tangent_inverse");
        const double t2 = t.s2 / t.c2;
        Mat3 Hi;
        Hi << 1.0, t.s1 * t2, t.c1 * t2, 0.0, t.c1, -t.s1, 0.0, t.s1 / t.c2, t.c1 / t.c2;
        return Hi;
    }

    // ∂(H_s v)/∂p of H_s v = v1 (c3c2, s3c2, −s2) + v2 (−s3, c3, 0) + v3 e3: no a1 dependence.
    static Mat3 spatial_tangent_derivative(const P& p, const P& v) {
        const Trig t = checked_tangent(p, "spatial_tangent_derivative");
        detail::require_finite(v, kName, "spatial_tangent_derivative");
        Mat3 D;
        D.col(0).setZero();
        D.col(1) = v[0] * Vec3(-t.c3 * t.s2, -t.s3 * t.s2, -t.c2);
        D.col(2) = v[0] * Vec3(-t.s3 * t.c2, t.c3 * t.c2, 0.0) + v[1] * Vec3(-t.c3, -t.s3, 0.0);
        return D;
    }

    // ∂(H_m v)/∂p of H_m v = v1 e1 + v2 (0, c1, −s1) + v3 (−s2, s1c2, c1c2): no a3 dependence.
    static Mat3 material_tangent_derivative(const P& p, const P& v) {
        const Trig t = checked_tangent(p, "material_tangent_derivative");
        detail::require_finite(v, kName, "material_tangent_derivative");
        Mat3 D;
        D.col(0) = v[1] * Vec3(0.0, -t.s1, -t.c1) + v[2] * Vec3(0.0, t.c1 * t.c2, -t.s1 * t.c2);
        D.col(1) = v[2] * Vec3(-t.c2, -t.s1 * t.s2, -t.c1 * t.s2);
        D.col(2).setZero();
        return D;
    }

    // ∂(H_s⁻¹ w)/∂p of H_s⁻¹ w = (u/c2, −s3w1 + c3w2, t2 u + w3), u = c3w1 + s3w2,
    // ∂u/∂a3 = −s3w1 + c3w2, d(1/c2)/da2 = s2/c2², d(t2)/da2 = 1/c2².
    static Mat3 spatial_tangent_inverse_derivative(const P& p, const Vec3& w) {
        const Trig t = checked_tangent(p, "spatial_tangent_inverse_derivative");
        detail::require_finite(w, kName, "spatial_tangent_inverse_derivative");
        const double u = t.c3 * w[0] + t.s3 * w[1];
        const double du = -t.s3 * w[0] + t.c3 * w[1];
        const double k = 1.0 / (t.c2 * t.c2);
        Mat3 D;
        D.col(0).setZero();
        D.col(1) = Vec3(u * t.s2 * k, 0.0, u * k);
        D.col(2) = Vec3(du / t.c2, -u, du * t.s2 / t.c2);
        return D;
    }

    // ∂(H_m⁻¹ w)/∂p of H_m⁻¹ w = (w1 + t2 v, c1w2 − s1w3, v/c2), v = s1w2 + c1w3,
    // ∂v/∂a1 = c1w2 − s1w3.
    static Mat3 material_tangent_inverse_derivative(const P& p, const Vec3& w) {
        const Trig t = checked_tangent(p, "material_tangent_inverse_derivative");
        detail::require_finite(w, kName, "material_tangent_inverse_derivative");
        const double v = t.s1 * w[1] + t.c1 * w[2];
        const double dv = t.c1 * w[1] - t.s1 * w[2];
        const double k = 1.0 / (t.c2 * t.c2);
        Mat3 D;
        D.col(0) = Vec3(dv * t.s2 / t.c2, -v, dv / t.c2);
        D.col(1) = Vec3(v * k, 0.0, v * t.s2 * k);
        D.col(2).setZero();
        return D;
    }

    // Principal rotation angle of R(p), in [0, π] (see the header comment).
    static double angle(const P& p) {
        checked(p, "angle");
        return so3::rotation_angle(matrix(p));
    }

    // The smallest rotation angle on the singular set: a quarter turn about the middle axis.
    static double singular_angle() { return 0.5 * kPi; }

    // The representative of R(p) nearest `reference` among the two branches shifted by 2π per
    // component (header comment). Unchecked: callers check their input.
    static P nearest(const P& p, const P& reference) {
        const auto shifted = [&](const P& q) {
            P out;
            for (int i = 0; i < 3; ++i) {
                out[i] = q[i] + 2.0 * kPi * std::round((reference[i] - q[i]) / (2.0 * kPi));
            }
            return out;
        };
        const P a = shifted(p);
        const P b = shifted(P(p[0] + kPi, kPi - p[1], p[2] + kPi));
        return (b - reference).squaredNorm() < (a - reference).squaredNorm() ? b : a;
    }

    static P rescale(const P& p, const P& reference) {
        checked(p, "rescale");
        checked(reference, "rescale");
        return nearest(p, reference);
    }

    static P from_rotation_vector(const Vec3& psi) {
        detail::require_finite(psi, kName, "from_rotation_vector");
        return principal(so3::exp_map(psi));
    }

    // Principal rotation vector of R(p) (angle in [0, π]).
    static Vec3 to_rotation_vector(const P& p) {
        checked(p, "to_rotation_vector");
        return so3::log_map(matrix(p));
    }
};

static_assert(RotationParameterization<EulerAngles>);

}  // namespace rotbeam::param
