// The p+1 estimate where the p-sequence is not spectral (docs/error-estimates.md, "p+1"): on the
// 45° bend (cases/bend-45.yaml) at orders 1 … 4 on 4 … 64 elements, where orders p and p+1 lock
// on coarse meshes and their errors cross on fine ones (order 3 worse than order 2 up to 32
// elements), every tip displacement and rotation estimate that says `reliable` has an effectivity
// (estimated / true error) within [0.5, 2], and no estimate at all is below a third of the true
// error (an estimator failure). The true error is against the continuum reference (core/continuum,
// docs/reference-solutions.md), independent of the finite elements. The runs go through run_case
// and add_run_estimate, the path of `rotbeam run`.
//
// Why [0.5, 2]: a reliable p+1 estimate has passed the decay check d₂ < d₁ / 2; under a geometric
// decay of ratio r ≤ 1/2 its effectivity lies within [1 − r, 1 + r] (quantity_estimate.hpp), and
// [0.5, 2] is the band the effectivity table of docs/error-estimates.md asserts where convergence
// is asymptotic. Why a third: the issue of estimator failures is a true error above 3 × the
// estimate, whether reliable or not (docs/error-estimates.md).
#include <boost/test/unit_test.hpp>
#include <sstream>

#include "cases/loader/case_loader.hpp"
#include "core/so3.hpp"
#include "core/static_driver.hpp"
#include "runs/run_case.hpp"
#include "tests/estimates/tip_states.hpp"

namespace rotbeam {

namespace {

using json = nlohmann::json;

// The continuum reference's verified accuracy is 1.8e-11 (of L in displacement, and in rotation
// angle, docs/reference-solutions.md), and converged runs of this case (8 elements, orders 8 … 10)
// agree with it within 2.3e-11 in and 1.4e-12 rad. 100 × that accuracy: a true error above the
// floor is measured to 1 %. L = 25π in, the arc length.
constexpr double kAccuracy = 1.8e-11;
constexpr double kDisplacementFloor = 100 * kAccuracy * 78.53981633974483;
constexpr double kRotationFloor = 100 * kAccuracy;

struct Tally {
    int reliable = 0;    // reliable estimates above the floor (the band asserted)
    int unreliable = 0;  // not reliable, above the floor (only the failure criterion)
    std::ostringstream table;
};

void check(const std::string& where, const json& q, double true_error, double floor, Tally& t) {
    const double est = q["error"].get<double>();
    const bool reliable = q["reliable"].get<bool>();
    t.table << where << ": true " << true_error << " est " << est << " eff " << est / true_error
            << (reliable ? "" : " (not reliable)") << "\n";
    if (true_error <= floor) return;
    BOOST_TEST(true_error <= 3.0 * est,
               where << ": estimator failure, true " << true_error << " > 3 × " << est);
    if (!reliable) {
        ++t.unreliable;
        return;
    }
    ++t.reliable;
    BOOST_TEST(est >= 0.5 * true_error, where << ": reliable, effectivity " << est / true_error);
    BOOST_TEST(est <= 2.0 * true_error, where << ": reliable, effectivity " << est / true_error);
}

}  // namespace

BOOST_AUTO_TEST_CASE(reliable_p_estimates_on_the_bend_lie_within_the_band) {
    const test::TipStates reference = test::bend_tip_reference();
    const std::string path = std::string(ROTBEAM_SOURCE_DIR) + "/cases/bend-45.yaml";
    Tally t;
    t.table.precision(3);
    for (int elements = 4; elements <= 64; elements *= 2) {
        for (int p = 1; p <= 4; ++p) {
            const RunRequest request{path,
                                     load_case(path,
                                               {"discretization.formulation=displacement",
                                                "discretization.rotation=quaternion",
                                                "members.*.elements=" + std::to_string(elements),
                                                "discretization.order=" + std::to_string(p)},
                                               CaseParts::case_file)};
            json r = run_case(request);
            BOOST_TEST_REQUIRE(has_solution(r["status"].get<std::string>()));
            add_run_estimate(request, r);
            BOOST_TEST_REQUIRE(r["estimate"]["status"] == "estimated");
            for (std::size_t k = 0; k < r["steps"].size(); ++k) {
                const json& step = r["steps"][k];
                const PointState exact = reference(k, step["load_factor"].get<double>());
                const PointState tip = test::point_state_of(step);
                const json& est = step["estimate"]["tip"];
                std::ostringstream where;
                where << elements << " x order " << p << ", P = " << step["load_factor"];
                check(where.str() + " u", est["displacement"],
                      (tip.displacement - exact.displacement).norm(), kDisplacementFloor, t);
                check(where.str() + " rotation", est["rotation"],
                      so3::rotation_angle(tip.rotation.transpose() * exact.rotation),
                      kRotationFloor, t);
            }
        }
    }
    BOOST_TEST_MESSAGE(t.table.str());
    // 5 meshes × 4 orders × 3 loads × 2 quantities = 120, less those below the floors (64
    // elements at order 4); measured 2026-11-26: 69 reliable and 24 not. Fewer reliable points
    // would mean the check marks everything unreliable, which would pass the band vacuously.
    BOOST_TEST(t.reliable >= 60, t.reliable << " reliable estimates checked");
    BOOST_TEST_MESSAGE(t.reliable << " reliable estimates in the band, " << t.unreliable
                                  << " not reliable");
}

}  // namespace rotbeam
