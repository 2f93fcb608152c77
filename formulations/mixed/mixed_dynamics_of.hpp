// MixedDynamicsOf<P>: the mixed dynamics class for a parameterization — MixedDynamics<P> for three
// parameters, MixedQuaternionDynamics<P> for four (mixed_quaternion_dynamics.hpp). For generic
// tests and the runner's switch, as mixed_statics_of.hpp for statics.
#pragma once

#include "formulations/mixed/mixed_dynamics.hpp"
#include "formulations/mixed/mixed_quaternion_dynamics.hpp"

namespace rotbeam::form {

template <param::RotationParameterization P>
struct MixedDynamicsSelect {
    using type = MixedDynamics<P>;
};

template <param::RotationParameterization P>
requires(P::kSize == 4) struct MixedDynamicsSelect<P> {
    using type = MixedQuaternionDynamics<P>;
};

template <param::RotationParameterization P>
using MixedDynamicsOf = typename MixedDynamicsSelect<P>::type;

}  // namespace rotbeam::form
