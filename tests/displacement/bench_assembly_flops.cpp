// The assembly against the machine's floating-point peak (the fraction of a
// flop/bandwidth estimate the assembly reaches). Times one residual + Jacobian evaluation —
// assembly only, no linear solve — of the roll-up's statics at a deformed state (λ = 0.5 reached
// first): the displacement formulation on one element of order 14 and on 16 linear elements, and
// the mixed formulation on 16 and 256 elements. Median thread CPU time of many evaluations.
//
// Flops (displacement): counted from the kernels of displacement_statics_assembly.hpp, per
// quadrature point, only the two products that grow with the element's size — the node maps
// D_b = [C dN_b | C K_b + O A_b] and E_b = [Pu dN_b | Pk K_b + Qp A_b] (6×3·3×3 and 3×3·3×3
// products: 324 flops per node), and the node-pair blocks w dN_a D_b + w N_a E_b scattered into J
// (110 flops per pair of free nodes). The strain, the section rotation, the stiffness blocks and
// the parameterization's maps are left out, so the count and the rate are lower bounds.
// Peak: plain x86-64 (SSE2, the build's target), one 2-wide add and one 2-wide multiply per cycle
// = 4 flops per cycle at the clock measured by a chain of dependent adds. The mixed element (a few
// 3×3 products per element, docs/mixed-formulation.md) has no such count: its rate is given per
// element and per Jacobian entry written. A benchmark, not a test: built, not registered with
// CTest.
//
// Usage: bench_assembly_flops [CPU seconds per row, default 0.5; at least 21 evaluations]
#include <time.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "core/static_driver.hpp"
#include "formulations/displacement/displacement_statics.hpp"
#include "formulations/mixed/mixed_statics_of.hpp"
#include "parameterizations/quaternion.hpp"
#include "parameterizations/rotation_vector.hpp"
#include "tests/displacement/models.hpp"

using namespace rotbeam;

namespace {

double thread_cpu_seconds() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

// The clock /proc/cpuinfo reports [GHz] (the first core's "cpu MHz"); 0 when unreadable. Under
// the hypervisor this is the nominal TSC rate, not the clock the core runs at.
double nominal_ghz() {
    std::ifstream in("/proc/cpuinfo");
    for (std::string line; std::getline(in, line);) {
        if (line.rfind("cpu MHz", 0) == 0) {
            return std::atof(line.c_str() + line.find(':') + 1) / 1e3;
        }
    }
    return 0.0;
}

// The clock the core runs at [GHz], measured: a chain of dependent integer adds retires one add
// per cycle. Median of 5 runs of 8e8 adds (the VM exposes no cycle counter).
double measured_ghz() {
    std::vector<double> ghz;
    for (int rep = 0; rep < 5; ++rep) {
        constexpr long kIterations = 100000000;
        long x = 0;
        const double start = thread_cpu_seconds();
        for (long i = 0; i < kIterations; ++i) {
            __asm__ volatile(
                "add $1, %0\n\tadd $1, %0\n\tadd $1, %0\n\tadd $1, %0\n\t"
                "add $1, %0\n\tadd $1, %0\n\tadd $1, %0\n\tadd $1, %0"
                : "+r"(x));
        }
        ghz.push_back(8.0 * kIterations / (thread_cpu_seconds() - start) * 1e-9);
    }
    std::nth_element(ghz.begin(), ghz.begin() + 2, ghz.end());
    return ghz[2];
}

double g_budget_seconds = 0.5;

// Median CPU seconds of one evaluate(r, &J), over as many evaluations as fit in the budget (≥ 21).
template <class Problem>
double seconds_per_evaluation(Problem& problem) {
    const StaticOutcome out = run_static(problem, {0.5}, NewtonSettings{}, nullptr);
    if (!has_solution(out.status)) std::printf("  (static state: %s)\n", out.message.c_str());
    VecX r;
    SparseMatrix J;
    problem.evaluate(r, &J);
    std::vector<double> t;
    for (double spent = 0.0; t.size() < 21 || (spent < g_budget_seconds && t.size() < 100000);) {
        const double start = thread_cpu_seconds();
        problem.evaluate(r, &J);
        t.push_back(thread_cpu_seconds() - start);
        spent += t.back();
    }
    std::nth_element(t.begin(), t.begin() + static_cast<long>(t.size() / 2), t.end());
    return t[t.size() / 2];
}

// The size-dependent flops of one Jacobian evaluation (see the file comment).
double displacement_flops(const form::Mesh& mesh) {
    double flops = 0.0;
    for (const form::MeshElement& e : mesh.elements) {
        double free = 0.0;
        for (int node : e.nodes) free += mesh.nodes[node].dof >= 0 ? 1.0 : 0.0;
        const double nn = static_cast<double>(e.nodes.size());
        flops += static_cast<double>(e.qp.size()) * (324.0 * nn + 110.0 * free * free);
    }
    return flops;
}

void displacement_row(int elements, int order, double peak) {
    form::DisplacementStatics<param::Quaternion> problem(test::rollup(elements, order));
    const double s = seconds_per_evaluation(problem);
    const double flops = displacement_flops(problem.mesh());
    std::printf("displacement/quaternion %3d x p%-2d %6d %12.2f %12.0f %10.2f %8.1f%%\n", elements,
                order, problem.size(), s * 1e6, flops, flops / s * 1e-9,
                peak > 0.0 ? 100.0 * flops / s / peak : 0.0);
}

template <class P>
void mixed_row(const char* name, int elements) {
    form::MixedStaticsOf<P> problem(test::rollup(elements, 1));  // the same roll-up model
    const double s = seconds_per_evaluation(problem);
    VecX r;
    SparseMatrix J;
    problem.evaluate(r, &J);
    std::printf(
        "mixed/%-17s %3d x p1  %6d %12.2f   %.3f µs per element, %.2f ns per Jacobian entry "
        "(%ld entries)\n",
        name, elements, problem.size(), s * 1e6, s * 1e6 / elements,
        s * 1e9 / static_cast<double>(J.nonZeros()), static_cast<long>(J.nonZeros()));
}

}  // namespace

int main(int argc, char** argv) {
    if (argc > 1) g_budget_seconds = std::atof(argv[1]);
    const double ghz = measured_ghz();
    const double peak = 4.0 * ghz * 1e9;  // SSE2: 2-wide add + 2-wide multiply per cycle
    std::printf(
        "clock %.2f GHz measured (nominal %.2f GHz, /proc/cpuinfo); SSE2 peak %.1f GFLOP/s "
        "per core\n",
        ghz, nominal_ghz(), peak * 1e-9);
    std::printf("%-32s %6s %12s %12s %10s %9s\n", "formulation / mesh", "dofs", "µs/eval.",
                "flops/eval.", "GFLOP/s", "of peak");
    displacement_row(1, 14, peak);
    displacement_row(2, 10, peak);
    displacement_row(16, 1, peak);
    displacement_row(256, 1, peak);
    mixed_row<param::RotationVector>("rotation-vector", 16);
    mixed_row<param::RotationVector>("rotation-vector", 256);
    return 0;
}
