#include "core/oracles/helix.hpp"

#include "core/errors.hpp"
#include "core/oracles/series.hpp"
#include "core/so3.hpp"

namespace rotbeam::oracle {

HelixState helix_state(double kappa, const Vec3& axis, double s) {
    ROTBEAM_VERIFY(axis.norm() > 0.0, "helix axis must be non-zero");
    const Vec3 n = axis.normalized();
    const Vec3 e1 = Vec3::UnitX();
    const double a = n.dot(e1);
    const Vec3 b = e1 - a * n;  // component of the reference tangent normal to the axis
    const double theta = kappa * s;
    // x(s) = ∫₀ˢ exp(κ t ñ) e₁ dt, exp(θñ) b = b cos θ + (n × b) sin θ (Rodrigues' formula).
    const Vec3 x = a * s * n + s * sinc(theta) * b + s * cosc(theta) * n.cross(b);
    HelixState state;
    state.displacement = x - s * e1;
    state.rotation_vector = theta * n;
    state.rotation = so3::exp_map(state.rotation_vector);
    return state;
}

Vec3 helix_moment(double kappa, double bending_stiffness, const Vec3& axis) {
    ROTBEAM_VERIFY(axis.norm() > 0.0 && bending_stiffness > 0.0, "helix needs n ≠ 0 and EI > 0");
    return kappa * bending_stiffness * axis.normalized();
}

}  // namespace rotbeam::oracle
