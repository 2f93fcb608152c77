// Exact helix of docs/benchmarks.md §5 (derivation in docs/reference-solutions.md §2).
//
// Straight cantilever along +x of length L, clamped at s = 0, isotropic in bending and torsion
// (EI₂ = EI₃ = GJ = EI), tip moment M = κ EI n with |n| = 1, dead or follower. The internal force
// is zero and the internal moment is M everywhere, so the spatial curvature is the constant κ n:
//   R(s) = exp(κ s ñ),   x(s) = a s n + b sin(κs)/κ + (n × b)(1 − cos κs)/κ,
// with a = n·e_x and b = e_x − a n. A follower moment R(L) M gives the same solution because
// R(L) n = n. The strains are exactly zero, so EA and GA do not enter.
#pragma once

#include "core/types.hpp"

namespace rotbeam::oracle {

struct HelixState {
    Vec3 displacement = Vec3::Zero();     // x(s) − s e_x
    Mat3 rotation = Mat3::Identity();     // relative to the reference configuration
    Vec3 rotation_vector = Vec3::Zero();  // κ s n, unwrapped (not reduced to the principal value)
};

// The state at arc length s ∈ [0, L] for curvature κ (κL is the tip rotation angle) about the
// unit axis n (normalized here; must be non-zero).
HelixState helix_state(double kappa, const Vec3& axis, double s);

// Tip moment of curvature κ: M = κ EI n̂.
Vec3 helix_moment(double kappa, double bending_stiffness, const Vec3& axis);

}  // namespace rotbeam::oracle
