// Explicit instantiation of the displacement statics for every parameterization (STYLE.md: every
// combination compiles, compile time stays bounded).
#include "formulations/displacement/displacement_statics.hpp"

#include "formulations/displacement/displacement_statics_assembly.hpp"
#include "formulations/displacement/displacement_statics_setup.hpp"
#include "parameterizations/quaternion.hpp"

namespace rotbeam::form {

template class DisplacementStatics<param::Quaternion>;

}  // namespace rotbeam::form
