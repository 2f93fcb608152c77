#include "make_problem.hpp"

#include <type_traits>

#include "core/errors.hpp"
#include "formulations/displacement/displacement_statics.hpp"
#include "formulations/mixed/mixed_statics.hpp"
#include "parameterizations/registry.hpp"
#include "parameterizations/wiener_milenkovic_continuous.hpp"

namespace rotbeam {

std::unique_ptr<StaticProblem> make_static_problem(const Model& model) {
    const Discretization& d = model.discretization;
    return param::dispatch_parameterization(
        d.rotation, [&]<class P>() -> std::unique_ptr<StaticProblem> {
            if (d.formulation == "displacement") {
                return std::make_unique<form::DisplacementStatics<P>>(model);
            }
            if (d.formulation == "mixed") {
                if (model.solver.mip) {
                    throw InputError(
                        "solver.mip: the mixed formulation's section resultants "
                        "are unknowns already; mip is for the displacement "
                        "formulation");
                }
                if constexpr (std::is_same_v<P, param::WienerMilenkovic>) {
                    if (d.wm_map == "continuous") {
                        return std::make_unique<
                            form::MixedStatics<param::WienerMilenkovicContinuous>>(model);
                    }
                }
                return std::make_unique<form::MixedStatics<P>>(model);
            }
            throw InputError("discretization.formulation: unknown formulation '" + d.formulation +
                             "' (displacement | mixed)");
        });
}

}  // namespace rotbeam
