#include "make_problem.hpp"

#include "combinations/dispatch.hpp"
#include "core/errors.hpp"

namespace rotbeam {

std::unique_ptr<StaticProblem> make_static_problem(const Model& model) {
    const Discretization& d = model.discretization;
    return comb::dispatch_formulation(
        d.formulation, [&]<Formulation F>() -> std::unique_ptr<StaticProblem> {
            return comb::dispatch_parameterization_of<F>(
                d, [&]<class P>() -> std::unique_ptr<StaticProblem> {
                    return std::make_unique<typename comb::StaticsOf<F, P>::type>(model);
                });
        });
}

}  // namespace rotbeam
