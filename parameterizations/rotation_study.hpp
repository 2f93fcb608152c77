// The rotation study behind `rotbeam study rotations`: how far each
// parameterization rotates before it fails, and how it fails.
#pragma once

#include <nlohmann/json.hpp>

namespace rotbeam::param {

// Sweeps the angle φ from 0 to 4π in `samples` equal steps (both ends included, samples ≥ 2)
// about the fixed generic axis (1, −2, 3)/√14, for every parameterization. Result:
//   { "axis": [3], "angles": [samples],
//     "parameterizations": [ { "name", "singular_angle" (null if none), "samples": [
//        { "angle", "defined" (from_rotation_vector accepted φ n), "parameter_norm",
//          "matrix_error" ‖R(p) − exp(ψ̃)‖, "round_trip_error" ‖ψ → p → ψ‖ (modulo 2π),
//          "tangent_defined", "sigma_min" σ_min(H_m), "tangent_inverse_norm" ‖H_m⁻¹‖₂ (the
//          right inverse for the quaternion), "condition" σ_max/σ_min,
//          "fd_error" max_j ‖H_m e_j − FD(Rᵀ ∂R/∂p_j)‖/‖H_m‖,
//          "refused_by" + "message" where something was refused } ] } ] }
// Values that do not exist at an angle are null. σ_min and ‖H⁻¹‖ show the WM singularity
// that the condition number hides (WM's Q has three equal singular values).
nlohmann::json rotation_study(int samples);

}  // namespace rotbeam::param
