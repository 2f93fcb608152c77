#include "core/oracles/rollup.hpp"

#include "core/errors.hpp"
#include "core/oracles/series.hpp"
#include "core/so3.hpp"

namespace rotbeam::oracle {

double rollup_moment(double length, double bending_stiffness, double lambda) {
    ROTBEAM_VERIFY(length > 0.0 && bending_stiffness > 0.0, "roll-up needs L > 0 and EI > 0");
    return lambda * kPi * bending_stiffness / length;
}

RollupState rollup_state(double length, double lambda, double s) {
    ROTBEAM_VERIFY(length > 0.0, "roll-up needs L > 0");
    // θ(s) = κ s with κ = λπ/L; x(s) = ∫ (cos κt, 0, sin κt) dt = s (sinc θ, 0, cosc θ).
    const double theta = lambda * kPi * s / length;
    RollupState state;
    state.angle = theta;
    state.displacement = Vec3(s * sinc(theta) - s, 0.0, s * cosc(theta));
    state.rotation = so3::exp_map(Vec3(0.0, -theta, 0.0));
    return state;
}

}  // namespace rotbeam::oracle
