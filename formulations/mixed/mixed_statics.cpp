// Explicit instantiations of the mixed statics for every three-parameter parameterization: Wiener–
// Milenković and Rodrigues (seed 002, Q⁻¹ of Eq. 25), the rotation vector (with the material
// tangent inverse dexp⁻¹ of rotation_vector.hpp Eq. V4 in place of Q⁻¹ in Eq. 48) and the Euler
// angles (H_m⁻¹ of euler_angles.hpp Eq. E5 in its place).
#include "formulations/mixed/mixed_statics_impl.hpp"
#include "formulations/mixed/mixed_statics_rest_terms.hpp"
#include "formulations/mixed/wm_continuous.hpp"
#include "parameterizations/euler_angles.hpp"
#include "parameterizations/rodrigues.hpp"
#include "parameterizations/rotation_vector.hpp"
#include "parameterizations/wiener_milenkovic.hpp"

namespace rotbeam::form {

template class MixedStatics<param::WienerMilenkovic>;
template class MixedStatics<param::Rodrigues>;
template class MixedStatics<param::RotationVector>;
template class MixedStatics<param::EulerAngles>;
template class MixedStatics<param::WienerMilenkovicContinuous>;  // GXBeam's continuous rescale

}  // namespace rotbeam::form
