// The precessing helix (docs/benchmarks.md §6): no closed form, so the checks are path properties —
// continuity along 160 load steps, independence of the step size, and dead ≠ follower.
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <sstream>
#include <string>

#include "continuum_models.hpp"
#include "core/continuum/continuum.hpp"
#include "core/so3.hpp"
#include "tests/cases/catalog_model.hpp"

using namespace rotbeam;

namespace {

constexpr double kL = 10.0;

// cases/helix-precessing.yaml: EI₂ = 100, EI₃ = 200, GJ = 50, EA = GA₂ = GA₃ = 1e6; tip moment
// κ EI₂ n, n = (0.6, 0, 0.8); the load factor is κL, here reported at `steps` equal steps to 4π
// (the catalog reports 4 of its 160) with the load's frame by override.
ContinuumOutcome precessing(LoadFrame frame, int steps) {
    std::ostringstream factors;
    factors.precision(17);
    factors << "analysis.load_factors=[";
    for (int i = 1; i <= steps; ++i) factors << (i > 1 ? ", " : "") << i * 4.0 * kPi / steps;
    factors << "]";
    const Model model = test::catalog_model(
        "helix-precessing",
        {factors.str(), "analysis.substeps=1",
         "loads.tip-moment.frame=" + std::string(frame == LoadFrame::dead ? "dead" : "follower")});
    BOOST_TEST_REQUIRE(model.analysis.statics.load_factors.size() == static_cast<size_t>(steps));
    return solve_continuum(model);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(continuum_precessing_helix)

BOOST_AUTO_TEST_CASE(path_of_160_steps_is_continuous_and_step_size_independent) {
    for (LoadFrame frame : {LoadFrame::dead, LoadFrame::follower}) {
        const ContinuumOutcome path = precessing(frame, 160);
        BOOST_TEST_REQUIRE(path.status == "converged", path.message);
        BOOST_TEST_REQUIRE(path.steps.size() == 160u);
        // A smooth path sampled with a uniform step h has second differences h²|u''| much
        // smaller than its first differences h|u'|; a jump to another branch makes one second
        // difference as large as the jump. Measured ratios are 0.05 (dead) and 0.1 (follower).
        double max_first = 0.0, max_second = 0.0, max_turn = 0.0;
        for (std::size_t i = 1; i < path.steps.size(); ++i) {
            const PointState& a = path.steps[i - 1].points[1];
            const PointState& b = path.steps[i].points[1];
            max_first = std::max(max_first, (b.displacement - a.displacement).norm());
            max_turn = std::max(max_turn, so3::rotation_angle(b.rotation * a.rotation.transpose()));
            if (i < 2) continue;
            const Vec3 d2 =
                b.displacement - 2.0 * a.displacement + path.steps[i - 2].points[1].displacement;
            max_second = std::max(max_second, d2.norm());
        }
        BOOST_TEST_MESSAGE("precessing helix " << (frame == LoadFrame::dead ? "dead" : "follower")
                                               << ": max |Δu| = " << max_first
                                               << ", max |Δ²u| = " << max_second
                                               << ", max tip turn per step = " << max_turn);
        BOOST_TEST(max_second < 0.25 * max_first);
        // The tip turns by about Δ(κL) = π/40 per step (exactly that for the isotropic helix);
        // three times that bounds every step of a continuous path.
        BOOST_TEST(max_turn < 3.0 * kPi / 40.0);
        // Half the step (320 steps) reaches the same equilibrium at κL = 4π: the path followed
        // does not depend on the step size.
        const ContinuumOutcome fine = precessing(frame, 320);
        BOOST_TEST_REQUIRE(fine.status == "converged", fine.message);
        const PointState& coarse_tip = path.steps.back().points[1];
        const PointState& fine_tip = fine.steps.back().points[1];
        BOOST_TEST((coarse_tip.displacement - fine_tip.displacement).norm() < 1e-9 * kL);
        BOOST_TEST((coarse_tip.rotation - fine_tip.rotation).norm() < 1e-9);
    }
}

BOOST_AUTO_TEST_CASE(dead_and_follower_moments_give_different_answers) {
    // Unlike the isotropic helix (§5), the anisotropic section makes the rotation axis precess,
    // so R(L) n ≠ n and the follower moment differs from the dead one.
    const ContinuumOutcome dead = precessing(LoadFrame::dead, 40);
    const ContinuumOutcome follower = precessing(LoadFrame::follower, 40);
    BOOST_TEST_REQUIRE(dead.status == "converged", dead.message);
    BOOST_TEST_REQUIRE(follower.status == "converged", follower.message);
    for (int i : {9, 19, 39}) {  // κL = π, 2π, 4π
        const double gap =
            (dead.steps[i].points[1].displacement - follower.steps[i].points[1].displacement)
                .norm();
        BOOST_TEST_MESSAGE("κL = " << dead.steps[i].load_factor
                                   << ": |u_dead − u_follower| = " << gap);
        BOOST_TEST(gap > 0.1 * kL);
    }
}

BOOST_AUTO_TEST_SUITE_END()
