// A deformed, moving state of the displacement dynamics for the Jacobian and allocation tests:
// the curved, twisted member of deformed.hpp (tip rotation 2.6 rad), non-zero nodal velocities,
// the consistent (non-zero) accelerations of that state, and a generalized-α step in progress
// whose increment is moved away from the predictor.
#pragma once

#include <cmath>

#include "deformed.hpp"
#include "formulations/displacement/displacement_dynamics.hpp"

namespace rotbeam::test {

// Damping coefficients μ (per strain component) on the curved member's section, or none.
inline Model moving_model(int elements, int order, bool damping) {
    Model m = curved_twisted(elements, order, true, true);
    // Loads with time functions: the follower tip load as a sine, the others constant.
    m.point_loads[0].time.kind = TimeFunction::Kind::sine;
    m.point_loads[0].time.omega = 3.0;
    m.point_loads[0].time.phase = 0.4;
    if (damping) {
        m.members[0].sections[0].section.damping << 0.01, 0.02, 0.015, 0.03, 0.012, 0.02;
    }
    m.analysis.kind = AnalysisKind::dynamic;
    return m;
}

template <class P>
void set_moving_state(form::DisplacementDynamics<P>& d, double rho_infinity = 0.6) {
    d.statics().set_load_factor(1.0);
    d.statics().retract(deforming_increment(d.mesh()));
    d.adopt_static_state();
    for (size_t i = 0; i < d.mesh().nodes.size(); ++i) {
        if (d.mesh().nodes[i].dof < 0) continue;
        const double t = static_cast<double>(i);
        Vec6 v;
        v << std::sin(t), 0.5 * std::cos(2 * t), -0.3, 0.7 * std::sin(3 * t + 1), -0.4,
            0.9 * std::cos(t);
        d.set_node_velocity(static_cast<int>(i), v);
        Vec6 a;
        a << 2.0 * std::cos(t), -1.5, std::sin(2 * t), 3.0 * std::cos(t + 2), 1.2, -2.5;
        d.set_node_acceleration(static_cast<int>(i), a);
    }
    d.begin_step(0.21, 0.01, GeneralizedAlpha::from_rho_infinity(rho_infinity));
    VecX dx(d.size());
    for (int k = 0; k < d.size(); ++k) dx[k] = 2e-3 * std::sin(0.7 * k + 0.3);
    d.retract(dx);
}

}  // namespace rotbeam::test
