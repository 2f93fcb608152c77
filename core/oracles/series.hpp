// Small-argument-safe sin(x)/x and (1 − cos x)/x, shared by the roll-up and helix oracles.
#pragma once

#include <cmath>

namespace rotbeam::oracle {

// Below this |x| the Taylor series to x⁶ is used; its truncation error x⁸/9! is < 1e-20 there.
inline constexpr double kSeriesThreshold = 1e-2;

inline double sinc(double x) {
    if (std::abs(x) < kSeriesThreshold) {
        const double x2 = x * x;
        return 1.0 - x2 / 6.0 * (1.0 - x2 / 20.0 * (1.0 - x2 / 42.0));
    }
    return std::sin(x) / x;
}

// (1 − cos x)/x.
inline double cosc(double x) {
    if (std::abs(x) < kSeriesThreshold) {
        const double x2 = x * x;
        return x / 2.0 * (1.0 - x2 / 12.0 * (1.0 - x2 / 30.0 * (1.0 - x2 / 56.0)));
    }
    return (1.0 - std::cos(x)) / x;
}

}  // namespace rotbeam::oracle
