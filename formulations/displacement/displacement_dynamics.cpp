// Explicit instantiation of the displacement dynamics for every parameterization.
#include "formulations/displacement/displacement_dynamics.hpp"

#include "formulations/displacement/displacement_dynamics_assembly.hpp"
#include "formulations/displacement/displacement_dynamics_setup.hpp"
#include "parameterizations/registry.hpp"

namespace rotbeam::form {

#define ROTBEAM_DISPLACEMENT_DYNAMICS_INSTANTIATE(P) template class DisplacementDynamics<param::P>;
ROTBEAM_FOR_EACH_PARAMETERIZATION(ROTBEAM_DISPLACEMENT_DYNAMICS_INSTANTIATE)
#undef ROTBEAM_DISPLACEMENT_DYNAMICS_INSTANTIATE

}  // namespace rotbeam::form
