// The manufactured load fields (Model::load_fields) on one mixed element: f̄^∓ = ∫ N∓ f ds,
// m̄^∓ = ∫ N∓ μ ds over the element with the linear end functions N∓ = (1 ∓ ξ)/2 — for a load
// constant along the element these are seed 002's h f, h m (Eqs. 51–54), which is how the element
// carries a constant load. The loads are dead (no Jacobian term). Used by the mixed statics
// and the mixed dynamics (at λ = 1 and the step's time). The element is the chord of a
// straight member here, so the arc length at ξ is s_mid + hξ.
#pragma once

#include <vector>

#include "core/model.hpp"
#include "core/quadrature.hpp"
#include "formulations/mixed/mixed_layout.hpp"

namespace rotbeam::form {

// Subtracts f̄^∓, m̄^∓ from the equilibrium rows of the element's start (a) and end (b) nodes, as
// the element equations subtract h f, h m (Eqs. 45–46). Returns the number of fields applied.
// `time`: the dynamics' time (fields in time, LoadField::density_in_time); statics pass none (0).
inline int add_mixed_load_fields(const std::vector<LoadField>& fields, const MixedElement& el,
                                 double lambda, const QuadratureRule& rule, int a, int b,
                                 VecX& residual, double time = 0.0) {
    const double h = 0.5 * el.length;
    int applied = 0;
    for (const LoadField& l : fields) {
        if (l.member != el.member) continue;
        ++applied;
        for (std::size_t q = 0; q < rule.points.size(); ++q) {
            const double xi = rule.points[q];
            const double w = rule.weights[q] * h;
            Vec3 f, m;
            l.evaluate(el.s_mid + h * xi, lambda, time, f, m);
            residual.segment<3>(a) -= 0.5 * (1.0 - xi) * w * f;
            residual.segment<3>(a + 3) -= 0.5 * (1.0 - xi) * w * m;
            residual.segment<3>(b) -= 0.5 * (1.0 + xi) * w * f;
            residual.segment<3>(b + 3) -= 0.5 * (1.0 + xi) * w * m;
        }
    }
    return applied;
}

// The rule the statics and the dynamics integrate the fields with: 4 Gauss points, exact to degree
// 7 (the element is second order; the integration error is far below its own).
inline const QuadratureRule& mixed_load_field_rule() {
    static const QuadratureRule rule = gauss_legendre(4);
    return rule;
}

}  // namespace rotbeam::form
