// Residual + Jacobian evaluation allocates nothing after the first call (the Newton loop must
// not allocate): the C allocator counted (tests/mixed/allocation_counter.cpp: Eigen allocates with
// std::malloc and std::calloc, operator new ends in malloc).
#define BOOST_TEST_MODULE displacement_allocation
#include <algorithm>
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <vector>

#include "core/gauss_collocation.hpp"
#include "core/generalized_alpha.hpp"
#include "core/step_observer.hpp"
#include "deformed.hpp"
#include "dynamic_state.hpp"
#include "formulations/displacement/displacement_statics.hpp"
#include "tests/harness/type_lists.hpp"
#include "tests/mixed/allocation_counter.hpp"

using namespace rotbeam;

template <class P>
long allocations_in_repeated_evaluations() {
    form::DisplacementStatics<P> s(test::curved_twisted(3, 5, true, true));
    s.set_load_factor(1.0);
    s.retract(test::deforming_increment(s.mesh()) * 0.3);
    VecX r;
    SparseMatrix J;
    s.evaluate(r, &J);  // first call: sizes r and copies the fixed pattern into J
    const VecX dx = VecX::Constant(s.size(), 1e-3);
    const long before = test::allocation_count();
    for (int k = 0; k < 3; ++k) {
        s.evaluate(r, &J);
        s.evaluate(r, nullptr);
        s.retract(dx);
    }
    return test::allocation_count() - before;
}

// The counter sees Eigen's allocations (otherwise the test below could not fail).
BOOST_AUTO_TEST_CASE(counter_sees_eigen_allocations) {
    const long before = test::allocation_count();
    VecX v = VecX::Random(100);
    BOOST_TEST(test::allocation_count() > before);
    BOOST_TEST(v.size() == 100);
}

BOOST_AUTO_TEST_CASE_TEMPLATE(evaluate_and_retract_allocate_nothing_after_the_first_call, P,
                              test::ParameterizationTypes<>) {
    BOOST_TEST(allocations_in_repeated_evaluations<P>() == 0);
}

// The dynamics: step start, residual + iteration matrix, retraction, checkpoints,
// energy, reactions and step end allocate nothing after the first step, damped, at a moving state.
template <class P>
long allocations_in_dynamic_steps() {
    form::DisplacementDynamics<P> d(test::moving_model(3, 3, true));
    test::set_moving_state(d);
    VecX r;
    SparseMatrix J;
    d.evaluate(r, &J);  // first call: sizes r and copies the fixed pattern into J
    const GeneralizedAlpha g = GeneralizedAlpha::from_rho_infinity(0.6);
    const VecX dx = VecX::Constant(d.size(), 1e-5);
    const int root = d.mesh().point_node[0];
    d.end_step();
    const long before = test::allocation_count();
    for (int k = 0; k < 3; ++k) {
        d.begin_step(0.22 + 0.01 * k, 0.01, g);
        d.evaluate(r, &J);
        d.evaluate(r, nullptr);
        d.save_state(0);
        d.retract(dx);
        d.restore_state(0);
        d.retract(dx);
        BOOST_TEST(d.energy().total() > 0.0);
        BOOST_TEST(d.reaction(root).norm() > 0.0);
        d.end_step();
    }
    return test::allocation_count() - before;
}

BOOST_AUTO_TEST_CASE_TEMPLATE(dynamic_steps_of_the_formulation_allocate_nothing_after_the_first, P,
                              test::ParameterizationTypes<>) {
    BOOST_TEST(allocations_in_dynamic_steps<P>() == 0);
}

// The moving test structure with dead loads (no follower stiffness) and twelve generalized-α
// steps: the runs of the two whole-step tests below.
namespace {

Model dead_loaded_moving_model() {
    Model m = test::moving_model(3, 3, false);
    m.point_loads[0].frame = LoadFrame::dead;
    m.distributed_loads[0].frame = LoadFrame::dead;
    return m;
}

TimeIntegrationSettings twelve_steps() {
    TimeIntegrationSettings ts;
    ts.time_step = 1e-3;
    ts.end_time = 12e-3;
    ts.rho_infinity = 0.8;
    return ts;
}

}  // namespace

// A whole time step through run_generalized_alpha: the formulation's part above plus the shared
// solve_newton with its NewtonWorkspace kept for the run (vectors, Jacobian, KLU refactored in
// place: core/sparse_lu.hpp) allocates nothing after the first step, whatever the number of
// Newton iterations.
BOOST_AUTO_TEST_CASE(full_time_steps_allocate_nothing_after_the_first) {
    form::DisplacementDynamics<param::Quaternion> d(dead_loaded_moving_model());
    const TimeIntegrationSettings ts = twelve_steps();
    std::vector<long> at_step;
    std::vector<int> iterations;
    at_step.reserve(32);
    iterations.reserve(32);
    const DynamicOutcome out =
        run_generalized_alpha(d, ts, NewtonSettings{}, [&](const TimeStepRecord& s) {
            at_step.push_back(test::allocation_count());
            iterations.push_back(s.newton_iterations);
        });
    BOOST_TEST_REQUIRE(has_solution(out.status), out.message);
    BOOST_TEST_REQUIRE(at_step.size() == 13u);
    std::cout << "allocations per full time step (steps 2-12, " << d.size()
              << " unknowns; Newton iterations in brackets):";
    for (size_t k = 2; k < at_step.size(); ++k) {
        const long a = at_step[k] - at_step[k - 1];
        std::cout << " " << a << " (" << iterations[k] << ")";
        BOOST_TEST(a == 0);
    }
    std::cout << "\n";
}

// The same for the Gauss–Legendre collocation (2 and 3 stages): stage iterations, the iteration
// matrix's three assemblies, its real (KLU) and complex (complex KLU) factorizations and solves,
// kept or refreshed, allocate nothing after the first step. Counted per accepted step by the step
// observer (below), with an output at every step: each output computes the consistent
// acceleration of its state (DisplacementDynamics::initialize_acceleration), whose mass KLU is
// kept from the start and refactored in place.
BOOST_AUTO_TEST_CASE(gauss_collocation_steps_and_outputs_allocate_nothing_after_the_first) {
    for (const int stages : {2, 3}) {
        form::DisplacementDynamics<param::Quaternion> d(dead_loaded_moving_model());
        TimeIntegrationSettings ts = twelve_steps();
        ts.output_interval = ts.time_step;
        std::vector<long> at_step;
        at_step.reserve(32);
        int outputs = 0;
        DynamicOutcome out;
        {
            const ScopedStepObserver observer(
                [](void* context, const StepProgress&) {
                    static_cast<std::vector<long>*>(context)->push_back(test::allocation_count());
                },
                &at_step);
            out = run_gauss_collocation(d, stages, ts, NewtonSettings{},
                                        [&](const TimeStepRecord&) { ++outputs; });
        }
        BOOST_TEST_REQUIRE(has_solution(out.status), out.message);
        BOOST_TEST_REQUIRE(at_step.size() == 12u);
        BOOST_TEST(outputs == 13);  // the start and every step
        std::cout << "Gauss–Legendre " << stages
                  << " stages, allocations per time step with its output (2-12):";
        for (size_t k = 1; k < at_step.size(); ++k) {
            std::cout << " " << at_step[k] - at_step[k - 1];
            BOOST_TEST(at_step[k] - at_step[k - 1] == 0);
        }
        std::cout << "\n";
    }
}

// The step observer (core/step_observer.hpp, `rotbeam bench --targets long-run`) is told about
// every accepted step, after its output, with the cumulative counts the outcome reports; neither
// notifying nor an installed observer that stores into reserved memory allocates.
BOOST_AUTO_TEST_CASE(the_step_observer_sees_every_step_and_allocates_nothing) {
    form::DisplacementDynamics<param::Quaternion> d(dead_loaded_moving_model());
    const TimeIntegrationSettings ts = twelve_steps();
    struct Seen {
        std::vector<StepProgress> progress;
        std::vector<long> allocations;
    } seen;
    seen.progress.reserve(32);
    seen.allocations.reserve(32);
    std::vector<long> at_output;
    at_output.reserve(32);
    DynamicOutcome out;
    {
        const ScopedStepObserver observer(
            [](void* context, const StepProgress& p) {
                Seen& s = *static_cast<Seen*>(context);
                s.progress.push_back(p);
                s.allocations.push_back(test::allocation_count());
            },
            &seen);
        out = run_generalized_alpha(d, ts, NewtonSettings{}, [&](const TimeStepRecord&) {
            at_output.push_back(test::allocation_count());
        });
    }
    BOOST_TEST(current_step_observer.function == nullptr);  // restored at the end of the scope
    BOOST_TEST_REQUIRE(has_solution(out.status), out.message);
    BOOST_TEST_REQUIRE(seen.progress.size() == 12u);
    for (size_t k = 0; k < seen.progress.size(); ++k) {
        BOOST_TEST(seen.progress[k].steps == static_cast<long>(k + 1));
        BOOST_TEST(std::abs(seen.progress[k].time - 1e-3 * static_cast<double>(k + 1)) <= 1e-15);
        if (k > 0)
            BOOST_TEST(seen.progress[k].newton_iterations > seen.progress[k - 1].newton_iterations);
        if (k > 0) BOOST_TEST(seen.allocations[k] - seen.allocations[k - 1] == 0);
    }
    BOOST_TEST(seen.progress.back().newton_iterations == out.newton_iterations);
    BOOST_TEST(seen.progress.back().time == ts.end_time);
}
