// Micro-benchmark of the parameterizations: ns per call of R(p), compose,
// H_m(p) and ∂(H_m v)/∂p, median of repeats, and the ratio to the quaternion. Not a test: run
// `bench_rotations [repeats]` on a quiet machine and read the table (docs/parameterizations.md).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include "parameterizations/registry.hpp"

namespace {

using namespace rotbeam;

// Keeps the compiler from discarding a result it cannot see used.
template <class T>
inline void do_not_optimize(const T& value) {
    asm volatile("" : : "g"(&value) : "memory");
}

constexpr int kInputs = 64;     // distinct inputs, cycled, so nothing is constant-folded
constexpr int kCalls = 20000;  // calls per repeat: ~1 ms, shorter than a scheduler slice

template <class F>
double median_ns_per_call(const F& call, int repeats) {
    std::vector<double> times;
    for (int r = 0; r < repeats; ++r) {
        const auto start = std::chrono::steady_clock::now();
        for (int i = 0; i < kCalls; ++i) call(i % kInputs);
        const auto stop = std::chrono::steady_clock::now();
        times.push_back(std::chrono::duration<double, std::nano>(stop - start).count() / kCalls);
    }
    std::nth_element(times.begin(), times.begin() + repeats / 2, times.end());
    return times[repeats / 2];
}

struct Row {
    std::string name;
    double ns[4];
};

template <class P>
Row measure(int repeats) {
    using V = typename P::P;
    std::mt19937 rng(12345);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    std::vector<V> a, b, v;
    for (int i = 0; i < kInputs; ++i) {
        // Angles below 0.9π: inside every chart.
        const Vec3 psi = Vec3(uniform(rng), uniform(rng), uniform(rng)).normalized() *
                         (0.9 * kPi * std::abs(uniform(rng)));
        const Vec3 psi2 = Vec3(uniform(rng), uniform(rng), uniform(rng)) * 0.5;
        a.push_back(P::from_rotation_vector(psi));
        b.push_back(P::from_rotation_vector(psi2));
        V x;
        for (int k = 0; k < P::kSize; ++k) x[k] = uniform(rng);
        v.push_back(x);
    }
    Row row{std::string(P::kName), {}};
    row.ns[0] = median_ns_per_call(
        [&](int i) {
            const Mat3 R = P::matrix(a[i]);
            do_not_optimize(R);
        },
        repeats);
    row.ns[1] = median_ns_per_call(
        [&](int i) {
            const V c = P::compose(a[i], b[i]);
            do_not_optimize(c);
        },
        repeats);
    row.ns[2] = median_ns_per_call(
        [&](int i) {
            const param::Tangent<P::kSize> H = P::material_tangent(a[i]);
            do_not_optimize(H);
        },
        repeats);
    row.ns[3] = median_ns_per_call(
        [&](int i) {
            const param::Tangent<P::kSize> D = P::material_tangent_derivative(a[i], v[i]);
            do_not_optimize(D);
        },
        repeats);
    return row;
}

}  // namespace

int main(int argc, char** argv) {
    const int repeats = argc > 1 ? std::max(1, std::atoi(argv[1])) : 201;
    std::vector<Row> rows;
    param::for_each_parameterization([&]<class P>() { rows.push_back(measure<P>(repeats)); });
    const char* ops[4] = {"R(p)", "compose", "H_m(p)", "d(H_m v)/dp"};
    std::printf("ns per call, median of %d repeats of %d calls (ratio to quaternion)\n\n", repeats,
                kCalls);
    std::printf("| %-18s |", "parameterization");
    for (const char* op : ops) std::printf(" %-18s |", op);
    std::printf("\n|%s|", std::string(20, '-').c_str());
    for (int k = 0; k < 4; ++k) std::printf("%s|", std::string(20, '-').c_str());
    std::printf("\n");
    for (const Row& r : rows) {
        std::printf("| %-18s |", r.name.c_str());
        for (int k = 0; k < 4; ++k) {
            char cell[32];
            std::snprintf(cell, sizeof cell, "%.1f (%.2f)", r.ns[k], r.ns[k] / rows[0].ns[k]);
            std::printf(" %-18s |", cell);
        }
        std::printf("\n");
    }
    return 0;
}
