// The inertial force of a section turning rigidly with a steady rotating frame (core/model.hpp,
// RotatingFrame) and its tangent, for the statics of both formulations in that frame.
//
// A section at position x (centre of the reference line) whose frame is Q, turning with constant
// angular velocity Ω about the axis through c, has u¨ = Ω̃Ω̃ r (r = x − c), ω = Ω, ω˙ = 0. Its
// inertial force is F^I of calculate_inertial_forces.hpp at that state:
//   F^I = [ m Ω̃Ω̃ r + Ω̃Ω̃ m η ;  m η̃ Ω̃Ω̃ r + Ω̃ ρ Ω ]
// (centripetal mass times acceleration: the centrifugal force is −F^I, pointing away from the
// axis). Tangents: ∂F^I/∂x = M(:, 1:3) Ω̃Ω̃ (through u¨ only), ∂F^I/∂δθ = K^I of that state (the
// spatial spin, Q → exp(δθ̃) Q). Everything is quadratic in Ω, so a load factor λ multiplies the
// force and both tangents (λ scales Ω²). Header-only, fixed-size, no heap.
#pragma once

#include "core/so3.hpp"
#include "core/types.hpp"
#include "formulations/displacement/calculate_inertial_forces.hpp"

namespace rotbeam::form {

struct RotatingFrameForces {
    Vec6 F = Vec6::Zero();                                                        // λ F^I
    Eigen::Matrix<double, 6, 3> dF_dx = Eigen::Matrix<double, 6, 3>::Zero();      // ∂/∂x
    Eigen::Matrix<double, 6, 3> dF_dtheta = Eigen::Matrix<double, 6, 3>::Zero();  // ∂/∂δθ
};

inline RotatingFrameForces calculate_rotating_frame_forces(const Mat6& M_star, const Mat3& Q,
                                                           const Vec3& r, const Vec3& Omega,
                                                           double lambda) {
    const Mat3 WW = so3::skew(Omega) * so3::skew(Omega);
    InertialState s;
    s.u_ddot = WW * r;
    s.omega = Omega;
    s.Q = Q;
    const InertialBlocks b = calculate_inertial_blocks(M_star, s);
    RotatingFrameForces out;
    out.F = lambda * b.F;
    out.dF_dx = lambda * b.M.leftCols<3>() * WW;
    out.dF_dtheta = lambda * b.K.rightCols<3>();
    return out;
}

}  // namespace rotbeam::form
