#include "tests/agreement/agreement_runs.hpp"

#include <boost/test/unit_test.hpp>
#include <chrono>

#include "cases/loader/case_loader.hpp"
#include "core/continuum/continuum.hpp"
#include "core/static_driver.hpp"
#include "formulations/displacement/displacement_statics.hpp"
#include "formulations/mixed/mixed_statics.hpp"
#include "parameterizations/quaternion.hpp"
#include "parameterizations/wiener_milenkovic.hpp"

namespace rotbeam::test {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

int tip_index(const Model& model) {
    const int tip = model.point_index("tip");
    BOOST_TEST_REQUIRE(tip >= 0);
    return tip;
}

// Drives one formulation through the case's load factors and sub-steps with the case's solver
// settings (the same settings `rotbeam run` uses).
TipRun run_fe(StaticProblem& problem, const Model& model) {
    const int tip = tip_index(model);
    const NewtonSettings settings = newton_settings_from(model.solver, model.analysis.statics);
    TipRun run;
    const Clock::time_point start = Clock::now();
    const StaticOutcome out = run_static(
        problem, model.analysis.statics.load_factors, settings, [&](const StepRecord& step) {
            run.tips.push_back(problem.point_state(tip).displacement);
            run.steps += step.substeps;
            run.iterations += step.newton_iterations;
        });
    run.seconds = seconds_since(start);
    BOOST_TEST_INFO(out.message);
    BOOST_TEST_REQUIRE(has_solution(out.status));
    BOOST_TEST_REQUIRE(run.tips.size() == model.analysis.statics.load_factors.size());
    return run;
}

}  // namespace

Model catalog_case(const std::string& name, const std::vector<std::string>& overrides) {
    return load_case(std::string(ROTBEAM_SOURCE_DIR) + "/cases/" + name + ".yaml", overrides);
}

TipRun run_continuum(const Model& model) {
    const int tip = tip_index(model);
    TipRun run;
    const Clock::time_point start = Clock::now();
    const ContinuumOutcome out = solve_continuum(model);
    run.seconds = seconds_since(start);
    BOOST_TEST_INFO(out.message);
    BOOST_TEST_REQUIRE(out.status == "converged");
    for (const ContinuumStep& step : out.steps) {
        run.tips.push_back(step.points[static_cast<std::size_t>(tip)].displacement);
        run.steps += step.substeps;
        run.iterations += step.iterations;
    }
    BOOST_TEST_REQUIRE(run.tips.size() == model.analysis.statics.load_factors.size());
    return run;
}

TipRun run_displacement(const Model& model) {
    form::DisplacementStatics<param::Quaternion> problem(model);
    return run_fe(problem, model);
}

TipRun run_mixed(const Model& model) {
    form::MixedStatics<param::WienerMilenkovic> problem(model);
    return run_fe(problem, model);
}

double relative_difference(const Vec3& a, const Vec3& b) { return (a - b).norm() / b.norm(); }

}  // namespace rotbeam::test
