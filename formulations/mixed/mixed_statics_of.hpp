// MixedStaticsOf<P>: the name the runner and the generic tests use for the mixed statics of a
// parameterization; one class serves every parameterization (mixed_statics.hpp).
#pragma once

#include "formulations/mixed/mixed_statics.hpp"

namespace rotbeam::form {

template <param::RotationParameterization P>
using MixedStaticsOf = MixedStatics<P>;

}  // namespace rotbeam::form
