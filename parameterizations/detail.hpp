// Helpers shared by the parameterization headers (not part of the concept).
//
// Every parameterization refuses non-finite input and inputs at or beyond its singular set by
// throwing SingularityError(kName, function, angle). The guard below is the distance (in radians
// of rotation angle) to the singular set at which the refusal starts: closer than that the
// parameters are so large (WM: |c| > 1.6e13, Rodrigues: |p| > 4e12) that the tangent operators
// have lost every digit (σ_min(H) ~ 1/|p|² < 1e-24), so a caller asking there has a bug or
// needs to rescale, and is told so instead of receiving numbers that mean nothing.
#pragma once

#include <cmath>
#include <limits>
#include <string>
#include <string_view>

#include "core/errors.hpp"
#include "core/types.hpp"

namespace rotbeam::param::detail {

inline constexpr double kSingularGuard = 1e-12;  // rad, distance to the singular set refused
inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

[[noreturn]] inline void refuse(std::string_view parameterization, const char* function,
                                double angle, const char* detail) {
    throw SingularityError(std::string(parameterization), function, angle, detail);
}

template <class Derived>
inline void require_finite(const Eigen::MatrixBase<Derived>& x, std::string_view parameterization,
                           const char* function) {
    if (!x.allFinite()) refuse(parameterization, function, kNaN, "non-finite input");
}

// The skew matrix a~ with a~ b = a × b, inline so that the headers stay allocation-free and
// inlinable in hot loops (so3::skew is the out-of-line equivalent).
inline Mat3 hat(const Vec3& a) {
    Mat3 m;
    m << 0.0, -a.z(), a.y(), a.z(), 0.0, -a.x(), -a.y(), a.x(), 0.0;
    return m;
}

}  // namespace rotbeam::param::detail
