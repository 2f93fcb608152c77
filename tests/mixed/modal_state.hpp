// The linearization of the mixed dynamics about a solved static state, as the modal analysis
// takes it (formulations/mixed/mixed_modal.hpp): the statics of `model` solved at load factor 1,
// their state carried into `dyn` (built on form::frozen_loads(model, 1)), and there the residual
// r with A = ∂F/∂X and B = ∂F/∂Ẋ at rest.
#pragma once

#include <boost/test/unit_test.hpp>

#include "core/static_driver.hpp"
#include "formulations/mixed/mixed_dynamics.hpp"
#include "formulations/mixed/mixed_statics.hpp"

namespace rotbeam::test {

// Returns the dynamic state X₀ of the equilibrium.
template <class P>
VecX linearize_about_static_equilibrium(const Model& model, form::MixedDynamics<P>& dyn, VecX& r,
                                        SparseMatrix& A, SparseMatrix& B) {
    form::MixedStatics<P> statics(model);
    statics.set_load_factor(1.0);
    BOOST_TEST_REQUIRE(solve_newton(statics, NewtonSettings{}).converged);
    const VecX x0 = dyn.from_static_state(statics.state_vector());
    dyn.evaluate(0.0, x0, VecX::Zero(dyn.size()), r, &A, &B);
    return x0;
}

}  // namespace rotbeam::test
