// Explicit instantiations of the mixed statics for every registered parameterization (seed 002's
// Eq. 48 with Q⁻¹ of Eq. 25 for Wiener–Milenković and Rodrigues, with dexp⁻¹ of
// rotation_vector.hpp Eq. V4 for the rotation vector, with H_m⁻¹ of euler_angles.hpp Eq. E5 for
// the Euler angles, with the right inverse H_m⁺ in four components for the quaternion) and for
// Wiener–Milenković with GXBeam's continuous map.
#include "formulations/mixed/mixed_statics_impl.hpp"
#include "formulations/mixed/mixed_statics_kinetic.hpp"
#include "formulations/mixed/mixed_statics_rest_terms.hpp"
#include "parameterizations/registry.hpp"
#include "parameterizations/wiener_milenkovic_continuous.hpp"

namespace rotbeam::form {

#define ROTBEAM_MIXED_STATICS_INSTANTIATE(P) template class MixedStatics<param::P>;
ROTBEAM_FOR_EACH_PARAMETERIZATION(ROTBEAM_MIXED_STATICS_INSTANTIATE)
#undef ROTBEAM_MIXED_STATICS_INSTANTIATE
template class MixedStatics<param::WienerMilenkovicContinuous>;  // GXBeam's continuous rescale

}  // namespace rotbeam::form
