// The one place where the runtime choice of parameterization and formulation is made
// (docs/architecture.md, Layers): below this switch nothing dispatches on the parameterization.
#pragma once

#include <memory>

#include "core/model.hpp"
#include "core/static_state.hpp"

namespace rotbeam {

// A static problem for model.discretization.{formulation, rotation} (combinations/dispatch.hpp).
// The options are typed per formulation (core/model.hpp): the loader has refused any the
// formulation does not take.
std::unique_ptr<StaticProblem> make_static_problem(const Model& model);

}  // namespace rotbeam
