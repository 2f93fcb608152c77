// The mixed statics' residual and analytic sparse Jacobian (seed 002 Eqs. 31–48): exactness of the
// reference configuration, consistency with central finite differences at a strongly deformed
// state, a fixed sparsity pattern and no heap allocation after the first evaluation.
#include <boost/test/unit_test.hpp>
#include <cmath>

#include "core/finite_difference.hpp"
#include "formulations/mixed/mixed_statics.hpp"
#include "parameterizations/euler_angles.hpp"
#include "parameterizations/rodrigues.hpp"
#include "parameterizations/rotation_vector.hpp"
#include "parameterizations/wiener_milenkovic.hpp"
#include "parameterizations/wiener_milenkovic_continuous.hpp"
#include "tests/mixed/allocation_counter.hpp"
#include "tests/mixed/deformed_model.hpp"
#include "tests/mixed/models.hpp"

using namespace rotbeam;
using Parameterizations = std::tuple<param::WienerMilenkovic, param::Rodrigues,
                                     param::RotationVector, param::EulerAngles>;

namespace {

// A deterministic state with rotations of 2.1–2.6 rad about axes that vary along the structure
// and unit-order displacements and section resultants.
template <class P>
VecX deformed_state(const form::MixedStatics<P>& problem, double base_angle = 2.1) {
    VecX x(problem.size());
    for (Eigen::Index i = 0; i < x.size(); ++i) x[i] = 0.5 * std::sin(0.37 * i + 0.2);
    const form::MixedNumbering& layout = problem.numbering();
    auto set_rotation = [&](int offset, int k) {
        const Vec3 axis = Vec3(std::cos(0.9 * k), std::sin(0.9 * k), 0.5).normalized();
        x.segment<3>(offset) =
            P::from_rotation_vector((base_angle + 0.5 * std::sin(1.3 * k)) * axis);
    };
    for (int n = 0; n < layout.node_count(); ++n) {
        if (!layout.supported(n)) set_rotation(layout.node_column(n) + 3, n);
    }
    for (int e = 0; e < layout.element_count; ++e) set_rotation(layout.element_column(e) + 3, e);
    return x;
}

}  // namespace

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

BOOST_AUTO_TEST_CASE_TEMPLATE(jacobian_matches_central_differences_at_deformed_state, P,
                              Parameterizations) {
    form::MixedStatics<P> problem(test::deformed_test_model());
    problem.set_load_factor(1.3);
    const VecX x0 = deformed_state(problem);
    BOOST_TEST(problem.max_rotation_angle() >= 0.0);
    problem.set_state_vector(x0);
    BOOST_TEST(problem.max_rotation_angle() > 2.0);
    VecX r;
    SparseMatrix J;
    problem.evaluate(r, &J);
    const MatX J_fd = central_difference_jacobian(
        [&problem](const VecX& x) {
            problem.set_state_vector(x);
            VecX rx;
            problem.evaluate(rx, nullptr);
            return rx;
        },
        x0);
    const MatX J_an = MatX(J);
    // Everything is of unit order; the central-difference step h ≈ ∛ε·max(1, |x|) ≲ 4e-5 (the
    // largest parameter, Rodrigues at 2.6 rad, is ≈ 7) leaves a truncation error h²|f'''|/6 ≲ 1e-8
    // for third derivatives ≲ 30 and a round-off ε|f|/h ≲ 1e-10. 1e-6 keeps a margin of 100 while
    // any wrong term (a sign, a missing S block) is O(0.1–1).
    const double error = (J_an - J_fd).cwiseAbs().maxCoeff();
    BOOST_TEST_MESSAGE(P::kName << ": max |J − J_fd| = " << error);
    BOOST_TEST(error < 1e-6);
    BOOST_TEST(J_an.cwiseAbs().maxCoeff() > 1.0);  // the comparison is not vacuous
}

// GXBeam's continuous WM map (wiener_milenkovic_continuous.hpp) past π, where the chain rule
// through c = (1 − 8m/|θ|)θ is active: rotations 4.0–5.0 rad (|θ| in 4.9–7.2) and 6.5–7.5 rad (past
// 2π, |θ| in 8.4–11). The FD step ≈ 6e-6·|θ| ≲ 7e-5 leaves a truncation error ≲ 1e-8 for third
// derivatives ≲ 10 (the map adds 1/|θ| factors ≤ 0.25); tolerance 1e-6 as above.
BOOST_AUTO_TEST_CASE(continuous_wm_jacobian_matches_central_differences_past_pi_and_2pi) {
    using P = param::WienerMilenkovicContinuous;
    for (const double base : {4.5, 7.0}) {
        form::MixedStatics<P> problem(test::deformed_test_model());
        problem.set_load_factor(1.3);
        const VecX x0 = deformed_state(problem, base);
        problem.set_state_vector(x0);
        BOOST_TEST(problem.max_rotation_angle() > base);
        VecX r;
        SparseMatrix J;
        problem.evaluate(r, &J);
        const MatX J_fd = central_difference_jacobian(
            [&problem](const VecX& x) {
                problem.set_state_vector(x);
                VecX rx;
                problem.evaluate(rx, nullptr);
                return rx;
            },
            x0);
        const double error = (MatX(J) - J_fd).cwiseAbs().maxCoeff();
        BOOST_TEST_MESSAGE("continuous WM, base angle " << base << ": max |J − J_fd| = " << error);
        BOOST_TEST(error < 1e-6);
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
    form::MixedStatics<P> problem(test::deformed_test_model());
    problem.set_load_factor(0.8);
    problem.set_state_vector(deformed_state(problem));
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
