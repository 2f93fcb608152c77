// The linearization of the displacement statics about a solved static state, as the modal
// analysis takes it (formulations/displacement/displacement_modal.hpp): the tangent K at the
// equilibrium reached through the given load factors, and the modal mass M at its rotations.
#pragma once

#include <boost/test/unit_test.hpp>
#include <vector>

#include "core/static_driver.hpp"
#include "formulations/displacement/displacement_modal.hpp"
#include "formulations/displacement/displacement_statics.hpp"

namespace rotbeam::test {

template <class P>
SparseMatrix tangent_and_mass_at_equilibrium(const Model& model,
                                             form::DisplacementStatics<P>& problem,
                                             const std::vector<double>& load_factors,
                                             SparseMatrix& M) {
    const StaticOutcome eq =
        run_static(problem, load_factors, NewtonSettings{}, [](const StepRecord&) {});
    // A solved static state: the tolerances met, or stalled at round-off with its error bound.
    BOOST_TEST_REQUIRE(has_solution(eq.status));
    VecX r;
    SparseMatrix K;
    problem.evaluate(r, &K);
    M = form::assemble_mass_matrix(model, form::build_mass_mesh(model), [&](int node) {
        return P::matrix(problem.node_rotation(node));
    });
    return K;
}

}  // namespace rotbeam::test
