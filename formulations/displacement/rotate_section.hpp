// Section matrix in inertial coordinates (seed 000, after Eq. 8):
//   C = 𝓡 C* 𝓡ᵀ,  𝓡 = diag(R R^r, R R^r)
// with C* the 6×6 material-axis matrix (fully populated allowed). Works for stiffness and mass.
#pragma once

#include "core/types.hpp"

namespace rotbeam::form {

// Q = R R^r (material → inertial).
Mat6 rotate_section(const Mat6& C_star, const Mat3& Q);

}  // namespace rotbeam::form
