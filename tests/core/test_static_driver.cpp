// The shared static driver on small problems whose behaviour is known in closed form: convergence
// rate, step cutting, and truthful statuses (diverged, singular) with the step in the message.
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "core/sparse_lu.hpp"
#include "core/static_driver.hpp"

using namespace rotbeam;

namespace {

// Two unknowns (x, y): r = (g(x) − λ, y − x²), with g chosen per test. The retraction is additive
// but refuses |x| ≥ x_limit (a stand-in for a parameterization's singular angle).
class ToyProblem : public StaticSystem {
  public:
    ToyProblem(std::function<double(double)> g, std::function<double(double)> dg,
               double x_limit = 1e300)
        : g_(std::move(g)), dg_(std::move(dg)), x_limit_(x_limit) {
        scale_ = VecX::Ones(2);
        pattern_.resize(2, 2);
        pattern_.insert(0, 0) = 1.0;
        pattern_.insert(1, 0) = 1.0;
        pattern_.insert(1, 1) = 1.0;
        pattern_.makeCompressed();
    }
    int size() const override { return 2; }
    void set_load_factor(double lambda) override { lambda_ = lambda; }
    void evaluate(VecX& r, SparseMatrix* J) override {
        r.resize(2);
        r << g_(x_[0]) - lambda_, x_[1] - x_[0] * x_[0];
        if (J) {
            *J = pattern_;
            J->coeffRef(0, 0) = dg_(x_[0]);
            J->coeffRef(1, 0) = -2.0 * x_[0];
            J->coeffRef(1, 1) = 1.0;
        }
    }
    void retract(const Eigen::Ref<const VecX>& dx) override {
        const double x = x_[0] + dx[0];
        if (std::abs(x) >= x_limit_) throw SingularityError("toy", "retract", x);
        x_ += dx;
    }
    void save_state(int slot) override { saved_[slot] = x_; }
    void restore_state(int slot) override { x_ = saved_[slot]; }
    const VecX& residual_scale() const override { return scale_; }
    const VecX& increment_scale() const override { return scale_; }
    std::string describe_state() const override { return "x = " + std::to_string(x_[0]); }

    Eigen::Vector2d x_ = Eigen::Vector2d::Zero();

  private:
    std::function<double(double)> g_, dg_;
    double x_limit_;
    double lambda_ = 0.0;
    VecX scale_;
    SparseMatrix pattern_;
    Eigen::Vector2d saved_[kCheckpointSlots];
};

NewtonSettings tight() {
    NewtonSettings s;
    s.residual_tolerance = 1e-12;
    s.increment_tolerance = 1e-12;
    return s;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(static_driver)

BOOST_AUTO_TEST_CASE(newton_converges_quadratically_on_a_smooth_problem) {
    // g = x + x³: Newton from 0 to λ = 2 (root x = 1) takes a handful of iterations.
    ToyProblem p([](double x) { return x + x * x * x; }, [](double x) { return 1 + 3 * x * x; });
    p.set_load_factor(2.0);
    const NewtonOutcome o = solve_newton(p, tight());
    BOOST_TEST(o.converged);
    BOOST_TEST(std::abs(p.x_[0] - 1.0) < 1e-14);
    BOOST_TEST(std::abs(p.x_[1] - 1.0) < 1e-14);
    BOOST_TEST(o.iterations <= 8);
}

BOOST_AUTO_TEST_CASE(step_cutting_rescues_a_step_newton_cannot_take_at_once) {
    // g = atan(x − 5) + atan 5 (g(0) = 0): from x = 0 the tangent is nearly flat (1/26), so a
    // full Newton step to x = 10 overshoots and diverges; small sub-steps converge.
    ToyProblem p([](double x) { return std::atan(x - 5.0) + std::atan(5.0); },
                 [](double x) { return 1.0 / (1.0 + (x - 5.0) * (x - 5.0)); });
    NewtonSettings s = tight();
    s.line_search = false;
    s.max_iterations = 30;
    const double target = 2.0 * std::atan(5.0);
    int calls = 0;
    const StaticOutcome o = run_static(p, {target}, s, [&](const StepRecord&) { ++calls; });
    BOOST_TEST(o.status == SolveStatus::converged);
    BOOST_TEST(calls == 1);
    BOOST_TEST(o.steps.at(0).substeps > 1);
    BOOST_TEST(std::abs(p.x_[0] - 10.0) < 1e-10);
}

// The atan problem of the test above, whose cold step needs sub-steps (root x = 10, y = 100).
ToyProblem atan_problem() {
    return ToyProblem([](double x) { return std::atan(x - 5.0) + std::atan(5.0); },
                      [](double x) { return 1.0 / (1.0 + (x - 5.0) * (x - 5.0)); });
}

BOOST_AUTO_TEST_CASE(a_step_with_a_good_guess_is_one_solve_without_sub_steps) {
    // From (9.9, 98), where the tangent is steep (1/25), Newton converges in a few iterations
    // at the full load; the cold step needs sub-steps (the test above).
    ToyProblem p = atan_problem();
    NewtonSettings s = tight();
    s.line_search = false;
    s.max_iterations = 30;
    std::vector<std::size_t> asked;
    const StepGuess guess = [&](std::size_t step) {
        asked.push_back(step);
        p.x_ << 9.9, 98.0;
        return true;
    };
    const StaticOutcome o = run_static(p, {2.0 * std::atan(5.0)}, s, nullptr, {}, guess);
    BOOST_TEST(o.status == SolveStatus::converged, o.message);
    BOOST_TEST((asked == std::vector<std::size_t>{0}));
    BOOST_TEST(o.steps.at(0).substeps == 1);
    BOOST_TEST(o.steps.at(0).newton_iterations <= 8);
    BOOST_TEST(std::abs(p.x_[0] - 10.0) < 1e-10);
}

BOOST_AUTO_TEST_CASE(a_refused_guess_leaves_the_step_to_the_sub_steps_from_the_last_state) {
    // From x = −20 the tangent is flat (1/626): the full Newton step overshoots and fails, so the
    // step is stepped from the unloaded state exactly as without a guess (same sub-steps, same
    // iterations counted, same root).
    NewtonSettings s = tight();
    s.line_search = false;
    s.max_iterations = 30;
    const double target = 2.0 * std::atan(5.0);
    ToyProblem cold = atan_problem();
    const StaticOutcome c = run_static(cold, {target}, s, nullptr);
    ToyProblem p = atan_problem();
    std::ostringstream trace;
    s.trace = &trace;
    const StaticOutcome o = run_static(p, {target}, s, nullptr, {}, [&](std::size_t) {
        p.x_ << -20.0, 400.0;
        return true;
    });
    BOOST_TEST(trace.str().find("initial guess refused") != std::string::npos);
    BOOST_TEST(o.status == SolveStatus::converged, o.message);
    BOOST_TEST(o.steps.at(0).substeps == c.steps.at(0).substeps);
    BOOST_TEST(o.steps.at(0).newton_iterations == c.steps.at(0).newton_iterations);
    BOOST_TEST(p.x_[0] == cold.x_[0]);
}

BOOST_AUTO_TEST_CASE(the_cut_budget_bounds_consecutive_halvings_not_their_sum) {
    // g = x + x³ with at most 4 Newton iterations per sub-step: only short sub-steps converge,
    // so the driver halves, takes two sub-steps, doubles, fails again, ... — many halvings in
    // one reported step, never many in a row. The budget of 4 bounds the depth (a smallest
    // sub-step of 1/16 of the first); summed over the step the halvings exceed it, and a
    // driver that counted the sum would report `diverged` although every stretch is passable.
    ToyProblem p([](double x) { return x + x * x * x; }, [](double x) { return 1 + 3 * x * x; });
    NewtonSettings s = tight();
    s.line_search = false;
    s.max_iterations = 4;
    s.max_step_cuts = 4;
    s.substeps = 16;
    std::ostringstream trace;
    s.trace = &trace;
    const StaticOutcome o = run_static(p, {30.0}, s, nullptr);
    BOOST_TEST(o.status == SolveStatus::converged, o.message);
    BOOST_TEST(std::abs(p.x_[0] + p.x_[0] * p.x_[0] * p.x_[0] - 30.0) < 1e-9);
    // The sum of the halvings exceeded the budget (what makes this test discriminate).
    const std::string t = trace.str();
    int halvings = 0;
    for (size_t at = t.find("step cut"); at != std::string::npos; at = t.find("step cut", at + 1)) {
        ++halvings;
    }
    BOOST_TEST(halvings > s.max_step_cuts, halvings << " halvings");
}

BOOST_AUTO_TEST_CASE(no_solution_gives_diverged_with_step_and_load_factor) {
    // g = sin: no root beyond λ = 1. Steps 0.5 and 0.9 converge, 1.5 cannot.
    ToyProblem p([](double x) { return std::sin(x); }, [](double x) { return std::cos(x); });
    NewtonSettings s = tight();
    s.max_step_cuts = 6;
    const StaticOutcome o = run_static(p, {0.5, 0.9, 1.5}, s, nullptr);
    BOOST_TEST(o.status == SolveStatus::diverged);
    BOOST_TEST(o.steps.size() == 2u);
    BOOST_TEST(o.message.find("load step 3") != std::string::npos, o.message);
    BOOST_TEST(o.message.find("x = ") != std::string::npos, o.message);
    // The state is the last converged sub-step (between 0.9 and the fold at 1), not garbage.
    BOOST_TEST(o.last_converged_load_factor > 0.9);
    BOOST_TEST(o.last_converged_load_factor <= 1.0);
    BOOST_TEST(std::abs(std::sin(p.x_[0]) - o.last_converged_load_factor) < 1e-12);
}

BOOST_AUTO_TEST_CASE(a_refusing_retraction_gives_status_singular) {
    // g = x, but the retraction refuses |x| ≥ 1.2: λ = 1.5 cannot be reached.
    ToyProblem p([](double x) { return x; }, [](double) { return 1.0; }, 1.2);
    NewtonSettings s = tight();
    s.max_step_cuts = 5;
    const StaticOutcome o = run_static(p, {1.0, 1.5}, s, nullptr);
    BOOST_TEST(o.status == SolveStatus::singular);
    BOOST_TEST(o.steps.size() == 1u);
    BOOST_TEST(o.message.find("singular at load step 2") != std::string::npos, o.message);
}

// A load far below tolerance × residual scale is still a load: the driver takes the Newton step
// (here the exact answer x = λ of g = x + x³ near 0) instead of calling the unloaded state
// converged, and a load factor of 1e-14 is not mistaken for the 0 it starts from.
BOOST_AUTO_TEST_CASE(a_tiny_load_is_solved_not_accepted_at_the_unloaded_state) {
    for (const double lambda : {1e-6, 1e-14, 1e-20}) {
        ToyProblem p([](double x) { return x + x * x * x; },
                     [](double x) { return 1 + 3 * x * x; });
        const StaticOutcome out = run_static(p, {lambda}, tight(), [](const StepRecord&) {});
        BOOST_TEST((out.status == SolveStatus::converged));
        BOOST_TEST(std::abs(p.x_[0] - lambda) <= 1e-12 * lambda);
        BOOST_TEST(out.steps.at(0).newton_iterations >= 1);
    }
}

// The symbolic factorization is made once per pattern. Refactoring the same
// pattern with new values must not analyse again (and must still solve the new matrix); a new
// pattern must. For each solver kind.
BOOST_AUTO_TEST_CASE(the_linear_solver_analyses_a_pattern_once_and_solves_each_new_matrix) {
    for (const auto kind : {SparseLUSolver::Kind::sparse_lu, SparseLUSolver::Kind::klu_refactor,
                            SparseLUSolver::Kind::dense}) {
        SparseLUSolver lu(kind);
        SparseMatrix J(3, 3);
        J.insert(0, 0) = 4.0;
        J.insert(1, 0) = 1.0;
        J.insert(1, 1) = 3.0;
        J.insert(2, 1) = 1.0;
        J.insert(2, 2) = 2.0;
        J.makeCompressed();
        const VecX b = VecX::Ones(3);
        VecX x;
        for (int k = 1; k <= 3; ++k) {
            J.coeffRef(0, 0) = 4.0 * k;
            BOOST_TEST(lu.factorize(J));
            lu.solve(b, x);
            BOOST_TEST((J * x - b).norm() <= 1e-14);
        }
        BOOST_TEST(lu.symbolic_analyses() == 1);
        BOOST_TEST(lu.factor_nonzeros() >= static_cast<double>(J.nonZeros()));
        J.insert(0, 2) = 1.0;  // a new pattern
        J.makeCompressed();
        BOOST_TEST(lu.factorize(J));
        lu.solve(b, x);
        BOOST_TEST((J * x - b).norm() <= 1e-14);
        BOOST_TEST(lu.symbolic_analyses() == 2);
    }
}

// The Newton driver keeps its analysis across iterations and across solves sharing a workspace
// (the load steps of run_static, the time steps of a dynamic run): at most one analysis per
// solver of the workspace (Newton, damping test), however many factorizations.
BOOST_AUTO_TEST_CASE(newton_iterations_sharing_a_workspace_reuse_the_symbolic_analysis) {
    ToyProblem p([](double x) { return x + x * x * x; }, [](double x) { return 1 + 3 * x * x; });
    NewtonWorkspace workspace;
    int iterations = 0;
    for (const double lambda : {0.5, 1.0, 2.0, 4.0}) {
        p.set_load_factor(lambda);
        const NewtonOutcome o = solve_newton(p, tight(), workspace);
        BOOST_TEST(o.converged);
        iterations += o.iterations;
    }
    BOOST_TEST(iterations >= 8);
    BOOST_TEST(workspace.symbolic_analyses() >= 1);
    BOOST_TEST(workspace.symbolic_analyses() <= 2);
}

BOOST_AUTO_TEST_SUITE_END()
