// SO(3) helpers shared by every parameterization and formulation.
//
// Conventions (docs/architecture.md): a rotation matrix R maps material components to inertial
// components; a unit quaternion is stored scalar first, q = (w, x, y, z) = (cos φ/2, sin φ/2 n);
// a rotation vector is ψ = φ n. skew(a) b = a × b, axial(skew(a)) = a.
//
// Small-angle branches use Taylor series below named thresholds so that R, exp and log are
// accurate to ~1e-15 relative at 1e-9 rad; log is computed through the quaternion (Shepperd's
// extraction) and atan2, which stays accurate at angles near π.
#pragma once

#include "core/types.hpp"

namespace rotbeam::so3 {

// Below this angle exp/log use their Taylor series (the truncation error is then < 1e-17).
inline constexpr double kSeriesAngle = 1e-4;

Mat3 skew(const Vec3& a);
// Axial vector of the skew-symmetric part of M: axial(M) = vee((M - Mᵀ)/2).
Vec3 axial(const Mat3& M);

// Rotation vector → rotation matrix (Rodrigues' formula), any angle.
Mat3 exp_map(const Vec3& psi);
// Rotation matrix → principal rotation vector, angle in [0, π]. At exactly π the sign of the
// axis is the one Shepperd's extraction yields.
Vec3 log_map(const Mat3& R);

// Unit quaternions, scalar first.
Vec4 quat_identity();
Vec4 quat_multiply(const Vec4& a, const Vec4& b);  // R(a ⊗ b) = R(a) R(b)
Vec4 quat_conjugate(const Vec4& q);
Mat3 quat_to_matrix(const Vec4& q);  // assumes |q| = 1
Vec4 quat_from_matrix(const Mat3& R);  // Shepperd; returns w ≥ 0
Vec4 quat_from_rotvec(const Vec3& psi);  // any angle: the hemisphere follows φ (w < 0 past π)
Vec3 rotvec_from_quat(const Vec4& q);  // principal value, angle in [0, π]
Vec3 quat_rotate(const Vec4& q, const Vec3& v);  // R(q) v

// Rotation angle of a matrix in [0, π] (robust: atan2 of sin and cos parts).
double rotation_angle(const Mat3& R);

// Unwrapped rotation angle: the angle equivalent to `principal` (a principal rotation vector)
// that is continuous with `previous_psi` (the last unwrapped rotation vector). Returns the
// unwrapped rotation vector; its norm is the unwrapped angle. Used to report a full roll-up
// as 2π, not 0.
Vec3 unwrap_rotation_vector(const Vec3& principal, const Vec3& previous_psi);

}  // namespace rotbeam::so3
