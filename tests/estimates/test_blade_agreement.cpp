// The MH-104 blade (cases/blade-mh104.yaml, docs/benchmarks.md §4) has no published number: its
// verification is the two formulations against each other (docs/suite-reproductions.md, "The two
// formulations on the blade"). Both discretize the same beam: their first twelve natural
// frequencies about the undeformed state agree to ≤ 2.3e-5 relative (displacement 20 × p4 against
// the mixed values extrapolated from 80 and 160 elements at the mixed element's order 2), so the
// two tip histories converge to the same function and the difference of two runs is bounded by
// the sum of their errors.
//
// The runs (Wiener–Milenković, Δt = 1 ms, tip every 5 ms over 0–2 s), each with its own estimate
// (docs/error-estimates.md, Dynamics: space + time at every output time and the history's
// largest):
// - displacement 20 elements × p5, Gauss–Legendre 3 (order 6 in time): estimate p+1 (20 × p6) and
//   Δt/2;
// - mixed 640 elements, Radau IIA 3 (order 5 in the positions): estimate h/2, h/4 (1280, 2560
//   elements) and Δt/2. Its time error at Δt = 1 ms is far below its space error (320 elements at
//   1 and 0.5 ms agree to 4 digits of their difference to the displacement run), and its space
//   error falls at the element's order 2 (measured against the displacement run: tip displacement
//   history 3.3e-3, 8.4e-4, 2.1e-4, 5.5e-5, 1.6e-5 of the amplitude on 320 … 5120 elements, the
//   last near the displacement run's own 9.8e-6; tip rotation 5.0e-2, 1.3e-2, 3.2e-3, 7.9e-4,
//   2.0e-4). 1e-4 needs ≈ 1900 elements for the tip
//   displacement and ≈ 7200 for the rotation (12 min of one core for 5120 elements, without the
//   estimate's 2N and 4N companions): with these finer companions not affordable in a test, so
//   here the mixed run is held to its own finer estimate, 8.4e-4 (displacement) and 1.3e-2
//   (rotation) of the amplitudes (below); test_blade_accuracy.cpp reaches 1e-4 with the coarser
//   companions.
//
// What is asserted, for the tip displacement and the tip rotation, and why:
// - the displacement run's history estimate is ≤ 1e-4 of the history's amplitude, with every
//   estimate reliable: the refined side of the comparison is at the accuracy asked for;
// - the largest difference of the two histories over the output times is at most the sum of the
//   two histories' largest estimated errors (space + time): the agreement "within the combined
//   estimates" of the histories;
// - at every output time the difference is at most 3 × the sum of the two pointwise estimates,
//   the estimates' criterion of an estimator failure (docs/error-estimates.md). Not 1 ×: a
//   pointwise h-estimate is built from |u_h − u_h/2| and |u_h/2 − u_h/4|, which pass near zero at
//   the times where the runs cross while the true error does not; measured 2026-11-29, the sum is
//   exceeded at 42 (displacement) and 26 (rotation) of the 401 output times, by up to 2.26× and
//   2.40×; the mixed estimate says `reliable: false` at 14 pointwise quantities (observed order
//   outside 2 ± 0.5 there), which is why its reliability is not asserted.
// Measured 2026-11-29: the mixed run's history estimates 8.36e-4 (displacement) and 1.27e-2
// (rotation) of the amplitudes against differences of 8.39e-4 and 1.27e-2, within the combined
// 8.46e-4 and 1.28e-2; its time part 7.4e-7 and 9.3e-6. Cost: 539–553 s of CPU (label long:
// ctest --preset long -R test_blade_agreement).
#include <algorithm>
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <string>

#include "blade_runs.hpp"

namespace rotbeam {

namespace {

using json = nlohmann::json;
using blade::kQuantities;
using blade::tip_difference;
using blade::tip_estimate;

json estimated_blade(std::vector<std::string> overrides) {
    overrides.insert(overrides.begin(), "analysis.output_interval=0.005");
    return blade::estimated_blade(overrides);
}

}  // namespace

BOOST_AUTO_TEST_CASE(refined_displacement_and_mixed_blade_histories_agree_within_their_estimates) {
    const json d =
        estimated_blade({"discretization.formulation=displacement", "members.blade.elements=20",
                         "discretization.order=5", "analysis.integrator=gauss-legendre-3"});
    const json m =
        estimated_blade({"discretization.formulation=mixed", "members.blade.elements=640",
                         "analysis.integrator=radau-iia-3"});
    BOOST_TEST(d["estimate"]["unreliable"].get<int>() == 0);
    const json& sd = d["steps"];
    const json& sm = m["steps"];
    BOOST_TEST_REQUIRE(sd.size() == sm.size());
    for (int q = 0; q < 2; ++q) {
        const std::string what = kQuantities[q];
        const json& hd = d["estimate"]["history"]["tip"][what];
        const json& hm = m["estimate"]["history"]["tip"][what];
        const double amplitude = hd["amplitude"].get<double>();
        BOOST_TEST(hd["max_error"].get<double>() <= 1e-4 * amplitude,
                   "displacement 20 x p5 GL3, tip " << what << ": estimate "
                                                    << hd["max_error"].get<double>() / amplitude
                                                    << " of the amplitude");
        double largest = 0.0;
        double worst_ratio = 0.0;
        int outside = 0;
        int compared = 0;
        for (std::size_t i = 0; i < sd.size(); ++i) {
            BOOST_TEST_REQUIRE(std::abs(sd[i]["time"].get<double>() - sm[i]["time"].get<double>()) <
                               1e-9);
            const double diff = tip_difference(sd[i], sm[i], q);
            largest = std::max(largest, diff);
            const double ed = tip_estimate(d, i, what);
            const double em = tip_estimate(m, i, what);
            if (ed < 0.0 || em < 0.0) continue;
            ++compared;
            if (diff > ed + em) ++outside;
            if (diff > 0.0) worst_ratio = std::max(worst_ratio, diff / (ed + em));
        }
        const double combined = hd["max_error"].get<double>() + hm["max_error"].get<double>();
        BOOST_TEST_MESSAGE("tip " << what << ": displacement estimate "
                                  << hd["max_error"].get<double>() / amplitude
                                  << " of the amplitude " << amplitude << ", mixed 640 "
                                  << hm["max_error"].get<double>() / amplitude << " (space "
                                  << hm["max_space"].get<double>() / amplitude << ", time "
                                  << hm["max_time"].get<double>() / amplitude
                                  << "); largest difference " << largest / amplitude
                                  << ", combined " << combined / amplitude << "; outside the "
                                  << "pointwise sum at " << outside << " of " << compared
                                  << " output times, worst " << worst_ratio << "x");
        BOOST_TEST(largest <= combined, "tip " << what);
        BOOST_TEST(compared == static_cast<int>(sd.size()), "tip " << what);
        BOOST_TEST(worst_ratio <= 3.0, "tip " << what);
    }
}

}  // namespace rotbeam
