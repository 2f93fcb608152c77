// Rodrigues parameterization of rotations (docs/architecture.md; Hodges 2006, Yu & Blair 2012,
// the GEBT convention; seed 002 Eq. 11 with generating function p(φ) = 2 tan(φ/2)).
//
// Definition: p = 2 tan(φ/2) n, kSize = 3. (Gibbs' vector tan(φ/2) n is p/2: no solution
// changes, but the scale of H, norm thresholds and Newton increment norms do; every threshold
// here is stated for p = 2 tan(φ/2) n.) With D = 1 + pᵀp/4, (1, p/2)/√D is the unit quaternion
// (cos φ/2, sin φ/2 n): Rodrigues is the gnomonic projection of the quaternion sphere.
// R maps material to inertial components (seed 002 writes Rᵀ, the GEBT C):
//     R(p) = [(1 − pᵀp/4) I + p̃ + p pᵀ/2] / D                                        (R1)
//     material H_m = (I − p̃/2)/D (GEBT's Q),  H_m⁻¹ = I + p̃/2 + p pᵀ/4    (Rᵀ δR = (H_m δp)~)
//     spatial  H_s = (I + p̃/2)/D = R H_m,     H_s⁻¹ = I − p̃/2 + p pᵀ/4    (δR Rᵀ = (H_s δp)~)
// Singular set: φ = π (|p| → ∞); every finite p has φ = 2 atan(|p|/2) < π.
// Refused (SingularityError): non-finite input; parameters within detail::kSingularGuard of π
// (|p| > 2/tan(kSingularGuard/2) ≈ 4e12); rotation vectors with |ψ| ≥ π − guard; compositions and
// matrices whose rotation is at (or, for compose, past) π.
// No rescale (kCanRescale = false; rescale returns p unchanged): p ↦ R is a bijection between R³
// and the rotations of angle < π, because φ and φ − 2π give the same tan(φ/2). There is no second
// chart to switch to; a rotation past π has no Rodrigues parameters on a continuous path from
// the identity, which is why the Rodrigues mixed formulation stops short of π (seed 002 Table I).
// compose is the closed-form Rodrigues composition (p = (a + b + a × b/2)/(1 − a·b/4)).
#pragma once

#include <cmath>

#include "core/so3.hpp"
#include "parameterizations/concept.hpp"
#include "parameterizations/detail.hpp"

namespace rotbeam::param {

struct Rodrigues {
    static constexpr int kSize = 3;
    static constexpr std::string_view kName = "rodrigues";
    static constexpr bool kCanRescale = false;
    using P = Params<3>;

    // Below |p|, φ < kSeriesNorm the tan/atan ratios use their series (next terms ~φ⁶/1e2,
    // < 1e-25 relative) instead of dividing by a vanishing norm.
    static constexpr double kSeriesNorm = 1e-4;

    static P identity() { return P::Zero(); }

    // |p| beyond which φ is within kSingularGuard of π: π − φ = 2 atan(2/|p|), so the limit is
    // 2/tan(kSingularGuard/2) = 4/kSingularGuard (tan x = x to 1e-25 relative at x ~ 1e-12).
    // Comparing norms keeps atan out of every call; it is evaluated only to report a refusal.
    static constexpr double kMaxNorm = 4.0 / detail::kSingularGuard;

    // Refuses non-finite p and p within kSingularGuard of φ = π; returns pᵀp.
    static double checked_squared_norm(const P& p, const char* function) {
        detail::require_finite(p, kName, function);
        const double s = p.squaredNorm();
        if (!(s < kMaxNorm * kMaxNorm)) {
            const double distance = 2.0 * std::atan2(2.0, std::sqrt(s));  // π − φ
            detail::refuse(kName, function, kPi - distance, "at the singular angle π");
        }
        return s;
    }

    // (R1). Refuses what checked_squared_norm refuses.
    static Mat3 matrix(const P& p) {
        const double s = checked_squared_norm(p, "matrix");
        const Mat3 m =
            (1.0 - 0.25 * s) * Mat3::Identity() + detail::hat(p) + 0.5 * p * p.transpose();
        return m / (1.0 + 0.25 * s);
    }

    // R(compose(a, b)) = R(a) R(b). Refuses non-finite or singular input and a result at or past
    // π (1 − a·b/4 ≤ 0).
    static P compose(const P& a, const P& b) {
        checked_squared_norm(a, "compose");
        checked_squared_norm(b, "compose");
        const double denominator = 1.0 - 0.25 * a.dot(b);
        if (!(denominator > 0.0)) detail::refuse(kName, "compose", kPi, "result at or past π");
        const P p = (a + b + 0.5 * a.cross(b)) / denominator;
        checked_squared_norm(p, "compose");
        return p;
    }

    static P inverse(const P& p) {
        checked_squared_norm(p, "inverse");
        return -p;
    }

    // (I + sign p̃/2)/D: sign +1 spatial, −1 material.
    static Mat3 tangent(const P& p, double sign, const char* function) {
        const double s = checked_squared_norm(p, function);
        return (Mat3::Identity() + 0.5 * sign * detail::hat(p)) / (1.0 + 0.25 * s);
    }
    static Tangent<3> spatial_tangent(const P& p) { return tangent(p, 1.0, "spatial_tangent"); }
    static Tangent<3> material_tangent(const P& p) { return tangent(p, -1.0, "material_tangent"); }

    // I − sign p̃/2 + p pᵀ/4.
    static Mat3 tangent_inverse(const P& p, double sign, const char* function) {
        checked_squared_norm(p, function);
        return Mat3::Identity() - 0.5 * sign * detail::hat(p) + 0.25 * p * p.transpose();
    }
    static TangentInverse<3> spatial_tangent_inverse(const P& p) {
        return tangent_inverse(p, 1.0, "spatial_tangent_inverse");
    }
    static TangentInverse<3> material_tangent_inverse(const P& p) {
        return tangent_inverse(p, -1.0, "material_tangent_inverse");
    }

    // ∂(H v)/∂p of H v = (v + sign p × v/2)/D, ∂D/∂p = pᵀ/2.
    static Mat3 tangent_derivative(const P& p, const Vec3& v, double sign, const char* fn) {
        const double s = checked_squared_norm(p, fn);
        detail::require_finite(v, kName, fn);
        const double d = 1.0 + 0.25 * s;
        const Vec3 n = v + 0.5 * sign * p.cross(v);
        return (-0.5 * sign * detail::hat(v) - n * p.transpose() / (2.0 * d)) / d;
    }
    static Mat3 spatial_tangent_derivative(const P& p, const P& v) {
        return tangent_derivative(p, v, 1.0, "spatial_tangent_derivative");
    }
    static Mat3 material_tangent_derivative(const P& p, const P& v) {
        return tangent_derivative(p, v, -1.0, "material_tangent_derivative");
    }

    // ∂(H⁻¹ w)/∂p of H⁻¹ w = w − sign p × w/2 + p (p·w)/4.
    static Mat3 tangent_inverse_derivative(const P& p, const Vec3& w, double sign, const char* fn) {
        checked_squared_norm(p, fn);
        detail::require_finite(w, kName, fn);
        return 0.5 * sign * detail::hat(w) +
               0.25 * (p.dot(w) * Mat3::Identity() + p * w.transpose());
    }
    static Mat3 spatial_tangent_inverse_derivative(const P& p, const Vec3& w) {
        return tangent_inverse_derivative(p, w, 1.0, "spatial_tangent_inverse_derivative");
    }
    static Mat3 material_tangent_inverse_derivative(const P& p, const Vec3& w) {
        return tangent_inverse_derivative(p, w, -1.0, "material_tangent_inverse_derivative");
    }

    // φ = 2 atan(|p|/2) ∈ [0, π).
    static double angle(const P& p) {
        checked_squared_norm(p, "angle");
        return 2.0 * std::atan(0.5 * p.norm());
    }

    static double singular_angle() { return kPi; }

    // No rescale exists (see the header comment): returns p unchanged after checking it.
    static P rescale(const P& p, const P& reference) {
        checked_squared_norm(p, "rescale");
        checked_squared_norm(reference, "rescale");
        return p;
    }

    // 2 tan(φ/2) n. Refuses non-finite ψ and |ψ| ≥ π − kSingularGuard (a rotation past π is
    // representable only after reducing ψ to its principal value, off this continuous path).
    static P from_rotation_vector(const Vec3& psi) {
        detail::require_finite(psi, kName, "from_rotation_vector");
        const double phi = psi.norm();
        if (!(phi < kPi - detail::kSingularGuard)) {
            detail::refuse(kName, "from_rotation_vector", phi, "at or beyond the singular angle π");
        }
        if (phi < kSeriesNorm) {
            const double p2 = phi * phi;
            return (1.0 + p2 / 12.0 + p2 * p2 / 120.0) * psi;
        }
        // tan may round |p| just past the norm limit right at the guard: check the result too.
        const P p = (2.0 * std::tan(0.5 * phi) / phi) * psi;
        checked_squared_norm(p, "from_rotation_vector");
        return p;
    }

    // φ n with φ = 2 atan(|p|/2) ∈ [0, π). Refuses non-finite or singular p.
    static Vec3 to_rotation_vector(const P& p) {
        const double s = checked_squared_norm(p, "to_rotation_vector");
        const double n = std::sqrt(s);
        if (n < kSeriesNorm) return (1.0 - s / 12.0 + s * s / 80.0) * p;
        return (2.0 * std::atan(0.5 * n) / n) * p;
    }

    // Through Shepperd's quaternion (w ≥ 0): p = 2 v/w. Refuses a non-finite R and rotations
    // within kSingularGuard of π.
    static P from_matrix(const Mat3& R) {
        detail::require_finite(R, kName, "from_matrix");
        const Vec4 q = so3::quat_from_matrix(R);
        if (!(q[0] > 0.0)) detail::refuse(kName, "from_matrix", kPi, "rotation by π");
        const P p = (2.0 / q[0]) * q.tail<3>();
        checked_squared_norm(p, "from_matrix");
        return p;
    }

    // compose(from_rotation_vector(dpsi), p): the spatial update R ← exp(dψ~) R.
    static P retract_spatial(const P& p, const Vec3& dpsi) {
        return compose(from_rotation_vector(dpsi), p);
    }
};

static_assert(RotationParameterization<Rodrigues>);

}  // namespace rotbeam::param
