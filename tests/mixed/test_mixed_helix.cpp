// Mixed statics' reach on the helices of docs/benchmarks.md §5 (isotropic, exact oracle) and §6
// (precessing: anisotropic section, the rotation axis varies along the beam; continuum
// reference), κL to 4π at 256 elements, for every combination.
#include <algorithm>
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <vector>

#include "core/continuum/continuum.hpp"
#include "core/oracles/helix.hpp"
#include "core/static_driver.hpp"
#include "formulations/mixed/mixed_statics_of.hpp"
#include "parameterizations/quaternion.hpp"
#include "parameterizations/rodrigues.hpp"
#include "parameterizations/rotation_vector.hpp"
#include "parameterizations/wiener_milenkovic.hpp"
#include "parameterizations/wiener_milenkovic_continuous.hpp"
#include "tests/mixed/models.hpp"

using namespace rotbeam;

namespace {

constexpr double kHelixLength = 10.0;
constexpr int kSteps = 64;  // κL = 4π in steps of π/16 (the continuum reference: 0.5 rad turns)

// cases/helix.yaml (isotropic, EI = GJ = 100) or cases/helix-precessing.yaml (EI2 = 100,
// EI3 = 200, GJ = 50): clamped root, dead tip moment κL·(6, 0, 8) at load factor κL.
Model helix_model(int elements, bool precessing) {
    Model m;
    m.points = {{"root", Vec3::Zero()}, {"tip", Vec3(kHelixLength, 0, 0)}};
    const Vec6 k = precessing ? (Vec6() << 1e6, 1e6, 1e6, 50, 100, 200).finished()
                              : (Vec6() << 1e4, 1e4, 1e4, 100, 100, 100).finished();
    m.members = {test::member("beam", 0, 1, test::diagonal_section(k), elements)};
    m.constraints = {Constraint{0, Constraint::Kind::clamped, Vec3::Zero(), Vec3::Zero(), {}}};
    PointLoad load;
    load.point = 1;
    load.moment = Vec3(6, 0, 8);
    m.point_loads = {load};
    return m;
}

std::vector<double> load_factors() {
    std::vector<double> f;
    for (int k = 1; k <= kSteps; ++k) f.push_back(4.0 * kPi * k / kSteps);
    return f;
}

// Reference tip displacements at every load factor: the exact helix (κ = κL/L about n) or the
// continuum shooting solver.
std::vector<Vec3> reference_tips(bool precessing) {
    std::vector<Vec3> tips;
    if (!precessing) {
        for (double f : load_factors()) {
            tips.push_back(oracle::helix_state(f / kHelixLength, Vec3(0.6, 0, 0.8), kHelixLength)
                               .displacement);
        }
        return tips;
    }
    Model m = helix_model(1, true);
    m.analysis.statics.load_factors = load_factors();
    const ContinuumOutcome ref = solve_continuum(m);
    BOOST_TEST_REQUIRE(ref.status == "converged");
    for (const ContinuumStep& s : ref.steps) tips.push_back(s.points[1].displacement);
    return tips;
}

struct HelixReach {
    SolveStatus status = SolveStatus::converged;
    double last = 0.0;
    double worst_error = 0.0;
};

template <class P>
HelixReach helix_reach(bool precessing, const std::vector<Vec3>& reference, int elements = 256) {
    form::MixedStaticsOf<P> problem(helix_model(elements, precessing));
    NewtonSettings s;
    s.max_iterations = 60;
    s.max_step_cuts = 8;
    HelixReach r;
    int k = 0;
    const StaticOutcome out = run_static(problem, load_factors(), s, [&](const StepRecord& step) {
        const Vec3 u = problem.point_state(1).displacement;
        const double e = (u - reference[static_cast<std::size_t>(k++)]).norm() / kHelixLength;
        r.worst_error = std::max(r.worst_error, e);
        (void)step;
    });
    r.status = out.status;
    r.last = out.last_converged_load_factor;
    BOOST_TEST_MESSAGE(P::kName << (precessing ? ", precessing helix" : ", helix")
                                << ", N = " << elements << ": " << out.status << ", κL reached "
                                << r.last << " (of 4π = " << 4 * kPi
                                << "), worst ‖Δu‖/L = " << r.worst_error << "; " << out.message);
    return r;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(mixed_helix_reach)

// The isotropic helix (exact oracle): every combination either reaches κL = 4π within 1e-4
// (rotation vector 9.8e-6, continuous WM 3.0e-5, quaternion 4.2e-5) or stops with a truthful
// status at its singular angle (plain WM at φ = 2π, Rodrigues at π: the tip rotation is κL here)
// — never a converged step off the oracle.
BOOST_AUTO_TEST_CASE(helix_reach_of_every_combination_at_256_elements) {
    const std::vector<Vec3> ref = reference_tips(false);
    const HelixReach rv = helix_reach<param::RotationVector>(false, ref);
    const HelixReach wm = helix_reach<param::WienerMilenkovic>(false, ref);
    const HelixReach wc = helix_reach<param::WienerMilenkovicContinuous>(false, ref);
    const HelixReach ro = helix_reach<param::Rodrigues>(false, ref);
    const HelixReach qu = helix_reach<param::Quaternion>(false, ref);
    for (const HelixReach* r : {&rv, &wm, &wc, &ro, &qu}) BOOST_TEST(r->worst_error <= 1e-4);
    // Near 4π the rotation vector's and continuous WM's tangents are nearly singular (|p| → 4π):
    // the residual reaches its round-off floor (≈ 1e-14) while the Newton correction stays above
    // 1e-12 (≤ 3.7e-10, measured), so some steps end stalled at round-off: a solution with that
    // stated error bound, and no step off the oracle (asserted above).
    BOOST_TEST((has_solution(rv.status) && has_solution(wc.status)));
    BOOST_TEST((qu.status == SolveStatus::converged));
    BOOST_TEST((wm.status != SolveStatus::converged && wm.last > 6.0 && wm.last < 2.0 * kPi));
    BOOST_TEST((ro.status != SolveStatus::converged && ro.last > 3.0 && ro.last < kPi));
}

// The precessing helix (continuum reference). Every combination with a chart past π reaches 4π,
// but at 256 elements the error is 5.1e-4 (rotation vector), 5.4e-4 (quaternion), 5.5e-4 (WM),
// 5.8e-4 (continuous WM): this is the second-order discretization error of the mixed element on
// this case, not a wrong branch — halving the mesh multiplies it by 4 (asserted below for the
// rotation vector; the same order 2.00 is measured in tests/agreement at κL = π). A 1e-4 target
// at 256 elements therefore cannot hold here for any parameterization; ~560 elements would be
// needed. Rodrigues stops truthfully before its singular angle π of the element rotation.
BOOST_AUTO_TEST_CASE(precessing_helix_reach_of_every_combination_at_256_elements) {
    const std::vector<Vec3> ref = reference_tips(true);
    const HelixReach coarse = helix_reach<param::RotationVector>(true, ref, 128);
    const HelixReach rv = helix_reach<param::RotationVector>(true, ref);
    const HelixReach wm = helix_reach<param::WienerMilenkovic>(true, ref);
    const HelixReach wc = helix_reach<param::WienerMilenkovicContinuous>(true, ref);
    const HelixReach ro = helix_reach<param::Rodrigues>(true, ref);
    const HelixReach qu = helix_reach<param::Quaternion>(true, ref);
    BOOST_TEST((coarse.status == SolveStatus::converged));
    for (const HelixReach* r : {&rv, &wm, &wc, &qu}) {
        BOOST_TEST((r->status == SolveStatus::converged));
        BOOST_TEST(r->worst_error <= 1e-3);
    }
    const double ratio = coarse.worst_error / rv.worst_error;
    BOOST_TEST_MESSAGE("error ratio 128/256 elements: " << ratio << " (order " << std::log2(ratio)
                                                        << ")");
    BOOST_TEST(std::abs(std::log2(ratio) - 2.0) < 0.1);
    // Rodrigues: tan(φ/2) grows without bound as the largest element rotation nears π (3.1316 rad
    // at κL = 2.9529, measured); Newton stops converging there (no state is refused, so the status
    // is `diverged`, not `singular`). The continuation must carry it to within 0.1 of that wall
    // (κL > 2.9: a regression that stops early fails) and not to κL = π, past which the element
    // rotation would exceed π; every step it reports stays on the reference.
    BOOST_TEST((ro.status == SolveStatus::diverged));
    BOOST_TEST(ro.last > 2.9);
    BOOST_TEST(ro.last < kPi);
    BOOST_TEST(ro.worst_error <= 1e-4);
}

BOOST_AUTO_TEST_SUITE_END()
