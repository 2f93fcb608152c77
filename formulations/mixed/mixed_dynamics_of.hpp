// MixedDynamicsOf<P>: the name the runner and the generic tests use for the mixed dynamics of a
// parameterization; one class serves every parameterization (mixed_dynamics.hpp).
#pragma once

#include "formulations/mixed/mixed_dynamics.hpp"

namespace rotbeam::form {

template <param::RotationParameterization P>
using MixedDynamicsOf = MixedDynamics<P>;

}  // namespace rotbeam::form
