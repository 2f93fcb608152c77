// Sectional strain of the displacement formulation (seed 000, "equivalent definition of strain").
//
//   ε = x^r′ + u′ − R x^r′                    (seed 000, the equation after Eq. 8)
//   κ = axial(R′ Rᵀ)                          (seed 000 Eq. 7, erratum: docs/benchmarks.md, Errata)
//
// R is the rotation relative to the reference configuration (R^c = R R^r), so both measures are
// exactly zero in the reference configuration (u = 0, R = I) at every point, whatever the
// reference line. Both are spatial (inertial components). κ comes from the rotation
// interpolation (interpolate_rotation.hpp); this kernel only stacks the pair.
#pragma once

#include "core/types.hpp"

namespace rotbeam::form {

// Returns [ε; κ].
Vec6 calculate_strain(const Vec3& x0_prime, const Vec3& u_prime, const Mat3& R, const Vec3& kappa);

}  // namespace rotbeam::form
