// Time-step control of the Lie-group generalized-α and the Gauss–Legendre collocation
// (core/time_stepping.hpp, core/step_size_control.hpp): a step whose Newton fails is recovered by
// halving it; adaptive Gauss steps meet their global tolerance against the exact motion.
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include "cases/loader/case_loader.hpp"
#include "core/errors.hpp"
#include "core/gauss_collocation.hpp"
#include "core/static_driver.hpp"
#include "formulations/displacement/displacement_dynamics.hpp"
#include "formulations/displacement/displacement_modal.hpp"
#include "tests/displacement/free_vibration_runs.hpp"
#include "tests/displacement/models.hpp"

using namespace rotbeam;
using rotbeam::test::first_mode_at_rest;

BOOST_AUTO_TEST_SUITE(step_control)

// Forwards every call of a SecondOrderProblem (Base: it or a derived interface) to `inner`; the
// test problems below override what they refuse.
// Newton tolerances 1e-14: far below the schemes' errors that the step-cut tests bound.
NewtonSettings tight_newton() {
    NewtonSettings newton;
    newton.residual_tolerance = 1e-14;
    newton.increment_tolerance = 1e-14;
    return newton;
}

template <class Base>
class Forwarding : public Base {
  public:
    explicit Forwarding(Base& inner) : inner_(inner) {}
    int size() const override { return inner_.size(); }
    void evaluate(VecX& r, SparseMatrix* J) override { inner_.evaluate(r, J); }
    void retract(const Eigen::Ref<const VecX>& dx) override { inner_.retract(dx); }
    void save_state(int slot) override { inner_.save_state(slot); }
    void restore_state(int slot) override { inner_.restore_state(slot); }
    const VecX& residual_scale() const override { return inner_.residual_scale(); }
    const VecX& increment_scale() const override { return inner_.increment_scale(); }
    void initialize_acceleration(double t) override { inner_.initialize_acceleration(t); }
    void begin_step(double t_next, double h, const GeneralizedAlpha& g) override {
        inner_.begin_step(t_next, h, g);
    }
    void end_step() override { inner_.end_step(); }

  protected:
    Base& inner_;
};

// A problem that refuses every step longer than `h_fail` ending in (t_from, t_to] (as a chart
// refuses a state near its singular angle: SingularityError), and is otherwise `inner`.
class FailsAtFullSize : public Forwarding<SecondOrderProblem> {
  public:
    FailsAtFullSize(SecondOrderProblem& inner, double h_fail, double t_from, double t_to)
        : Forwarding(inner), h_fail_(h_fail), t_from_(t_from), t_to_(t_to) {}
    void evaluate(VecX& r, SparseMatrix* J) override {
        if (h_ > h_fail_ && t_ > t_from_ && t_ <= t_to_) {
            throw SingularityError("test", "a step longer than h_fail", 0.0, std::to_string(h_));
        }
        inner_.evaluate(r, J);
    }
    void begin_step(double t_next, double h, const GeneralizedAlpha& g) override {
        t_ = t_next;
        h_ = h;
        inner_.begin_step(t_next, h, g);
    }

  private:
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
    const NewtonSettings newton = tight_newton();
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

namespace {

// The free-vibration cantilever at rest, started in its first discrete mode with tip amplitude
// A = 1e-4 L: the transverse tip motion is z(t) = z_0 cos(ω₁ t) up to the geometric
// non-linearity, which is cubic in the transverse direction (~A³/L² = 1e-12 m) but quadratic in
// the axial one (the foreshortening ~A²/L = 1e-8 m, at 2ω₁): the Gauss tests compare z, whose
// exact motion is known far below their bounds.
struct FirstModeStart {
    double omega = 0.0;
    Vec3 tip0 = Vec3::Zero();
    int tip = 0;
};

Model unloaded_free_vibration() {
    Model m = load_case(std::string(ROTBEAM_SOURCE_DIR) + "/cases/free-vibration.yaml");
    m.point_loads.clear();
    m.analysis.dynamics.initial_state = InitialState::rest;
    return m;
}

FirstModeStart start_in_first_mode(const Model& m,
                                   form::DisplacementDynamics<param::RotationVector>& d) {
    const form::ModalSolution modes = first_mode_at_rest(m, d);
    FirstModeStart f;
    f.omega = 2.0 * kPi * modes.frequencies_hz[0];
    f.tip = m.point_index("tip");
    const int tip_dof = d.mesh().nodes[d.mesh().point_node[f.tip]].dof;
    VecX shape = modes.shapes[0];
    shape *= 1e-4 / std::abs(shape[tip_dof + 2]);
    f.tip0 = shape.segment<3>(tip_dof);
    d.statics().retract(shape);
    d.adopt_static_state();
    return f;
}

// Refuses (SingularityError) every stage state of a full-size step (h = 1 ms on the 1 ms grid:
// stage times t_n + c_i h, c_i = ½ ∓ √3/6) ending in (0.1, 0.103], as a chart refuses a state near
// its singular angle; the stages of a half step sit at other fractions of the grid and pass.
class RefusesFullSizeStages : public Forwarding<CollocationProblem> {
  public:
    explicit RefusesFullSizeStages(CollocationProblem& inner) : Forwarding(inner) {}
    bool energy_terms(EnergyTerms& terms) override { return inner_.energy_terms(terms); }
    void start_rates(VecX& v, VecX& v_dot) const override { inner_.start_rates(v, v_dot); }
    void set_start_acceleration(const Eigen::Ref<const VecX>& v_dot) override {
        inner_.set_start_acceleration(v_dot);
    }
    void set_stage(const Eigen::Ref<const VecX>& delta, const Eigen::Ref<const VecX>& v,
                   const Eigen::Ref<const VecX>& v_dot, double t, double c_v, double c_a) override {
        const double in_step = t / 1e-3 - std::floor(t / 1e-3);
        const double c1 = 0.5 - std::sqrt(3.0) / 6.0;
        const bool full = std::abs(in_step - c1) < 1e-6 || std::abs(in_step - (1.0 - c1)) < 1e-6;
        if (full && t > 0.1 && t < 0.103) {
            throw SingularityError("test", "a full-size step's stage", 0.0, std::to_string(t));
        }
        inner_.set_stage(delta, v, v_dot, t, c_v, c_a);
    }
    void velocity_of_rate(const Eigen::Ref<const VecX>& delta, const Eigen::Ref<const VecX>& w,
                          Eigen::Ref<VecX> v) const override {
        inner_.velocity_of_rate(delta, w, v);
    }
};

}  // namespace

// The Gauss–Legendre 2 step cut, as the generalized-α test above: three full-size steps refused
// (stages in (0.1, 0.103]). Without cuts the run stops `singular` at time step 101; with cuts each
// refused step is covered by two halves from the unchanged state n, the outputs stay on the grid,
// and the tip follows x_0 cos ω₁t to the scheme's accuracy: Gauss–Legendre 2 has the phase error
// (ωh)⁵/720 per step ((2!)²/(4! 5!) of the (2,2) Padé approximant), so |x − x_exact| ≤
// A (ωh)⁴/720 ω T for the transverse z (bound below: 1.5 × that, the margin for the amplitude
// error's share, + 1e-12 m for the cubic non-linearity). A cut that did not restore state n would
// put ~A ω h = 5e-2 A into the history, orders above it.
BOOST_AUTO_TEST_CASE(a_gauss_step_cut_recovers_a_step_refused_at_full_size) {
    const Model m = unloaded_free_vibration();
    const NewtonSettings newton = tight_newton();
    constexpr double kDt = 1e-3;
    for (const int max_cuts : {0, kDynamicStepCuts}) {
        form::DisplacementDynamics<param::RotationVector> d(m);
        const FirstModeStart f = start_in_first_mode(m, d);
        RefusesFullSizeStages problem(d);
        TimeIntegrationSettings ts;
        ts.time_step = kDt;
        ts.end_time = 4.0 * 2.0 * kPi / f.omega;
        ts.max_cuts = max_cuts;
        double worst = 0.0;
        int outputs = 0;
        const DynamicOutcome out =
            run_gauss_collocation(problem, 2, ts, newton, [&](const TimeStepRecord& s) {
                ++outputs;
                const double exact = f.tip0.z() * std::cos(f.omega * s.time);
                worst = std::max(worst, std::abs(d.point_state(f.tip).displacement.z() - exact));
            });
        std::cout << "Gauss 2, max_cuts " << max_cuts << ": " << to_string(out.status) << ": "
                  << out.message << "; tip error " << worst << "\n";
        if (max_cuts == 0) {
            BOOST_TEST(out.status == SolveStatus::singular);
            BOOST_TEST(out.message.find("at time step 101 (t = 0.101") != std::string::npos);
            continue;
        }
        BOOST_TEST_REQUIRE(has_solution(out.status), out.message);
        BOOST_TEST(out.control.step_cuts == 3);
        BOOST_TEST(out.steps == static_cast<int>(std::ceil(ts.end_time / kDt - 1e-9)) + 3);
        BOOST_TEST(outputs == static_cast<int>(std::ceil(ts.end_time / kDt - 1e-9)) + 1);
        const double A = f.tip0.norm(), wh = f.omega * kDt;
        const double bound = 1.5 * A * std::pow(wh, 4) / 720.0 * f.omega * ts.end_time + 1e-12;
        std::cout << "  bound " << bound << "\n";
        BOOST_TEST(worst <= bound);
    }
}

// Adaptive Gauss–Legendre steps (step doubling, core/gauss_collocation.hpp) on the first-mode
// motion over four periods, against z_0 cos ω₁t (exact up to ~1e-12 m): the global error of the
// tip's z at the end, scaled like the tolerance (translations by the length scale, 1 m here), must
// be within the tolerance τ for each τ — the controller's promise (core/step_size_control.hpp:
// local errors ≤ τ h/T summed over the window, undamped modes propagating them without growth) —
// and the step count must scale as τ^(−1/2s): τ/16 doubles it for 2 stages, τ/64 for 3. The count
// ratio is checked within [1.7, 2.3]: the first steps (from the given 1 ms, growth ≤ 2 per step)
// and the step that lands on the end are not at the asymptotic size, a few of some 20–200 steps.
// Tolerances 6.4e-5 … 1e-6 (0.64 … 0.01 of the amplitude): above the estimate's floor on this
// motion. The start has no axial foreshortening (~A²/L = 1e-8 m), so it excites the axial modes
// (ω ≳ 1e4 rad/s, unresolved) at about that amplitude; step doubling reports such a mode at ~its
// amplitude, and a tolerance whose allowance τ h/T falls below that resolves them (measured:
// Gauss 2 at τ = 6.25e-8 took 78 620 steps where τ = 1e-6 took 48; Gauss 3 at 1.6e-8, 47 856) —
// correctly so, the axial oscillation is part of the discrete motion, but then the first mode's
// order no longer sets the count.
void check_adaptive(int stages, const std::vector<double>& tolerances, bool check_count) {
    const Model m = unloaded_free_vibration();
    const NewtonSettings newton = tight_newton();
    std::vector<int> steps;
    for (const double tau : tolerances) {
        form::DisplacementDynamics<param::RotationVector> d(m);
        const FirstModeStart f = start_in_first_mode(m, d);
        TimeIntegrationSettings ts;
        ts.time_step = 1e-3;
        ts.end_time = 4.0 * 2.0 * kPi / f.omega;
        ts.output_interval = ts.end_time;
        ts.tolerance = tau;
        ts.length_scale = 1.0;
        const DynamicOutcome out = run_gauss_collocation(d, stages, ts, newton, {});
        BOOST_TEST_REQUIRE(has_solution(out.status), out.message);
        const double exact = f.tip0.z() * std::cos(f.omega * ts.end_time);
        const double error = std::abs(d.point_state(f.tip).displacement.z() - exact);
        std::printf(
            "Gauss %d adaptive, tolerance %.1e: %d steps (%d rejected), error at the end "
            "%.3e (%.3f of the tolerance)\n",
            stages, tau, out.steps, out.control.rejected_steps, error, error / tau);
        BOOST_TEST(error <= tau);
        steps.push_back(out.steps);
    }
    for (size_t k = 1; check_count && k < steps.size(); ++k) {
        const double ratio = static_cast<double>(steps[k]) / steps[k - 1];
        BOOST_TEST(ratio >= 1.7);
        BOOST_TEST(ratio <= 2.3);
    }
}

BOOST_AUTO_TEST_CASE(adaptive_gauss_legendre_2_meets_its_global_tolerance) {
    check_adaptive(2, {1.6e-5, 1e-6}, true);  // measured 26 → 48 steps
}

BOOST_AUTO_TEST_CASE(adaptive_gauss_legendre_3_meets_its_global_tolerance) {
    // The count is not checked: between the floor above and τ ≈ 1e-4 the 3-stage steps are not in
    // their asymptotic range (measured 24 → 26 steps for τ 6.4e-5 → 1e-6, steps of ~20 ms, ωh ≈ 1),
    // so τ^(−1/6) does not describe them there; the errors are checked.
    check_adaptive(3, {6.4e-5, 1e-6}, false);
}

BOOST_AUTO_TEST_SUITE_END()
