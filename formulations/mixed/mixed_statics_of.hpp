// MixedStaticsOf<P>: the mixed statics class for a parameterization — MixedStatics<P> for three
// parameters (seed 002's Eq. 48 with H_m⁻¹), MixedQuaternionStatics<P> for four (Eq. 48 with the
// right inverse H_m⁺, mixed_quaternion_statics.hpp). For generic tests and the runner's switch.
#pragma once

#include "formulations/mixed/mixed_quaternion_statics.hpp"
#include "formulations/mixed/mixed_statics.hpp"

namespace rotbeam::form {

template <param::RotationParameterization P>
struct MixedStaticsSelect {
    using type = MixedStatics<P>;
};

template <param::RotationParameterization P>
requires(P::kSize == 4) struct MixedStaticsSelect<P> {
    using type = MixedQuaternionStatics<P>;
};

template <param::RotationParameterization P>
using MixedStaticsOf = typename MixedStaticsSelect<P>::type;

}  // namespace rotbeam::form
