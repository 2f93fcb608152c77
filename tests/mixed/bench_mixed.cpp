// Cost of one Newton iteration of the mixed statics: residual
// + Jacobian assembly, sparse LU factorization with the symbolic analysis reused (the static
// driver's SparseLUSolver), and the solve (tests/scaling/per_iteration.hpp), on the roll-up at a
// deformed state (λ = 0.5 reached first), for 16 … 8192 elements and every parameterization and
// option. Prints the median CPU and wall time per iteration with its split, the LU fill
// nnz(L + U)/nnz(J), the analyses made, the fitted log-log slope of CPU time against unknowns
// (linear cost: 1) and the peak resident memory (VmHWM, reset before each size through
// /proc/self/clear_refs, so each row is that size's own peak). A benchmark, not a test: built,
// not registered with CTest.
//
// Usage: bench_mixed [largest elements, default 8192] [parameterization name: only that one]
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "core/static_driver.hpp"
#include "formulations/mixed/mixed_statics_of.hpp"
#include "parameterizations/quaternion.hpp"
#include "parameterizations/rodrigues.hpp"
#include "parameterizations/rotation_vector.hpp"
#include "parameterizations/wiener_milenkovic.hpp"
#include "parameterizations/wiener_milenkovic_continuous.hpp"
#include "tests/mixed/models.hpp"
#include "tests/scaling/per_iteration.hpp"

using namespace rotbeam;

namespace {

template <class P>
scaling::Row seconds_per_iteration(int elements) {
    form::MixedStaticsOf<P> problem(test::rollup_model(elements));
    const StaticOutcome out = run_static(problem, {0.5}, NewtonSettings{}, nullptr);
    if (out.status != SolveStatus::converged) {
        std::printf("  (static state: %s)\n", out.message.c_str());
    }
    return scaling::time_iterations(problem, elements);
}

template <class P>
void sweep(const char* name, int largest, const char* only) {
    if (only != nullptr && std::strstr(name, only) != name) return;
    std::vector<int> sizes;
    for (int n = 16; n <= largest; n *= 2) sizes.push_back(n);
    scaling::sweep_sizes(name, sizes, [](int n) { return seconds_per_iteration<P>(n); });
}

}  // namespace

int main(int argc, char** argv) {
    const int largest = argc > 1 ? std::atoi(argv[1]) : 8192;
    const char* only = argc > 2 ? argv[2] : nullptr;
    if (largest < 16) {
        std::fprintf(stderr, "bench_mixed: largest element count must be ≥ 16\n");
        return 2;
    }
    sweep<param::Quaternion>("quaternion (13 unknowns per element, 7 per node)", largest, only);
    sweep<param::WienerMilenkovic>("wiener-milenkovic", largest, only);
    sweep<param::WienerMilenkovicContinuous>("wiener-milenkovic, continuous map", largest, only);
    sweep<param::Rodrigues>("rodrigues", largest, only);
    sweep<param::RotationVector>("rotation-vector", largest, only);
    return 0;
}
