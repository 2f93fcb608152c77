// The mixed statics' residual and analytic sparse Jacobian (seed 002 Eqs. 31–48): exactness of the
// reference configuration, GXBeam's continuous WM map past 2π, a fixed sparsity pattern and no heap
// allocation after the first evaluation (the Jacobian against central differences, for every
// combination, is the generic harness's: tests/harness/test_jacobians.cpp).
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <vector>

#include "formulations/mixed/mixed_statics.hpp"
#include "parameterizations/parameter_constraint.hpp"
#include "tests/harness/type_lists.hpp"
#include "tests/mixed/allocation_counter.hpp"
#include "tests/mixed/deformed_model.hpp"
#include "tests/mixed/deformed_state.hpp"
#include "tests/mixed/models.hpp"

using namespace rotbeam;
using Parameterizations = test::MixedParameterizationTypes<>;

namespace {
// The curved two-member structure; with a redundant parameter (the quaternion) also with a second
// support, whose given rotation carries the scale ρ (mixed_layout.hpp).
template <class P>
std::vector<Model> structures() {
    std::vector<Model> out = {test::deformed_test_model()};
    if constexpr (param::ParameterConstraint<P>::kRows > 0)
        out.push_back(test::two_support_model());
    return out;
}
}  // namespace

BOOST_AUTO_TEST_SUITE(mixed_statics)

BOOST_AUTO_TEST_CASE_TEMPLATE(reference_configuration_solves_the_unloaded_curved_structure, P,
                              Parameterizations) {
    for (const Model& m : structures<P>()) {
        form::MixedStatics<P> problem(m);
        problem.set_load_factor(0.0);
        VecX r;
        problem.evaluate(r, nullptr);
        BOOST_TEST(r.size() == problem.size());
        // Only round-off of the frames and chords (unit-order geometry) remains.
        BOOST_TEST(r.cwiseAbs().maxCoeff() < 1e-14);
    }
}

// The map's rotation is the rotation vector's at every angle up to 4π, and the angle round-trips.
BOOST_AUTO_TEST_CASE(continuous_wm_map_reproduces_rotations_beyond_two_pi) {
    using P = param::WienerMilenkovicContinuous;
    const Vec3 axis = Vec3(0.3, -0.8, 0.5).normalized();
    for (double phi = 0.25; phi < 4.0 * kPi; phi += 0.5) {
        const Vec3 psi = phi * axis;
        const P::P theta = P::from_rotation_vector(psi);
        BOOST_TEST((P::matrix(theta) - so3::exp_map(psi)).norm() < 1e-13);
        BOOST_TEST(std::abs(P::angle(theta) - phi) < 1e-13);
        BOOST_TEST(
            (P::material_tangent(theta) * P::material_tangent_inverse(theta) - Mat3::Identity())
                .norm() < 1e-12);
    }
}

BOOST_AUTO_TEST_CASE_TEMPLATE(evaluation_keeps_the_pattern_and_allocates_nothing_after_first_call,
                              P, Parameterizations) {
    for (const Model& m : structures<P>()) {
        form::MixedStatics<P> problem(m);
        problem.set_load_factor(0.8);
        problem.set_state_vector(test::deformed_mixed_state<P>(problem.numbering()));
        VecX r;
        SparseMatrix J;
        problem.evaluate(r, &J);
        const long nnz = J.nonZeros();
        const int* const outer = J.outerIndexPtr();
        const long before = test::allocation_count();
        problem.evaluate(r, &J);
        problem.evaluate(r, nullptr);
        test::check_no_allocation_since(before);
        BOOST_TEST(J.nonZeros() == nnz);
        BOOST_TEST(J.outerIndexPtr() == outer);
        const form::MixedLayout& layout = problem.layout();
        // Unknowns per element 9 + K, per free node 3 + K, per supported node 6 (its reactions) and
        // ρ at a further support: 12 and 6 for three parameters (seed 002 §III; mixed_layout.hpp).
        const form::MixedNumbering& nb = problem.numbering();
        int node_unknowns = 0;
        for (int n = 0; n < nb.node_count(); ++n) {
            node_unknowns += nb.supported(n) ? 6 + (nb.has_scale(n) ? 1 : 0) : 3 + P::kSize;
        }
        BOOST_TEST(problem.size() == (9 + P::kSize) * layout.element_count() + node_unknowns);
        BOOST_TEST(problem.counters().inertial_terms == 0);  // statics: no momenta, no inertia
    }
}

BOOST_AUTO_TEST_SUITE_END()
