// Explicit instantiation of the displacement statics for every parameterization (so every
// combination compiles, compile time stays bounded).
#include "formulations/displacement/displacement_statics.hpp"

#include "formulations/displacement/displacement_statics_absent_terms.hpp"
#include "formulations/displacement/displacement_statics_assembly.hpp"
#include "formulations/displacement/displacement_statics_energy.hpp"
#include "formulations/displacement/displacement_statics_kinetic.hpp"
#include "formulations/displacement/displacement_statics_setup.hpp"
#include "formulations/displacement/displacement_statics_warm_start.hpp"
#include "parameterizations/registry.hpp"

namespace rotbeam::form {

#define ROTBEAM_DISPLACEMENT_INSTANTIATE(P) template class DisplacementStatics<param::P>;
ROTBEAM_FOR_EACH_PARAMETERIZATION(ROTBEAM_DISPLACEMENT_INSTANTIATE)
#undef ROTBEAM_DISPLACEMENT_INSTANTIATE

}  // namespace rotbeam::form
