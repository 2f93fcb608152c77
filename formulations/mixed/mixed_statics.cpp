// Explicit instantiations of the mixed statics for every three-parameter parameterization (the
// quaternion and the rotation vector need their own kinematics: issue 8).
#include "formulations/mixed/mixed_statics_impl.hpp"
#include "parameterizations/rodrigues.hpp"
#include "parameterizations/wiener_milenkovic.hpp"

namespace rotbeam::form {

template class MixedStatics<param::WienerMilenkovic>;
template class MixedStatics<param::Rodrigues>;

}  // namespace rotbeam::form
