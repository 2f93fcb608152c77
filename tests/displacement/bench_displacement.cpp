// Cost of one Newton iteration of the displacement statics:
// residual + Jacobian assembly, sparse LU factorization with the symbolic analysis reused, and
// the solve (tests/scaling/per_iteration.hpp), on the roll-up at a deformed state (λ = 0.5 reached
// first), for 16 … 8192 linear elements and 1 … 256 elements of order 8. Prints the median CPU
// time per iteration with its split, the LU fill, the analyses made, the fitted log-log slope of
// CPU time against unknowns (linear cost: 1) and each size's own peak resident memory.
// A benchmark, not a test: built, not registered with CTest.
//
// Usage: bench_displacement [largest linear element count, default 8192]
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "core/static_driver.hpp"
#include "formulations/displacement/displacement_statics.hpp"
#include "parameterizations/quaternion.hpp"
#include "tests/displacement/models.hpp"
#include "tests/scaling/per_iteration.hpp"

using namespace rotbeam;

namespace {

scaling::Row seconds_per_iteration(int elements, int order) {
    form::DisplacementStatics<param::Quaternion> problem(test::rollup(elements, order));
    const StaticOutcome out = run_static(problem, {0.5}, NewtonSettings{}, nullptr);
    if (!has_solution(out.status)) {
        std::printf("  (static state: %s)\n", out.message.c_str());
    }
    return scaling::time_iterations(problem, elements);
}

void sweep(int order, const std::vector<int>& elements) {
    char name[64];
    std::snprintf(name, sizeof name, "displacement/quaternion, order %d", order);
    scaling::sweep_sizes(name, elements, [&](int n) { return seconds_per_iteration(n, order); });
}

}  // namespace

int main(int argc, char** argv) {
    const int largest = argc > 1 ? std::atoi(argv[1]) : 8192;
    if (largest < 16) {
        std::fprintf(stderr, "bench_displacement: largest element count must be ≥ 16\n");
        return 2;
    }
    std::vector<int> linear, order8;
    for (int n = 16; n <= largest; n *= 2) linear.push_back(n);
    for (int n = 1; n <= largest / 32; n *= 2) order8.push_back(n);  // same unknowns
    sweep(1, linear);
    sweep(8, order8);
    return 0;
}
