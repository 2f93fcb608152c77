// Rotation-vector (exponential-map) parameterization of rotations (seed 000's δψ increments;
// docs/architecture.md, Shared conventions).
//
// Definition: ψ = φ n, kSize = 3; R(ψ) = exp(ψ̃) maps material to inertial components and is
// defined for every finite ψ (any angle, not reduced):
//     R = I + α ψ̃ + a ψ̃²,  α = sin φ/φ,  a = (1 − cos φ)/φ²                              (V1)
// Tangents (the left and right Jacobians of SO(3), "dexp"):
//     spatial  H_s = I + a ψ̃ + b ψ̃²    (δR Rᵀ = (H_s δψ)~),  b = (φ − sin φ)/φ³          (V2)
//     material H_m = I − a ψ̃ + b ψ̃²    (Rᵀ δR = (H_m δψ)~, H_m = Rᵀ H_s)               (V3)
//     H_s⁻¹ = I − ψ̃/2 + g ψ̃²,  H_m⁻¹ = I + ψ̃/2 + g ψ̃²,  g = (1 − (φ/2) cot(φ/2))/φ²    (V4)
// Singular set: the tangents are singular (det H = 2(1 − cos φ)/φ² = 0) at φ = 2πk, k ≥ 1;
// singular_angle() = 2π is the first. R, compose, inverse and the conversions are defined
// everywhere (finite input).
// Refused (SingularityError): non-finite input everywhere; the tangents, their inverses and
// their derivatives within detail::kSingularGuard of φ = 2πk, k ≥ 1.
// Rescale: ψ ↦ (φ + 2πk) n, the same R, with the integer k that brings it nearest the reference
// (reference 0 gives the principal value, φ ≤ π).
// Small angles: below kSeriesAngle the coefficients and their derivatives use Taylor series to
// φ⁸ (truncation < φ¹⁰/4e7 ≈ 3e-18 at the threshold); above it the closed forms lose at most
// ~ε/φ ≈ 2e-15 in the derivative coefficients, nothing in R and H.
#pragma once

#include <cmath>

#include "core/so3.hpp"
#include "parameterizations/concept.hpp"
#include "parameterizations/detail.hpp"

namespace rotbeam::param {

struct RotationVector {
    static constexpr int kSize = 3;
    static constexpr std::string_view kName = "rotation-vector";
    static constexpr bool kCanRescale = true;
    using P = Params<3>;

    static constexpr double kSeriesAngle = 0.1;

    // The scalar coefficients of (V1)–(V4) and the derivatives a1 = a'/φ, b1 = b'/φ, g1 = g'/φ.
    struct Coefficients {
        double alpha, a, b, a1, b1;
    };
    struct InverseCoefficients {
        double g, g1;
    };

    static P identity() { return P::Zero(); }

    static Coefficients coefficients(double phi) {
        const double x = phi * phi;
        if (phi < kSeriesAngle) {
            return {1.0 - x / 6.0 * (1.0 - x / 20.0 * (1.0 - x / 42.0 * (1.0 - x / 72.0))),
                    0.5 - x / 24.0 * (1.0 - x / 30.0 * (1.0 - x / 56.0 * (1.0 - x / 90.0))),
                    1.0 / 6.0 - x / 120.0 * (1.0 - x / 42.0 * (1.0 - x / 72.0 * (1.0 - x / 110.0))),
                    -1.0 / 12.0 + x / 180.0 - x * x / 6720.0 + x * x * x / 453600.0 -
                        x * x * x * x / 47900160.0,
                    -1.0 / 60.0 + x / 1260.0 - x * x / 60480.0 + x * x * x / 4989600.0 -
                        x * x * x * x / 622702080.0};
        }
        const double s = std::sin(phi);
        const double h = std::sin(0.5 * phi);
        const double one_minus_cos = 2.0 * h * h;
        const double a = one_minus_cos / x;
        const double b = (phi - s) / (x * phi);
        return {s / phi, a, b, (phi * s - 2.0 * one_minus_cos) / (x * x),
                one_minus_cos / (x * x) - 3.0 * b / x};
    }

    // g and g1 of (V4); the caller has excluded φ = 2πk.
    static InverseCoefficients inverse_coefficients(double phi) {
        const double x = phi * phi;
        if (phi < kSeriesAngle) {
            return {1.0 / 12.0 + x / 720.0 + x * x / 30240.0 + x * x * x / 1209600.0 +
                        x * x * x * x / 47900160.0,
                    1.0 / 360.0 + x / 7560.0 + x * x / 201600.0 + x * x * x / 5987520.0};
        }
        const double sh = std::sin(0.5 * phi);
        const double cot = std::cos(0.5 * phi) / sh;
        const double g = 1.0 / x - cot / (2.0 * phi);
        const double dg = -2.0 / (x * phi) + 1.0 / (4.0 * phi * sh * sh) + cot / (2.0 * x);
        return {g, dg / phi};
    }

    // Refuses non-finite ψ; returns φ = |ψ|.
    static double checked_angle(const P& psi, const char* function) {
        detail::require_finite(psi, kName, function);
        return psi.norm();
    }

    // Also refuses φ within kSingularGuard of 2πk, k ≥ 1 (where the tangents are singular).
    static double checked_tangent_angle(const P& psi, const char* function) {
        const double phi = checked_angle(psi, function);
        const double k = std::round(phi / (2.0 * kPi));
        if (k >= 1.0 && std::abs(phi - 2.0 * kPi * k) <= detail::kSingularGuard) {
            detail::refuse(kName, function, phi, "tangent singular at 2πk");
        }
        return phi;
    }

    // (V1), any finite ψ.
    static Mat3 matrix(const P& psi) {
        const Coefficients c = coefficients(checked_angle(psi, "matrix"));
        const Mat3 k = detail::hat(psi);
        return Mat3::Identity() + c.alpha * k + c.a * k * k;
    }

    // The representative (φ0 + 2πk) n of the rotation φ0 n nearest `target`; for φ0 n = 0 the
    // axis is free and taken from the target.
    static P nearest_representative(const P& psi0, const P& target) {
        const double phi0 = psi0.norm();
        if (phi0 == 0.0) {
            const double t = target.norm();
            const double k = std::round(t / (2.0 * kPi));
            return k == 0.0 ? P(P::Zero()) : P((2.0 * kPi * k / t) * target);
        }
        const P n = psi0 / phi0;
        const double k = std::round((n.dot(target) - phi0) / (2.0 * kPi));
        return (phi0 + 2.0 * kPi * k) * n;
    }

    // R(compose(a, b)) = R(a) R(b), through the quaternion product; of the equivalent rotation
    // vectors, the one nearest a + b (so a small increment never jumps the chart). Any finite
    // input.
    static P compose(const P& a, const P& b) {
        checked_angle(a, "compose");
        checked_angle(b, "compose");
        const Vec4 q = so3::quat_multiply(so3::quat_from_rotvec(a), so3::quat_from_rotvec(b));
        const double sn = q.tail<3>().norm();
        const P principal =
            sn == 0.0 ? P(P::Zero()) : P((2.0 * std::atan2(sn, q[0]) / sn) * q.tail<3>());
        return nearest_representative(principal, a + b);
    }

    static P inverse(const P& psi) {
        checked_angle(psi, "inverse");
        return -psi;
    }

    // I + sign a ψ̃ + b ψ̃²: sign +1 spatial (V2), −1 material (V3).
    static Mat3 tangent(const P& psi, double sign, const char* function) {
        const Coefficients c = coefficients(checked_tangent_angle(psi, function));
        const Mat3 k = detail::hat(psi);
        return Mat3::Identity() + sign * c.a * k + c.b * k * k;
    }
    static Tangent<3> spatial_tangent(const P& psi) { return tangent(psi, 1.0, "spatial_tangent"); }
    static Tangent<3> material_tangent(const P& psi) {
        return tangent(psi, -1.0, "material_tangent");
    }

    // (V4): I − sign ψ̃/2 + g ψ̃².
    static Mat3 tangent_inverse(const P& psi, double sign, const char* function) {
        const InverseCoefficients c = inverse_coefficients(checked_tangent_angle(psi, function));
        const Mat3 k = detail::hat(psi);
        return Mat3::Identity() - 0.5 * sign * k + c.g * k * k;
    }
    static TangentInverse<3> spatial_tangent_inverse(const P& psi) {
        return tangent_inverse(psi, 1.0, "spatial_tangent_inverse");
    }
    static TangentInverse<3> material_tangent_inverse(const P& psi) {
        return tangent_inverse(psi, -1.0, "material_tangent_inverse");
    }

    // ∂(ψ × (ψ × v))/∂ψ = (ψ·v) I + ψ vᵀ − 2 v ψᵀ.
    static Mat3 double_cross_derivative(const P& psi, const Vec3& v) {
        return psi.dot(v) * Mat3::Identity() + psi * v.transpose() - 2.0 * v * psi.transpose();
    }

    // ∂(H v)/∂ψ of H v = v + sign a ψ × v + b ψ × (ψ × v), ∂a/∂ψ = a1 ψᵀ, ∂b/∂ψ = b1 ψᵀ.
    static Mat3 tangent_derivative(const P& psi, const Vec3& v, double sign, const char* fn) {
        const Coefficients c = coefficients(checked_tangent_angle(psi, fn));
        detail::require_finite(v, kName, fn);
        const Vec3 pv = psi.cross(v);
        const Vec3 ppv = psi.cross(pv);
        return sign * (c.a1 * pv * psi.transpose() - c.a * detail::hat(v)) +
               c.b1 * ppv * psi.transpose() + c.b * double_cross_derivative(psi, v);
    }
    static Mat3 spatial_tangent_derivative(const P& psi, const P& v) {
        return tangent_derivative(psi, v, 1.0, "spatial_tangent_derivative");
    }
    static Mat3 material_tangent_derivative(const P& psi, const P& v) {
        return tangent_derivative(psi, v, -1.0, "material_tangent_derivative");
    }

    // ∂(H⁻¹ w)/∂ψ of H⁻¹ w = w − sign ψ × w/2 + g ψ × (ψ × w).
    static Mat3 tangent_inverse_derivative(const P& psi, const Vec3& w, double sign,
                                           const char* fn) {
        const InverseCoefficients c = inverse_coefficients(checked_tangent_angle(psi, fn));
        detail::require_finite(w, kName, fn);
        const Vec3 ppw = psi.cross(psi.cross(w));
        return 0.5 * sign * detail::hat(w) + c.g1 * ppw * psi.transpose() +
               c.g * double_cross_derivative(psi, w);
    }
    static Mat3 spatial_tangent_inverse_derivative(const P& psi, const Vec3& w) {
        return tangent_inverse_derivative(psi, w, 1.0, "spatial_tangent_inverse_derivative");
    }
    static Mat3 material_tangent_inverse_derivative(const P& psi, const Vec3& w) {
        return tangent_inverse_derivative(psi, w, -1.0, "material_tangent_inverse_derivative");
    }

    // φ = |ψ|, not reduced.
    static double angle(const P& psi) { return checked_angle(psi, "angle"); }

    static double singular_angle() { return 2.0 * kPi; }

    // (φ + 2πk) n nearest the reference. Refuses non-finite input.
    static P rescale(const P& psi, const P& reference) {
        checked_angle(psi, "rescale");
        checked_angle(reference, "rescale");
        return nearest_representative(psi, reference);
    }

    static P from_rotation_vector(const Vec3& psi) {
        checked_angle(psi, "from_rotation_vector");
        return psi;
    }
    static Vec3 to_rotation_vector(const P& psi) {
        checked_angle(psi, "to_rotation_vector");
        return psi;
    }

    // The principal value (φ ≤ π), robust near 0 and π (so3::log_map). Refuses a non-finite R.
    static P from_matrix(const Mat3& R) {
        detail::require_finite(R, kName, "from_matrix");
        return so3::log_map(R);
    }

    // compose(dpsi, ψ): the spatial update R ← exp(dψ~) R.
    static P retract_spatial(const P& psi, const Vec3& dpsi) { return compose(dpsi, psi); }
};

static_assert(RotationParameterization<RotationVector>);

}  // namespace rotbeam::param
