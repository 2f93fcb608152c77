// The measurement shared by the per-iteration scaling benchmarks (used by
// tests/displacement/bench_displacement.cpp, tests/mixed/bench_mixed.cpp): one Newton iteration of
// a static problem at a converged deformed state, timed as the driver performs it — residual +
// Jacobian assembly (`evaluate`), factorization by the driver's own SparseLUSolver (Eigen SparseLU
// with COLAMD, the symbolic analysis made once per pattern) and the solve — in CPU time of the
// calling thread, with the parts split, the LU fill, the number of symbolic analyses the
// repetitions made (1: the analysis is reused) and the size's own peak resident memory.
// Header-only: benchmarks, not tests (built, not registered with CTest).
#pragma once

#include <malloc.h>
#include <time.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "core/nonlinear_system.hpp"
#include "core/sparse_lu.hpp"

namespace rotbeam::scaling {

// Returns freed heap to the system, then resets the peak resident set size to the current one
// (Linux ≥ 4.0); false where unsupported.
inline bool reset_peak_memory() {
    malloc_trim(0);
    std::ofstream f("/proc/self/clear_refs");
    f << "5";
    return static_cast<bool>(f);
}

// VmHWM of /proc/self/status in MB (−1 when unreadable).
inline double peak_memory_mb() {
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
inline double thread_cpu_seconds() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

inline double median(std::vector<double> t) {
    std::nth_element(t.begin(), t.begin() + static_cast<long>(t.size() / 2), t.end());
    return t[t.size() / 2];
}

struct Row {
    int elements = 0;
    int unknowns = 0;
    double nonzeros = 0.0;       // nnz(J)
    double seconds = 0.0;        // median CPU time of one iteration
    double wall = 0.0;           // median wall time of one iteration
    double assembly = 0.0;       // median CPU time of its evaluate() part
    double factorization = 0.0;  // median CPU time of its factorize() part
    double fill = 0.0;           // nnz(L + U) / nnz(J): a load-independent witness of linear cost
    int analyses = 0;            // symbolic analyses over all repetitions (1: reused)
    int repeats = 0;
    double peak_mb = 0.0;  // VmHWM after the size (reset before it)
};

// Times `repeats` iterations (repeats scaled to ~2e5 unknowns in total, 5 … 200) at the problem's
// current state; the first factorization (with the analysis) is made before the timed ones.
inline Row time_iterations(StaticProblem& problem, int elements) {
    Row row;
    row.elements = elements;
    row.unknowns = problem.size();
    VecX r, dx;
    SparseMatrix J;
    SparseLUSolver lu;
    problem.evaluate(r, &J);
    lu.factorize(J);
    row.repeats = std::max(5, std::min(200, 200000 / row.unknowns));
    std::vector<double> t, w, a, f;
    for (int k = 0; k < row.repeats; ++k) {
        const auto wall_start = std::chrono::steady_clock::now();
        const double start = thread_cpu_seconds();
        problem.evaluate(r, &J);
        const double assembled = thread_cpu_seconds();
        lu.factorize(J);
        const double factored = thread_cpu_seconds();
        lu.solve(r, dx);
        t.push_back(thread_cpu_seconds() - start);
        a.push_back(assembled - start);
        f.push_back(factored - assembled);
        w.push_back(
            std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count());
    }
    row.seconds = median(t);
    row.wall = median(w);
    row.assembly = median(a);
    row.factorization = median(f);
    row.nonzeros = static_cast<double>(J.nonZeros());
    row.fill = lu.factor_nonzeros() / row.nonzeros;
    row.analyses = lu.symbolic_analyses();
    return row;
}

// Least-squares slope of log(CPU time) against log(unknowns) over the rows with at least
// `min_unknowns` unknowns.
inline double fitted_slope(const std::vector<Row>& rows, int min_unknowns) {
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    int m = 0;
    for (const Row& r : rows) {
        if (r.unknowns < min_unknowns) continue;
        const double x = std::log(r.unknowns), y = std::log(r.seconds);
        sx += x;
        sy += y;
        sxx += x * x;
        sxy += x * y;
        ++m;
    }
    return m < 2 ? std::nan("") : (m * sxy - sx * sy) / (m * sxx - sx * sx);
}

inline void print_header(const char* name) {
    std::printf("\n%s\n%9s %9s %10s %11s %11s %9s %7s %7s %6s %4s %8s\n", name, "elements",
                "unknowns", "nnz(J)", "CPU ms/it.", "wall ms/it.", "CPU us/u", "assem.", "factor",
                "fill", "ana.", "VmHWM MB");
}

inline void print_row(const Row& w, bool reset) {
    std::printf("%9d %9d %10.0f %11.4f %11.4f %9.3f %6.0f%% %6.0f%% %6.2f %4d %8.1f%s\n",
                w.elements, w.unknowns, w.nonzeros, 1e3 * w.seconds, 1e3 * w.wall,
                1e6 * w.seconds / w.unknowns, 100.0 * w.assembly / w.seconds,
                100.0 * w.factorization / w.seconds, w.fill, w.analyses, w.peak_mb,
                reset ? "" : " (process peak: clear_refs unsupported)");
    std::fflush(stdout);
}

// The slope over all sizes swept and the slope where fixed costs no longer dominate.
inline void print_slopes(const std::vector<Row>& rows) {
    std::printf(
        "log-log slope of CPU time per iteration vs unknowns: %.3f over %d … %d "
        "elements, %.3f over ≥ 500 unknowns (linear: 1)\n",
        fitted_slope(rows, 0), rows.front().elements, rows.back().elements,
        fitted_slope(rows, 500));
}

// One sweep: the header, then measure(n) (a Row) for every n of `sizes` with that size's own peak
// memory, then the slopes.
template <class Measure>
void sweep_sizes(const char* name, const std::vector<int>& sizes, Measure measure) {
    print_header(name);
    std::vector<Row> rows;
    for (int n : sizes) {
        const bool reset = reset_peak_memory();
        rows.push_back(measure(n));
        rows.back().peak_mb = peak_memory_mb();
        print_row(rows.back(), reset);
    }
    print_slopes(rows);
}

}  // namespace rotbeam::scaling
