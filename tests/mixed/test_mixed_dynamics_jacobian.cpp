// The mixed dynamic residual F(t, X, Ẋ) (seed 002 Eqs. 45–50, 56 with {P; H} = I{V; Ω}) and its
// Jacobians ∂F/∂X, ∂F/∂Ẋ against central differences at a deformed, moving state, for every
// three-parameter parameterization; the pattern is fixed and evaluation allocates nothing.
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <tuple>

#include "core/finite_difference.hpp"
#include "formulations/mixed/mixed_dynamics.hpp"
#include "parameterizations/euler_angles.hpp"
#include "parameterizations/rodrigues.hpp"
#include "parameterizations/rotation_vector.hpp"
#include "parameterizations/wiener_milenkovic.hpp"
#include "parameterizations/wiener_milenkovic_continuous.hpp"
#include "tests/mixed/allocation_counter.hpp"
#include "tests/mixed/dynamic_models.hpp"

using namespace rotbeam;
using Parameterizations =
    std::tuple<param::WienerMilenkovic, param::Rodrigues, param::RotationVector,
               param::WienerMilenkovicContinuous, param::EulerAngles>;

namespace {

// Rotations of 2.1–2.6 rad about axes varying along the structure (4.0–5.0 rad for the continuous
// WM map, past π where its chain rule is active), unit-order everything else, and unit-order
// rates of every unknown (the algebraic ones too: F must not depend on them).
template <class P>
void moving_state(const form::MixedDynamics<P>& dyn, VecX& x, VecX& xdot) {
    const double base = P::kName == param::WienerMilenkovicContinuous::kName ? 4.5 : 2.1;
    const int n = dyn.size();
    x.resize(n);
    xdot.resize(n);
    for (int i = 0; i < n; ++i) {
        x[i] = 0.5 * std::sin(0.37 * i + 0.2);
        xdot[i] = 0.7 * std::cos(0.53 * i + 0.1);
    }
    const form::MixedNumbering& nb = dyn.numbering();
    auto set_rotation = [&](int offset, int k) {
        const Vec3 axis = Vec3(std::cos(0.9 * k), std::sin(0.9 * k), 0.5).normalized();
        x.segment<3>(offset) = P::from_rotation_vector((base + 0.5 * std::sin(1.3 * k)) * axis);
    };
    for (int node = 0; node < nb.node_count(); ++node) {
        if (!dyn.layout().supported(node)) set_rotation(nb.node_column(node) + 3, node);
    }
    for (int e = 0; e < nb.element_count; ++e) set_rotation(nb.element_column(e) + nb.c(), e + 7);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(mixed_dynamics)

BOOST_AUTO_TEST_CASE_TEMPLATE(jacobians_match_central_differences_at_moving_deformed_state, P,
                              Parameterizations) {
    form::MixedDynamics<P> dyn(test::dynamic_test_model(), 1.0);
    VecX x0, xd0;
    moving_state(dyn, x0, xd0);
    const double t = 0.37;
    VecX r;
    SparseMatrix Jx, Jxd;
    dyn.evaluate(t, x0, xd0, r, &Jx, &Jxd);
    const MatX Jx_fd = central_difference_jacobian(
        [&](const VecX& x) {
            VecX rx;
            dyn.evaluate(t, x, xd0, rx, nullptr, nullptr);
            return rx;
        },
        x0);
    const MatX Jxd_fd = central_difference_jacobian(
        [&](const VecX& xd) {
            VecX rx;
            dyn.evaluate(t, x0, xd, rx, nullptr, nullptr);
            return rx;
        },
        xd0);
    // As the statics' test (test_mixed_jacobian.cpp): unit-order quantities, step ∛ε·max(1,|x|)
    // ≲ 6e-5, truncation h²|f'''|/6 ≲ 1e-8, round-off ≲ 1e-10: 1e-6 keeps a margin of 100 while
    // a wrong term (a sign, a missing transpose of C^ab, I⁻¹'s off-diagonal block) is O(0.1–1).
    const double ex = (MatX(Jx) - Jx_fd).cwiseAbs().maxCoeff();
    const double exd = (MatX(Jxd) - Jxd_fd).cwiseAbs().maxCoeff();
    BOOST_TEST_MESSAGE(P::kName << ": max |∂F/∂X − FD| = " << ex << ", max |∂F/∂Ẋ − FD| = " << exd
                                << ", largest rotation " << dyn.max_rotation_angle(x0));
    BOOST_TEST(ex < 1e-6);
    BOOST_TEST(exd < 1e-6);
    // Not vacuous: both Jacobians are of unit order, and F depends on the rates.
    BOOST_TEST(MatX(Jx).cwiseAbs().maxCoeff() > 1.0);
    BOOST_TEST(MatX(Jxd).cwiseAbs().maxCoeff() > 0.5);
    BOOST_TEST(dyn.max_rotation_angle(x0) > 2.0);
    // Algebraic unknowns (F, M, node unknowns) have no rate in F.
    const MatX Jd = MatX(Jxd);
    for (int j = 0; j < dyn.size(); ++j) {
        if (dyn.differential()[j] == 0.0) BOOST_TEST(Jd.col(j).cwiseAbs().maxCoeff() == 0.0);
    }
}

// At rest (Ẋ = 0, P = H = 0) the dynamic residual is the static one: the momentum terms vanish
// and f_P = f_H = 0, so a static equilibrium is a dynamic one.
BOOST_AUTO_TEST_CASE_TEMPLATE(at_rest_the_momentum_rows_vanish, P, Parameterizations) {
    form::MixedDynamics<P> dyn(test::dynamic_test_model(), 1.0);
    VecX x, xd;
    moving_state(dyn, x, xd);
    const form::MixedNumbering& nb = dyn.numbering();
    for (int e = 0; e < nb.element_count; ++e)
        x.segment<6>(nb.element_column(e) + nb.P()).setZero();
    VecX r;
    dyn.evaluate(0.2, x, VecX::Zero(dyn.size()), r, nullptr, nullptr);
    for (int e = 0; e < nb.element_count; ++e) {
        BOOST_TEST(r.segment<6>(nb.element_column(e) + nb.P()).cwiseAbs().maxCoeff() == 0.0);
    }
}

BOOST_AUTO_TEST_CASE_TEMPLATE(evaluation_allocates_nothing_after_first_call, P, Parameterizations) {
    form::MixedDynamics<P> dyn(test::dynamic_test_model(), 1.0);
    VecX x, xd, r;
    moving_state(dyn, x, xd);
    SparseMatrix Jx, Jxd;
    dyn.evaluate(0.1, x, xd, r, &Jx, &Jxd);
    const int* const outer = Jx.outerIndexPtr();
    const long before = test::allocation_count();
    dyn.evaluate(0.2, x, xd, r, &Jx, &Jxd);
    dyn.evaluate(0.3, x, xd, r, nullptr, nullptr);
    test::check_no_allocation_since(before);
    BOOST_TEST(Jx.outerIndexPtr() == outer);
    const form::MixedNumbering& nb = dyn.numbering();
    // 18 unknowns per element, 6 per node (seed 002 after Eq. 56: 18N + 6M).
    BOOST_TEST(dyn.size() == 18 * nb.element_count + 6 * nb.node_count());
    BOOST_TEST(dyn.counters().inertial_terms == 3L * nb.element_count);
}

// The counters say which terms a scene needs: a follower point load's stiffness
// block is counted at every Jacobian, a dead one's never (they used to count 0 for both).
BOOST_AUTO_TEST_CASE_TEMPLATE(follower_point_load_stiffness_is_counted, P, Parameterizations) {
    Model m = test::dynamic_test_model();
    m.distributed_loads.erase(m.distributed_loads.begin());  // the follower distributed load
    form::MixedDynamics<P> follower(m, 1.0);
    m.point_loads.at(0).frame = LoadFrame::dead;
    form::MixedDynamics<P> dead(m, 1.0);
    for (form::MixedDynamics<P>* dyn : {&follower, &dead}) {
        VecX x, xd, r;
        moving_state(*dyn, x, xd);
        SparseMatrix Jx, Jxd;
        dyn->evaluate(0.1, x, xd, r, &Jx, &Jxd);
        dyn->evaluate(0.2, x, xd, r, &Jx, &Jxd);
        dyn->evaluate(0.3, x, xd, r, nullptr, nullptr);
    }
    BOOST_TEST(follower.counters().follower_stiffness == 2);
    BOOST_TEST(dead.counters().follower_stiffness == 0);
}

BOOST_AUTO_TEST_SUITE_END()
