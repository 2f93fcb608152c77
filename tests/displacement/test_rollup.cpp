// Roll-up (benchmarks.md §1; seed 002 Example 1): tip displacement against the exact solution.
#include <boost/test/unit_test.hpp>
#include <cstdio>

#include "core/static_driver.hpp"
#include "formulations/displacement/displacement_statics.hpp"
#include "models.hpp"

using namespace rotbeam;
using Statics = form::DisplacementStatics<param::Quaternion>;

namespace {

// Solves the roll-up to each λ in `lambdas` (one load step each) and returns the largest tip
// error ‖Δu‖/L over them; -1 when the driver does not converge.
double rollup_error(int elements, int order, const std::vector<double>& lambdas, int substeps) {
    Model m = test::rollup(elements, order);
    Statics problem(m);
    NewtonSettings s;
    s.substeps = substeps;
    double worst = 0.0;
    const int tip = 1;
    const StaticOutcome out = run_static(problem, lambdas, s, [&](const StepRecord& r) {
        const Vec3 u = problem.point_state(tip).displacement;
        worst = std::max(worst, (u - test::rollup_exact_tip(r.load_factor)).norm() / test::kRollupL);
    });
    if (out.status != SolveStatus::converged) return -1.0;
    return worst;
}

}  // namespace
