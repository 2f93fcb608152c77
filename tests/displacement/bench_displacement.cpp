// Cost of one Newton iteration of the displacement statics (issue 5 point 8): residual +
// Jacobian assembly, sparse LU factorization with the symbolic analysis reused, and the solve, on
// the roll-up at a deformed state (λ = 0.5 reached first), for 16 … 8192 linear elements and
// 1 … 256 elements of order 8 (issue 13 item 4). Prints the median time per iteration, the fitted
// log-log slope of time against unknowns (linear cost: 1) and the peak resident memory after each
// size.
// A benchmark, not a test: built, not registered with CTest.
#include <sys/resource.h>

#include <Eigen/SparseLU>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

#include "core/static_driver.hpp"
#include "formulations/displacement/displacement_statics.hpp"
#include "parameterizations/quaternion.hpp"
#include "tests/displacement/models.hpp"

using namespace rotbeam;

namespace {

double peak_rss_mb() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return static_cast<double>(u.ru_maxrss) / 1024.0;
}

// Median seconds of one iteration (evaluate with Jacobian, factorize, solve).
double seconds_per_iteration(int elements, int order, int& unknowns) {
    form::DisplacementStatics<param::Quaternion> problem(test::rollup(elements, order));
    const StaticOutcome out = run_static(problem, {0.5}, NewtonSettings{}, [](const StepRecord&) {});
    if (out.status != SolveStatus::converged) std::printf("  (static state: %s)\n", out.message.c_str());
    unknowns = problem.size();
    VecX r, dx;
    SparseMatrix J;
    Eigen::SparseLU<SparseMatrix, Eigen::COLAMDOrdering<int>> lu;
    problem.evaluate(r, &J);
    lu.analyzePattern(J);
    const int repeats = std::max(5, std::min(200, 200000 / unknowns));
    std::vector<double> t;
    for (int k = 0; k < repeats; ++k) {
        const auto start = std::chrono::steady_clock::now();
        problem.evaluate(r, &J);
        lu.factorize(J);
        dx = lu.solve(r);
        t.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
    std::nth_element(t.begin(), t.begin() + static_cast<long>(t.size() / 2), t.end());
    return t[t.size() / 2];
}

void sweep(int order, const std::vector<int>& elements) {
    std::printf("\norder %d\n%10s %10s %16s %14s\n", order, "elements", "unknowns",
                "s/iteration", "peak RSS [MB]");
    std::vector<double> lx, ly;
    for (int n : elements) {
        int unknowns = 0;
        const double s = seconds_per_iteration(n, order, unknowns);
        std::printf("%10d %10d %16.3e %14.1f\n", n, unknowns, s, peak_rss_mb());
        lx.push_back(std::log(unknowns));
        ly.push_back(std::log(s));
    }
    // Least-squares slope over the sizes with at least 500 unknowns (below, fixed costs dominate).
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    int m = 0;
    for (size_t i = 0; i < lx.size(); ++i) {
        if (std::exp(lx[i]) < 500) continue;
        sx += lx[i]; sy += ly[i]; sxx += lx[i] * lx[i]; sxy += lx[i] * ly[i]; ++m;
    }
    std::printf("log-log slope of time per iteration vs unknowns (≥ 500 unknowns): %.3f\n",
                (m * sxy - sx * sy) / (m * sxx - sx * sx));
}

}  // namespace

int main() {
    sweep(1, {16, 32, 64, 128, 256, 512, 1024, 2048, 4096, 8192});
    sweep(8, {1, 2, 4, 8, 16, 32, 64, 128, 256});
    return 0;
}
