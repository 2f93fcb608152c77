// The continuum solver against the exact solutions: roll-up, helix and the inextensible elastica
// (to ≤ 1e-9 relative).
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <string>

#include "continuum_models.hpp"
#include "core/continuum/continuum.hpp"
#include "core/oracles/elastica.hpp"
#include "core/oracles/helix.hpp"
#include "core/oracles/rollup.hpp"
#include "tests/cases/catalog_model.hpp"

using namespace rotbeam;

namespace {

// ODE tolerance 1e-13 on O(1) scaled states and a 1e-11 free-end residual give errors of a few
// 1e-12 L here; 1e-9 is the accuracy the reference promises, not a loosened bound.
constexpr double kExact = 1e-9;

}  // namespace

BOOST_AUTO_TEST_SUITE(continuum_exact)

BOOST_AUTO_TEST_CASE(rollup_matches_the_exact_circle_up_to_two_full_turns) {
    // docs/benchmarks.md §1 (cases/cantilever-moment-4.yaml): L = 12, EI = 2.5e6,
    // M = −λ π EI/L e_y; λ to 4 (two turns) in steps of 0.25.
    const double L = 12.0;
    const Model model = test::catalog_model("cantilever-moment-4", {});
    const ContinuumOutcome outcome = solve_continuum(model);
    BOOST_TEST_REQUIRE(outcome.status == "converged", outcome.message);
    double worst = 0.0;
    for (const ContinuumStep& step : outcome.steps) {
        const oracle::RollupState tip = oracle::rollup_tip(L, step.load_factor);
        worst = std::max(worst, (step.points[1].displacement - tip.displacement).norm() / L);
        worst = std::max(worst, (step.points[1].rotation - tip.rotation).norm());
        for (std::size_t i = 0; i < step.centreline.size(); ++i) {
            const double s = step.centreline_s[i];
            const Vec3 exact =
                oracle::rollup_state(L, step.load_factor, s).displacement + Vec3(s, 0, 0);
            worst = std::max(worst, (step.centreline[i] - exact).norm() / L);
        }
    }
    BOOST_TEST_MESSAGE("roll-up, λ ≤ 4: worst error " << worst);
    BOOST_TEST(worst < kExact);
}

BOOST_AUTO_TEST_CASE(helix_matches_the_exact_solution_to_kappa_L_4pi_dead_and_follower) {
    // docs/benchmarks.md §5 (cases/helix.yaml): L = 10, EI₂ = EI₃ = GJ = 100, EA = GA = 1e4,
    // M = κ EI n, κL = π/2 … 4π; the follower variant by override.
    const double L = 10.0;
    const Vec3 n(0.6, 0.0, 0.8);
    for (LoadFrame frame : {LoadFrame::dead, LoadFrame::follower}) {
        const Model model = test::catalog_model(
            "helix", {"loads.tip-moment.frame=" +
                      std::string(frame == LoadFrame::dead ? "dead" : "follower")});
        BOOST_TEST_REQUIRE((model.point_loads.at(0).frame == frame));
        const ContinuumOutcome outcome = solve_continuum(model);
        BOOST_TEST_REQUIRE(outcome.status == "converged", outcome.message);
        double worst = 0.0;
        for (const ContinuumStep& step : outcome.steps) {
            const oracle::HelixState tip = oracle::helix_state(step.load_factor / L, n, L);
            worst = std::max(worst, (step.points[1].displacement - tip.displacement).norm() / L);
            worst = std::max(worst, (step.points[1].rotation - tip.rotation).norm());
        }
        BOOST_TEST_MESSAGE("helix (" << (frame == LoadFrame::dead ? "dead" : "follower")
                                     << "), κL ≤ 4π: worst error " << worst);
        BOOST_TEST(worst < kExact);
    }
}

BOOST_AUTO_TEST_CASE(rigid_compliance_rows_give_the_inextensible_elastica) {
    // Zero axial and shear compliance (rigid rows), EI = 2, L = 3, dead tip force P e_z with
    // PL²/EI = 1, 2, 5, 10, 30, 100: the elliptic-integral oracle (itself checked against
    // Mattiasson up to 10).
    const double L = 3.0, EI = 2.0;
    const Mat6 C = test::diagonal_compliance((Vec6() << 0, 0, 0, 1.5, EI, EI).finished());
    const std::vector<double> alphas = {1.0, 2.0, 5.0, 10.0, 30.0, 100.0};
    const Model model = test::cantilever(Vec3(L, 0, 0), C, Vec3(0, 0, EI / (L * L)), Vec3::Zero(),
                                         LoadFrame::dead, alphas);
    const ContinuumOutcome outcome = solve_continuum(model);
    BOOST_TEST_REQUIRE(outcome.status == "converged", outcome.message);
    for (const ContinuumStep& step : outcome.steps) {
        const oracle::ElasticaTip tip = oracle::elastica_tip(step.load_factor);
        const Vec3 u = step.points[1].displacement / L;
        const double angle =
            std::atan2(-step.points[1].rotation(0, 2), step.points[1].rotation(0, 0));
        BOOST_TEST_MESSAGE("elastica α = " << step.load_factor
                                           << ": Δw/L = " << u.z() - tip.deflection
                                           << ", Δu/L = " << -u.x() - tip.shortening);
        BOOST_TEST(std::abs(u.z() - tip.deflection) < kExact);
        BOOST_TEST(std::abs(-u.x() - tip.shortening) < kExact);
        BOOST_TEST(std::abs(u.y()) < kExact);
        BOOST_TEST(std::abs(std::abs(angle) - tip.angle) < kExact);
    }
}

BOOST_AUTO_TEST_CASE(unsupported_models_are_refused_with_a_reason) {
    const Mat6 C = test::diagonal_compliance(Vec6::Ones());
    Model two_members =
        test::cantilever(Vec3(1, 0, 0), C, Vec3(0, 0, 1), Vec3::Zero(), LoadFrame::dead, {1.0});
    two_members.members.push_back(two_members.members.front());
    const ContinuumOutcome outcome = solve_continuum(two_members);
    BOOST_TEST(outcome.status == "error");
    BOOST_TEST(outcome.message.find("one member") != std::string::npos);
    Model off_line =
        test::cantilever(Vec3(1, 0, 0), C, Vec3(0, 0, 1), Vec3::Zero(), LoadFrame::dead, {1.0});
    off_line.points.push_back({"elsewhere", Vec3(0.5, 0.5, 0.0)});
    BOOST_TEST(solve_continuum(off_line).status == "error");
}

BOOST_AUTO_TEST_CASE(an_unreachable_load_reports_diverged_with_the_load_factor) {
    // PL²/EI = 2000 is beyond simple shooting (sensitivity ~e^√α, docs §5): with three cuts
    // allowed the solver must stop and say where, not return a wrong equilibrium.
    const Mat6 C = test::diagonal_compliance((Vec6() << 0, 0, 0, 1.0, 1.0, 1.0).finished());
    const Model model =
        test::cantilever(Vec3(1, 0, 0), C, Vec3(0, 0, 1), Vec3::Zero(), LoadFrame::dead, {2000.0});
    ContinuumOptions options;
    options.max_step_cuts = 3;
    options.max_iterations = 10;
    const ContinuumOutcome outcome = solve_continuum(model, options);
    BOOST_TEST(outcome.status == "diverged");
    BOOST_TEST(outcome.steps.empty());
    BOOST_TEST(outcome.message.find("from load factor 0") != std::string::npos, outcome.message);
}

BOOST_AUTO_TEST_SUITE_END()
