// The adaptive steps of the mixed formulation's Radau IIA and trapezoidal schemes
// (core/dae_radau.hpp, core/dae_trapezoidal.cpp) do not depend on the rotation parameterization:
// their error weights measure the element rotations in radians (MixedDynamics::build_scales: a
// rotation parameter's state scale is its change per radian at the identity, ½ for the
// quaternion's half-angle components, 1 for the three-parameter charts).
//
// Every parameterization integrates the same semi-discrete motion, so a controller that measures
// the same quantity takes the same steps up to the noise of its discrete decisions. The charts'
// weights still differ at second order in the rotation (a parameter error maps to radians through
// H(p), not H(0): ≤ 2 % at the joined beam's rotations, a third of that in the step); what moves
// the counts is the accept/reject sequence (a third of the attempts are rejected here), which
// averages out over a longer window. Measured with the three-parameter charts, whose weights were
// always in radians: Radau IIA 0–0.2 s 204–238 steps (±8 %), 0–0.5 s 865–909 (5 %), 0–1 s
// 2 504–2 551 (2 %); trapezoidal 0–0.05 s 165–167. Asserted on 0–0.5 s and 0–0.05 s: within 10 % of
// Wiener–Milenković's count, twice the measured spread. When the quaternion's rotation error was
// measured in parameter units (scale 1), it was allowed twice the rotation error of the others and
// took 562 Radau IIA steps against 865 and 99 trapezoidal steps against 167 (× 0.65, × 0.59).
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <map>
#include <utility>

#include "core/dae_driver.hpp"
#include "formulations/mixed/mixed_dynamics_of.hpp"
#include "formulations/mixed/mixed_statics_of.hpp"
#include "parameterizations/wiener_milenkovic.hpp"
#include "tests/cases/catalog_model.hpp"
#include "tests/harness/type_lists.hpp"

using namespace rotbeam;
using MixedTypes = test::MixedParameterizationTypes<>;

namespace {

// The joined beam under its dead load (cases/joined-beam-dead.yaml) from the static state, 0–end
// with outputs every 10 ms and the adaptive `integrator` at time tolerance 1e-3; the step count.
template <class P>
long adaptive_steps(Integrator integrator, double end) {
    // The model's discretization.rotation is not read here: P is the type solved with.
    const Model model =
        test::catalog_model("joined-beam-dead", {"discretization.formulation=mixed"});
    form::MixedDynamicsOf<P> dyn(model, end, 1e-9);
    VecX x = dyn.from_static_state(form::MixedStaticsOf<P>(model).state_vector());
    VecX xdot = VecX::Zero(dyn.size());
    DaeSettings s;
    s.end_time = end;
    s.time_step = 1e-3;
    s.output_interval = 1e-2;
    s.time_tolerance = 1e-3;
    const DaeOutput ignore = [](double, const VecX&, const VecX&, int) {};
    const DaeOutcome o = integrator == Integrator::radau_iia_3
                             ? integrate_radau_iia(dyn, x, xdot, s, ignore)
                             : integrate_trapezoidal(dyn, x, xdot, s, ignore);
    // stalled_at_round_off: the tolerance met what the arithmetic allows (core/convergence.hpp).
    BOOST_REQUIRE_MESSAGE(
        o.status == SolveStatus::converged || o.status == SolveStatus::stalled_at_round_off,
        P::kName << ": " << o.message);
    return o.steps;
}

// Wiener–Milenković's count for `integrator` over 0–end, made once per test program.
long wiener_milenkovic_steps(Integrator integrator, double end) {
    static std::map<std::pair<Integrator, double>, long> made;
    const auto key = std::make_pair(integrator, end);
    if (!made.contains(key)) made[key] = adaptive_steps<param::WienerMilenkovic>(integrator, end);
    return made[key];
}

template <class P>
void same_steps_as_wiener_milenkovic(Integrator integrator, double end) {
    const long steps = adaptive_steps<P>(integrator, end);
    const long reference = wiener_milenkovic_steps(integrator, end);
    const double ratio = static_cast<double>(steps) / static_cast<double>(reference);
    BOOST_TEST_MESSAGE(P::kName << ", " << choice_name(integrator) << ": " << steps
                                << " steps against Wiener–Milenković's " << reference << ": × "
                                << ratio);
    BOOST_TEST(std::abs(ratio - 1.0) <= 0.10);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(mixed_adaptive_parameterizations)

BOOST_AUTO_TEST_CASE_TEMPLATE(radau_iia_takes_the_steps_of_every_other_parameterization, P,
                              MixedTypes) {
    same_steps_as_wiener_milenkovic<P>(Integrator::radau_iia_3, 0.5);
}

BOOST_AUTO_TEST_CASE_TEMPLATE(trapezoidal_takes_the_steps_of_every_other_parameterization, P,
                              MixedTypes) {
    same_steps_as_wiener_milenkovic<P>(Integrator::trapezoidal, 0.05);
}

BOOST_AUTO_TEST_SUITE_END()
