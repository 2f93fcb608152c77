#include "make_problem.hpp"

#include <type_traits>

#include "core/errors.hpp"
#include "formulations/displacement/displacement_statics.hpp"
#include "formulations/mixed/mixed_quaternion_statics.hpp"
#include "formulations/mixed/mixed_statics.hpp"
#include "formulations/mixed/wm_continuous.hpp"
#include "parameterizations/registry.hpp"

namespace rotbeam {

namespace {

// The parameterizations formulations/mixed/mixed_statics.cpp instantiates; the quaternion has its
// own four-component statics (mixed_quaternion_statics.cpp).
template <class P>
constexpr bool kMixedAvailable =
    std::is_same_v<P, param::WienerMilenkovic> || std::is_same_v<P, param::Rodrigues> ||
    std::is_same_v<P, param::RotationVector>;

}  // namespace

std::unique_ptr<StaticProblem> make_static_problem(const Model& model) {
    const Discretization& d = model.discretization;
    return param::dispatch_parameterization(
        d.rotation, [&]<class P>() -> std::unique_ptr<StaticProblem> {
            if (d.formulation == "displacement") {
                return std::make_unique<form::DisplacementStatics<P>>(model);
            }
            if (d.formulation == "mixed") {
                if (model.solver.mip) {
                    throw InputError("solver.mip: the mixed formulation's section resultants "
                                     "are unknowns already; mip is for the displacement "
                                     "formulation");
                }
                if constexpr (std::is_same_v<P, param::WienerMilenkovic>) {
                    if (d.wm_map == "continuous") {
                        return std::make_unique<
                            form::MixedStatics<param::WienerMilenkovicContinuous>>(model);
                    }
                }
                if constexpr (std::is_same_v<P, param::Quaternion>) {
                    return std::make_unique<form::MixedQuaternionStatics<P>>(model);
                } else if constexpr (kMixedAvailable<P>) {
                    return std::make_unique<form::MixedStatics<P>>(model);
                } else {
                    throw InputError(
                        "discretization.rotation: the mixed formulation is not "
                        "available with '" +
                        d.rotation +
                        "' (quaternion | wiener-milenkovic | rodrigues | rotation-vector)");
                }
            }
            throw InputError("discretization.formulation: unknown formulation '" + d.formulation +
                             "' (displacement | mixed)");
        });
}

}  // namespace rotbeam
