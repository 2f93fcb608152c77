// Seed 002 Example 1, Table I (docs/benchmarks.md §1): 16-element roll-up with Wiener–Milenković
// and Rodrigues parameters against the paper's GEBT columns, and the truthful stop of each
// parameterization past the load the 16-element equations can carry (λ* ≈ 0.937 Rodrigues,
// ≈ 1.874 WM).
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <vector>

#include "core/static_driver.hpp"
#include "formulations/mixed/mixed_statics.hpp"
#include "parameterizations/rodrigues.hpp"
#include "parameterizations/wiener_milenkovic.hpp"
#include "tests/mixed/models.hpp"

using namespace rotbeam;

namespace {

struct TableRow {
    double lambda;
    double u1, u3;  // GEBT tip displacement, 4 decimals
    int iterations;
};

// Seed 002 Table I, GEBT columns (docs/benchmarks.md §1); the gated rows only.
const std::vector<TableRow> kWienerMilenkovic = {{0.4, -2.9161, 6.6004, 9},
                                                 {0.8, -9.1946, 8.6455, 14},
                                                 {1.0, -12.0062, 7.6466, 14},
                                                 {1.2, -13.8800, 5.7576, 19},
                                                 {1.6, -14.2403, 1.6287, 25}};
const std::vector<TableRow> kRodrigues = {{0.4, -2.9175, 6.6016, 9}, {0.8, -9.2220, 8.6333, 15}};

NewtonSettings paper_settings() {
    NewtonSettings s;
    s.residual_tolerance = 1e-12;  // the paper's Newton tolerance on the residual
    s.increment_tolerance = 1e-10;
    s.max_iterations = 100;
    return s;
}

template <class P>
void check_table(const std::vector<TableRow>& rows) {
    for (const TableRow& row : rows) {
        // Each λ in one load step from the unloaded state (as Table I's iteration counts read).
        form::MixedStatics<P> problem(test::rollup_model(16));
        const StaticOutcome out = run_static(problem, {row.lambda}, paper_settings(), nullptr);
        BOOST_TEST_REQUIRE((out.status == SolveStatus::converged));
        const Vec3 u = problem.point_state(1).displacement;
        BOOST_TEST_MESSAGE(P::kName << " λ = " << row.lambda << ": u1 = " << u[0]
                                    << ", u3 = " << u[2] << " (paper " << row.u1 << ", " << row.u3
                                    << "), " << out.steps.back().newton_iterations
                                    << " iterations (paper " << row.iterations << ")");
        // ±0.5 in the last printed digit (1e-4), plus 1e-9 for the comparison itself.
        BOOST_TEST(std::abs(u[0] - row.u1) <= 0.5e-4 + 1e-9);
        BOOST_TEST(std::abs(u[2] - row.u3) <= 0.5e-4 + 1e-9);
        BOOST_TEST(std::abs(u[1]) < 1e-12);
    }
}

// Past λ* the continuation stops with a non-converged status and leaves the last converged state
// between the last solvable and the first unsolvable tabulated load.
template <class P>
void check_stop(double solvable, double unsolvable) {
    form::MixedStatics<P> problem(test::rollup_model(16));
    NewtonSettings s = paper_settings();
    s.max_iterations = 50;
    s.max_step_cuts = 8;
    const StaticOutcome out = run_static(problem, {solvable, unsolvable}, s, nullptr);
    BOOST_TEST_MESSAGE(P::kName << ": " << out.status << " after λ = "
                                << out.last_converged_load_factor << ": " << out.message);
    BOOST_TEST((out.status == SolveStatus::diverged || out.status == SolveStatus::singular));
    BOOST_TEST(out.last_converged_load_factor >= solvable);
    BOOST_TEST(out.last_converged_load_factor < unsolvable);
    BOOST_TEST(out.steps.size() == 1u);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(mixed_table_one)

BOOST_AUTO_TEST_CASE(wiener_milenkovic_16_elements_reproduce_table_one) {
    check_table<param::WienerMilenkovic>(kWienerMilenkovic);
}

BOOST_AUTO_TEST_CASE(rodrigues_16_elements_reproduce_table_one) {
    check_table<param::Rodrigues>(kRodrigues);
}

BOOST_AUTO_TEST_CASE(rodrigues_stops_truthfully_between_0p8_and_1p0) {
    check_stop<param::Rodrigues>(0.8, 1.0);
}

BOOST_AUTO_TEST_CASE(wiener_milenkovic_stops_truthfully_between_1p6_and_1p96) {
    check_stop<param::WienerMilenkovic>(1.6, 1.96);
}

BOOST_AUTO_TEST_SUITE_END()
