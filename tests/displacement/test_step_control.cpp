// Time-step control of the Lie-group generalized-α (core/generalized_alpha.hpp,
// core/step_size_control.hpp): a step whose Newton fails is recovered by halving it.
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include "cases/loader/case_loader.hpp"
#include "core/errors.hpp"
#include "core/static_driver.hpp"
#include "formulations/displacement/displacement_dynamics.hpp"
#include "formulations/displacement/displacement_modal.hpp"
#include "tests/displacement/free_vibration_runs.hpp"
#include "tests/displacement/models.hpp"

using namespace rotbeam;
using rotbeam::test::first_mode_at_rest;

BOOST_AUTO_TEST_SUITE(step_control)

// A problem that refuses every step longer than `h_fail` ending in (t_from, t_to] (as a chart
// refuses a state near its singular angle: SingularityError), and is otherwise `inner`.
class FailsAtFullSize : public SecondOrderProblem {
  public:
    FailsAtFullSize(SecondOrderProblem& inner, double h_fail, double t_from, double t_to)
        : inner_(inner), h_fail_(h_fail), t_from_(t_from), t_to_(t_to) {}
    int size() const override { return inner_.size(); }
    void evaluate(VecX& r, SparseMatrix* J) override {
        if (h_ > h_fail_ && t_ > t_from_ && t_ <= t_to_) {
            throw SingularityError("test", "a step longer than h_fail", 0.0, std::to_string(h_));
        }
        inner_.evaluate(r, J);
    }
    void retract(const Eigen::Ref<const VecX>& dx) override { inner_.retract(dx); }
    void save_state(int slot) override { inner_.save_state(slot); }
    void restore_state(int slot) override { inner_.restore_state(slot); }
    const VecX& residual_scale() const override { return inner_.residual_scale(); }
    const VecX& increment_scale() const override { return inner_.increment_scale(); }
    void initialize_acceleration(double t) override { inner_.initialize_acceleration(t); }
    void begin_step(double t_next, double h, const GeneralizedAlpha& g) override {
        t_ = t_next;
        h_ = h;
        inner_.begin_step(t_next, h, g);
    }
    void end_step() override { inner_.end_step(); }

  private:
    SecondOrderProblem& inner_;
    double h_fail_, t_from_, t_to_;
    double t_ = 0.0, h_ = 0.0;
};

// The first mode of the free-vibration cantilever (below: x(t) = x_0 cos(ω₁ t), tip amplitude
// 1e-4 L), Δt = 1 ms, ρ∞ = 1, over four periods, with every step ending in (0.1, 0.1 + 3 ms]
// refused at its full size (three steps). Without cuts the run stops at the first of them with
// `singular`, naming the step and the time. With cuts each is covered by two halves from the
// unchanged state n and the run goes on; its tip history must still be the first mode's to the
// trapezoidal rule's accuracy: phase error (ω h)²/12 · ω T at most (the halved steps err less),
// i.e. |x − x_exact| ≤ A (ω h)²/12 ω T (with a margin 1.5 for the amplitude error's share and the
// non-linearity's 1e-8). A cut that did not restore the state n (a half step started from the
// failed iterate) would put an error of the size of the step's increment, ~A ω h = 5e-2 A, into
// the history, 60× this bound.
BOOST_AUTO_TEST_CASE(a_step_cut_recovers_a_step_that_fails_at_full_size) {
    Model m = load_case(std::string(ROTBEAM_SOURCE_DIR) + "/cases/free-vibration.yaml");
    m.point_loads.clear();
    m.analysis.dynamics.initial_state = InitialState::rest;
    NewtonSettings newton;
    newton.residual_tolerance = 1e-14;
    newton.increment_tolerance = 1e-14;
    constexpr double kDt = 1e-3;
    for (const int max_cuts : {0, kDynamicStepCuts}) {
        form::DisplacementDynamics<param::RotationVector> d(m);
        const form::ModalSolution modes = first_mode_at_rest(m, d);
        const double omega = 2.0 * kPi * modes.frequencies_hz[0];
        const int tip = m.point_index("tip");
        const int tip_dof = d.mesh().nodes[d.mesh().point_node[tip]].dof;
        VecX shape = modes.shapes[0];
        shape *= 1e-4 / std::abs(shape[tip_dof + 2]);
        const Vec3 tip0 = shape.segment<3>(tip_dof);
        d.statics().retract(shape);
        d.adopt_static_state();
        FailsAtFullSize problem(d, 0.75 * kDt, 0.1 + 1e-9, 0.1 + 3e-3 + 1e-9);
        TimeIntegrationSettings ts;
        ts.time_step = kDt;
        ts.end_time = 4.0 * 2.0 * kPi / omega;
        ts.max_cuts = max_cuts;
        double worst = 0.0;
        int outputs = 0;
        const DynamicOutcome out =
            run_generalized_alpha(problem, ts, newton, [&](const TimeStepRecord& s) {
                ++outputs;
                worst = std::max(
                    worst,
                    (d.point_state(tip).displacement - tip0 * std::cos(omega * s.time)).norm());
            });
        std::cout << "max_cuts " << max_cuts << ": " << to_string(out.status) << ": " << out.message
                  << "; tip error " << worst << "\n";
        if (max_cuts == 0) {
            BOOST_TEST(out.status == SolveStatus::singular);
            BOOST_TEST(out.message.find("at time step 101 (t = 0.101") != std::string::npos);
            continue;
        }
        BOOST_TEST_REQUIRE(has_solution(out.status));
        BOOST_TEST(out.control.step_cuts == 3);
        BOOST_TEST(out.message.find("3 steps cut to h/2") != std::string::npos);
        BOOST_TEST(outputs == static_cast<int>(std::ceil(ts.end_time / kDt - 1e-9)) + 1);
        const double A = tip0.norm(), wh = omega * kDt;
        const double bound = 1.5 * A * wh * wh / 12.0 * omega * ts.end_time;
        std::cout << "  bound " << bound << "\n";
        BOOST_TEST(worst <= bound);
    }
}

BOOST_AUTO_TEST_SUITE_END()
