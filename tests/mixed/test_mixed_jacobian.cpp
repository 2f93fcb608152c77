// The mixed statics' residual and analytic sparse Jacobian (seed 002 Eqs. 31–48): exactness of the
// reference configuration, GXBeam's continuous WM map past 2π, a fixed sparsity pattern and no heap
// allocation after the first evaluation (the Jacobian against central differences, for every
// combination, is the generic harness's: tests/harness/test_jacobians.cpp).
#include <boost/test/unit_test.hpp>
#include <cmath>

#include "formulations/mixed/mixed_statics.hpp"
#include "parameterizations/euler_angles.hpp"
#include "parameterizations/rodrigues.hpp"
#include "parameterizations/rotation_vector.hpp"
#include "parameterizations/wiener_milenkovic.hpp"
#include "parameterizations/wiener_milenkovic_continuous.hpp"
#include "tests/mixed/allocation_counter.hpp"
#include "tests/mixed/deformed_model.hpp"
#include "tests/mixed/deformed_state.hpp"
#include "tests/mixed/models.hpp"

using namespace rotbeam;
using Parameterizations = std::tuple<param::WienerMilenkovic, param::Rodrigues,
                                     param::RotationVector, param::EulerAngles>;

BOOST_AUTO_TEST_SUITE(mixed_statics)

BOOST_AUTO_TEST_CASE_TEMPLATE(reference_configuration_solves_the_unloaded_curved_structure, P,
                              Parameterizations) {
    form::MixedStatics<P> problem(test::deformed_test_model());
    problem.set_load_factor(0.0);
    VecX r;
    problem.evaluate(r, nullptr);
    BOOST_TEST(r.size() == problem.size());
    // Only round-off of the frames and chords (unit-order geometry) remains.
    BOOST_TEST(r.cwiseAbs().maxCoeff() < 1e-14);
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
    form::MixedStatics<P> problem(test::deformed_test_model());
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
    // Unknowns per element 12, per node 6 (seed 002 §III; mixed_layout.hpp).
    BOOST_TEST(problem.size() ==
               12 * layout.element_count() + 6 * static_cast<int>(layout.nodes.size()));
    BOOST_TEST(problem.counters().inertial_terms == 0);
}

BOOST_AUTO_TEST_SUITE_END()
