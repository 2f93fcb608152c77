// The deformed (and moving) states of the mixed formulation's Jacobian tests, for three and four
// rotation parameters alike: rotations of base + 0.5 sin(1.3 k) rad (2.1–2.6 rad for the default
// base) about axes that vary along the structure, quaternions scaled off the unit sphere by
// 0.8–1.2 (R = C(q)/|q|² must not care, its derivatives must carry the 1/|q|² terms), the scale ρ
// of a second support at −0.9 (the other sign of a closure), unit-order displacements and section
// resultants, and unit-order rates of every unknown (the algebraic ones too: F must not depend on
// them).
#pragma once

#include <cmath>

#include "core/types.hpp"
#include "formulations/mixed/mixed_layout.hpp"

namespace rotbeam::test {

template <class P>
VecX deformed_mixed_state(const form::MixedNumbering& nb, double base = 2.1) {
    VecX x(nb.size());
    for (Eigen::Index i = 0; i < x.size(); ++i)
        x[i] = 0.5 * std::sin(0.37 * static_cast<double>(i) + 0.2);
    auto set_rotation = [&](int column, int k) {
        const Vec3 axis = Vec3(std::cos(0.9 * k), std::sin(0.9 * k), 0.5).normalized();
        typename P::P p = P::from_rotation_vector((base + 0.5 * std::sin(1.3 * k)) * axis);
        if constexpr (P::kSize == 4) p *= 1.0 + 0.2 * std::sin(2.1 * k + 0.4);
        x.segment<P::kSize>(column) = p;
    };
    for (int n = 0; n < nb.node_count(); ++n) {
        if (!nb.supported(n)) set_rotation(nb.node_column(n) + nb.c(), n);
        if (nb.has_scale(n)) x[nb.node_column(n) + 6] = -0.9;
    }
    for (int e = 0; e < nb.element_count; ++e) set_rotation(nb.element_column(e) + nb.c(), e + 7);
    return x;
}

inline VecX mixed_rates(Eigen::Index size) {
    VecX xdot(size);
    for (Eigen::Index i = 0; i < size; ++i)
        xdot[i] = 0.7 * std::cos(0.53 * static_cast<double>(i) + 0.1);
    return xdot;
}

}  // namespace rotbeam::test
