// The mixed dynamic residual F(t, X, Ẋ) (seed 002 Eqs. 45–50, 56 with {P; H} = I{V; Ω}) of every
// three-parameter parameterization: at rest it is the static one, the pattern is fixed,
// evaluation allocates nothing and the counters say which terms a scene needs (its Jacobians
// against central differences, for every combination, are the generic harness's:
// tests/harness/test_jacobians.cpp).
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <vector>

#include "formulations/mixed/mixed_dynamics.hpp"
#include "parameterizations/parameter_constraint.hpp"
#include "tests/harness/type_lists.hpp"
#include "tests/mixed/allocation_counter.hpp"
#include "tests/mixed/deformed_state.hpp"
#include "tests/mixed/dynamic_models.hpp"

using namespace rotbeam;
using Parameterizations = test::MixedParameterizationTypes<>;

namespace {

// The deformed, moving state of tests/mixed/deformed_state.hpp (rotations of 2.1–2.6 rad; 4.0–5.0
// rad for the continuous WM map, past π where its chain rule is active).
template <class P>
void moving_state(const form::MixedDynamics<P>& dyn, VecX& x, VecX& xdot) {
    const double base = P::kName == param::WienerMilenkovicContinuous::kName ? 4.5 : 2.1;
    x = test::deformed_mixed_state<P>(dyn.numbering(), base);
    xdot = test::mixed_rates(dyn.size());
}

// The moving two-member structure; with a redundant parameter (the quaternion) also with a second,
// prescribed and moving support whose given rotation carries the scale ρ.
template <class P>
std::vector<Model> structures() {
    std::vector<Model> out = {test::dynamic_test_model()};
    if constexpr (param::ParameterConstraint<P>::kRows > 0) {
        out.push_back(test::two_support_dynamic_model());
    }
    return out;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(mixed_dynamics)

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
        BOOST_TEST(r.segment<6>(nb.element_row(e) + nb.fP()).cwiseAbs().maxCoeff() == 0.0);
    }
}

BOOST_AUTO_TEST_CASE_TEMPLATE(evaluation_allocates_nothing_after_first_call, P, Parameterizations) {
    for (const Model& m : structures<P>()) {
        form::MixedDynamics<P> dyn(m, 1.0);
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
        // 15 + K unknowns per element, 3 + K per free node, 6 per supported one and ρ at a further
        // support: 18N + 6M for three parameters (seed 002 after Eq. 56).
        int node_unknowns = 0;
        for (int n = 0; n < nb.node_count(); ++n) {
            node_unknowns += nb.supported(n) ? 6 + (nb.has_scale(n) ? 1 : 0) : 3 + P::kSize;
        }
        BOOST_TEST(dyn.size() == (15 + P::kSize) * nb.element_count + node_unknowns);
        BOOST_TEST(dyn.counters().inertial_terms == 3L * nb.element_count);
    }
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
