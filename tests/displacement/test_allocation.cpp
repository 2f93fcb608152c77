// Residual + Jacobian evaluation allocates nothing after the first call (issue 5 item 8; STYLE.md
// "no allocation inside the Newton loop"): a counting global operator new around evaluate().
#define BOOST_TEST_MODULE displacement_allocation
#include <boost/test/unit_test.hpp>
#include <cstdlib>

#include "deformed.hpp"
#include "formulations/displacement/displacement_statics.hpp"

// Eigen allocates with std::malloc, not operator new, so malloc itself is interposed (the
// executable's definition wins over glibc's; __libc_malloc is glibc's implementation).
extern "C" void* __libc_malloc(std::size_t);
extern "C" void* __libc_calloc(std::size_t, std::size_t);
extern "C" void* __libc_realloc(void*, std::size_t);
namespace {
long g_allocations = 0;
}
extern "C" void* malloc(std::size_t n) {
    ++g_allocations;
    return __libc_malloc(n);
}
extern "C" void* calloc(std::size_t n, std::size_t m) {
    ++g_allocations;
    return __libc_calloc(n, m);
}
extern "C" void* realloc(void* p, std::size_t n) {
    ++g_allocations;
    return __libc_realloc(p, n);
}

using namespace rotbeam;

template <class P>
long allocations_in_repeated_evaluations() {
    form::DisplacementStatics<P> s(test::curved_twisted(3, 5, true, true));
    s.set_load_factor(1.0);
    s.retract(test::deforming_increment(s.mesh()) * 0.3);
    VecX r;
    SparseMatrix J;
    s.evaluate(r, &J);  // first call: sizes r and copies the fixed pattern into J
    const VecX dx = VecX::Constant(s.size(), 1e-3);
    const long before = g_allocations;
    for (int k = 0; k < 3; ++k) {
        s.evaluate(r, &J);
        s.evaluate(r, nullptr);
        s.retract(dx);
    }
    return g_allocations - before;
}

// The counter sees Eigen's allocations (otherwise the test below could not fail).
BOOST_AUTO_TEST_CASE(counter_sees_eigen_allocations) {
    const long before = g_allocations;
    VecX v = VecX::Random(100);
    BOOST_TEST(g_allocations > before);
    BOOST_TEST(v.size() == 100);
}

BOOST_AUTO_TEST_CASE(evaluate_and_retract_allocate_nothing_after_the_first_call) {
    BOOST_TEST(allocations_in_repeated_evaluations<param::Quaternion>() == 0);
    BOOST_TEST(allocations_in_repeated_evaluations<param::WienerMilenkovic>() == 0);
    BOOST_TEST(allocations_in_repeated_evaluations<param::RotationVector>() == 0);
}
