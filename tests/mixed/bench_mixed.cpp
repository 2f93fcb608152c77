// Cost of one Newton iteration of the mixed statics (issue 8 point 6): residual + Jacobian
// assembly, sparse LU factorization with the symbolic analysis reused (the static driver's
// SparseLU/COLAMD), and the solve, on the roll-up at a deformed state (λ = 0.5 reached first), for
// 16 … 8192 elements and every parameterization and option. Prints the median CPU and wall time
// per iteration, the share of assembly, the LU fill nnz(L + U)/nnz(J), the fitted log-log slope
// of CPU time against unknowns (linear cost: 1) and the peak resident memory (VmHWM, reset before
// each size through /proc/self/clear_refs, so each row is that size's own peak). A benchmark, not
// a test: built, not registered with CTest.
//
// Usage: bench_mixed [largest elements, default 8192]
#include <malloc.h>
#include <time.h>

#include <Eigen/SparseLU>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "core/static_driver.hpp"
#include "formulations/mixed/mixed_statics_of.hpp"
#include "formulations/mixed/wm_continuous.hpp"
#include "parameterizations/quaternion.hpp"
#include "parameterizations/rodrigues.hpp"
#include "parameterizations/rotation_vector.hpp"
#include "parameterizations/wiener_milenkovic.hpp"
#include "tests/mixed/models.hpp"

using namespace rotbeam;

namespace {

// Returns freed heap to the system, then resets the peak resident set size to the current one
// (Linux ≥ 4.0); false where unsupported.
bool reset_peak_memory() {
    malloc_trim(0);
    std::ofstream f("/proc/self/clear_refs");
    f << "5";
    return static_cast<bool>(f);
}

// VmHWM of /proc/self/status in MB (−1 when unreadable).
double peak_memory_mb() {
    std::ifstream f("/proc/self/status");
    std::string line;
    while (std::getline(f, line)) {
        if (line.rfind("VmHWM:", 0) == 0) return std::atof(line.c_str() + 6) / 1024.0;
    }
    return -1.0;
}

// CPU seconds of the calling thread: unlike wall time it does not count the time the thread waits
// while other processes run, so sizes whose iteration outlasts a scheduler time slice are not
// penalized on a shared machine (cache pollution by other processes still counts).
double thread_cpu_seconds() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

struct Row {
    int unknowns = 0;
    double seconds = 0.0;   // median CPU time of one iteration
    double wall = 0.0;      // median wall time of one iteration
    double assembly = 0.0;  // median CPU time of its evaluate() part
    double fill = 0.0;      // nnz(L + U) / nnz(J): a load-independent witness of linear cost
};

double median(std::vector<double> t) {
    std::nth_element(t.begin(), t.begin() + static_cast<long>(t.size() / 2), t.end());
    return t[t.size() / 2];
}

// Median seconds of one iteration (evaluate with Jacobian, factorize, solve).
template <class P>
Row seconds_per_iteration(int elements) {
    form::MixedStaticsOf<P> problem(test::rollup_model(elements));
    const StaticOutcome out = run_static(problem, {0.5}, NewtonSettings{}, nullptr);
    if (out.status != SolveStatus::converged) {
        std::printf("  (static state: %s)\n", out.message.c_str());
    }
    Row row;
    row.unknowns = problem.size();
    VecX r, dx;
    SparseMatrix J;
    Eigen::SparseLU<SparseMatrix, Eigen::COLAMDOrdering<int>> lu;
    problem.evaluate(r, &J);
    lu.analyzePattern(J);
    const int repeats = std::max(5, std::min(200, 200000 / row.unknowns));
    std::vector<double> t, w, a;
    for (int k = 0; k < repeats; ++k) {
        const auto wall_start = std::chrono::steady_clock::now();
        const double start = thread_cpu_seconds();
        problem.evaluate(r, &J);
        const double assembled = thread_cpu_seconds();
        lu.factorize(J);
        dx = lu.solve(r);
        t.push_back(thread_cpu_seconds() - start);
        a.push_back(assembled - start);
        w.push_back(
            std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count());
    }
    row.seconds = median(t);
    row.wall = median(w);
    row.assembly = median(a);
    row.fill = static_cast<double>(lu.nnzL() + lu.nnzU()) / static_cast<double>(J.nonZeros());
    return row;
}

// Least-squares slope of log(time) against log(unknowns) over the sizes with ≥ 500 unknowns
// (below, fixed costs dominate).
double fitted_slope(const std::vector<Row>& rows) {
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    int m = 0;
    for (const Row& r : rows) {
        if (r.unknowns < 500) continue;
        const double x = std::log(r.unknowns), y = std::log(r.seconds);
        sx += x;
        sy += y;
        sxx += x * x;
        sxy += x * y;
        ++m;
    }
    return (m * sxy - sx * sy) / (m * sxx - sx * sx);
}

template <class P>
void sweep(const char* name, int largest) {
    std::printf("\n%s\n%10s %10s %14s %14s %10s %8s %12s\n", name, "elements", "unknowns",
                "CPU s/iter.", "wall s/iter.", "assembly", "fill", "VmHWM [MB]");
    std::vector<Row> rows;
    for (int n = 16; n <= largest; n *= 2) {
        const bool reset = reset_peak_memory();
        rows.push_back(seconds_per_iteration<P>(n));
        const Row& w = rows.back();
        std::printf("%10d %10d %14.3e %14.3e %9.0f%% %8.2f %12.1f%s\n", n, w.unknowns, w.seconds,
                    w.wall, 100.0 * w.assembly / w.seconds, w.fill, peak_memory_mb(),
                    reset ? "" : " (process peak: clear_refs unsupported)");
        std::fflush(stdout);
    }
    std::printf("log-log slope of CPU time per iteration vs unknowns (≥ 500 unknowns): %.3f\n",
                fitted_slope(rows));
}

}  // namespace

int main(int argc, char** argv) {
    const int largest = argc > 1 ? std::atoi(argv[1]) : 8192;
    if (largest < 16) {
        std::fprintf(stderr, "bench_mixed: largest element count must be ≥ 16\n");
        return 2;
    }
    sweep<param::Quaternion>("quaternion (13 unknowns per element, 7 per node)", largest);
    sweep<param::WienerMilenkovic>("wiener-milenkovic", largest);
    sweep<param::WienerMilenkovicContinuous>("wiener-milenkovic, continuous map", largest);
    sweep<param::Rodrigues>("rodrigues", largest);
    sweep<param::RotationVector>("rotation-vector", largest);
    return 0;
}
