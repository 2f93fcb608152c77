// The shared hard sample set and the helpers the parameterization tests
// share: which samples each parameterization's chart contains, distances to its singular set
// (the tolerances grow like ε/δ), and fixed-size central differences.
#pragma once

#include <boost/mpl/list.hpp>
#include <cmath>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

#include "core/so3.hpp"
#include "parameterizations/registry.hpp"

namespace rotbeam::test {

namespace detail {
template <class List>
struct AsMplList;
template <class... Ts>
struct AsMplList<param::TypeList<Ts...>> {
    using type = boost::mpl::list<Ts...>;
};
}  // namespace detail

// Every registered parameterization (parameterizations/registry.hpp), for
// BOOST_AUTO_TEST_CASE_TEMPLATE.
using AllParameterizationTypes = detail::AsMplList<param::AllParameterizations>::type;

inline constexpr double kEps = std::numeric_limits<double>::epsilon();

struct Sample {
    double angle;
    std::string label;
};

// 0, 1e-12, 1e-8, 1e-4 rad, π/2, π − 1e-6, just past π, 2π − 1e-6, 3π.
inline std::vector<Sample> hard_samples() {
    return {{0.0, "0"},
            {1e-12, "1e-12"},
            {1e-8, "1e-8"},
            {1e-4, "1e-4"},
            {0.5 * kPi, "pi/2"},
            {kPi - 1e-6, "pi-1e-6"},
            {kPi + 1e-6, "pi+1e-6"},
            {2.0 * kPi - 1e-6, "2pi-1e-6"},
            {3.0 * kPi, "3pi"}};
}

// A generic axis (no component zero, no two equal) and a second, independent one.
inline Vec3 generic_axis() { return Vec3(1.0, -2.0, 3.0).normalized(); }
inline Vec3 other_axis() { return Vec3(2.0, 1.0, -0.5).normalized(); }

// Distance of φ to the nearest 2πk, k ≥ 1.
inline double distance_to_full_turns(double phi) {
    const double k = std::max(1.0, std::round(phi / (2.0 * kPi)));
    return std::abs(phi - 2.0 * kPi * k);
}

// Whether from_rotation_vector(φ n) lies in P's chart (WM and Rodrigues end at their singular
// angle; the quaternion, the rotation vector and the Euler angles take any angle).
template <class P>
bool chart_contains(double phi) {
    if constexpr (std::is_same_v<P, param::RotationVector> ||
                  std::is_same_v<P, param::Quaternion> || std::is_same_v<P, param::EulerAngles>) {
        return true;
    } else {
        return phi < P::singular_angle();
    }
}

// Distance δ (rad) to where P's tangent operators are singular, for the rotation φ about the
// generic axis (the Euler angles' singular set is gimbal lock, not an angle).
template <class P>
double tangent_distance(double phi) {
    if constexpr (std::is_same_v<P, param::Quaternion>) {
        return std::numeric_limits<double>::infinity();
    } else if constexpr (std::is_same_v<P, param::EulerAngles>) {
        return P::gimbal_distance(P::from_rotation_vector(phi * generic_axis()));
    } else if constexpr (std::is_same_v<P, param::RotationVector>) {
        return distance_to_full_turns(phi);
    } else {
        return P::singular_angle() - phi;
    }
}

// Distance δ (rad) to where P's conversion to a rotation vector is ill-conditioned: the
// quaternion's axis is lost at 2πk (v → 0 with w → −1), WM and Rodrigues at their singular angle;
// the Euler angles return the principal rotation vector of R, whose axis is lost at 2πk too.
template <class P>
double conversion_distance(double phi) {
    if constexpr (std::is_same_v<P, param::Quaternion> || std::is_same_v<P, param::EulerAngles>) {
        return distance_to_full_turns(phi);
    } else if constexpr (std::is_same_v<P, param::RotationVector>) {
        return std::numeric_limits<double>::infinity();
    } else {
        return P::singular_angle() - phi;
    }
}

// The length over which P's functions of p vary: the parameter norm (at least 1) for R and H of
// every chart (WM, Rodrigues and the quaternion are rational in p, the rotation vector's and the
// Euler angles' R and H are entire); for the rotation vector's H⁻¹ ~ 1/δ also the distance δ to
// the singularity at 2πk, for the Euler angles' H⁻¹ ~ 1/cos a2 the distance to gimbal lock.
template <class P>
double variation_length(const typename P::P& p, bool of_inverse) {
    const double length = std::max(1.0, p.norm());
    if constexpr (std::is_same_v<P, param::RotationVector>) {
        return of_inverse ? std::min(length, distance_to_full_turns(p.norm())) : length;
    } else if constexpr (std::is_same_v<P, param::EulerAngles>) {
        return of_inverse ? std::min(length, P::gimbal_distance(p)) : length;
    } else {
        return length;
    }
}

// Central difference of f along direction d with step h.
template <class F, class Vp>
auto central_difference(const F& f, const Vp& p, const Vp& d, double h) {
    using R = std::decay_t<decltype(f(p))>;
    const Vp pp = p + h * d;
    const Vp pm = p - h * d;
    const R fp = f(pp);
    const R fm = f(pm);
    const R out = (fp - fm) / (2.0 * h);
    return out;
}

// Tolerance of a central difference with step h = ∛ε L of a function G varying on length L:
// truncation h²/6 ‖G‴‖ ≈ ε^(2/3) ‖G′‖ (G‴ ~ G′/L²; the factor 10 covers the unknown ratio of
// third to first derivative on that scale) plus round-off of the two evaluations divided by h:
// ε ‖G‖ from evaluating G and ε ‖p‖ ‖G′‖ from rounding p ± h d, which dominates near a
// singularity where G′ is large (the rotation vector's H⁻¹ at 2π − 1e-6: ‖G′‖ ~ φ/δ²).
inline double fd_tolerance(double norm_derivative, double norm_value, double h, double norm_point) {
    return 10.0 * (std::cbrt(kEps * kEps) * norm_derivative +
                   kEps * (norm_value + norm_point * norm_derivative) / h);
}

}  // namespace rotbeam::test
