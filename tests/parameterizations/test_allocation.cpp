// No heap allocation in R(p), compose, H(p) and ∂(H v)/∂p: a counting
// replacement of the global operator new sees every allocation of the executable.
#include <atomic>
#include <boost/test/unit_test.hpp>
#include <cstdlib>
#include <new>

#include "samples.hpp"

namespace {
std::atomic<long> g_allocations{0};
}

// GCC's -Wmismatched-new-delete cannot tell that these replacements pair malloc with free.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
void* operator new(std::size_t size) {
    ++g_allocations;
    if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
    throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
#pragma GCC diagnostic pop

namespace rotbeam::test {

BOOST_AUTO_TEST_SUITE(parameterization_allocation)

BOOST_AUTO_TEST_CASE(counting_operator_new_sees_allocations) {
    const long before = g_allocations.load();
    auto* probe = new double(1.0);
    BOOST_TEST(g_allocations.load() == before + 1);
    delete probe;
}

BOOST_AUTO_TEST_CASE_TEMPLATE(matrix_compose_tangents_and_derivatives_do_not_allocate, P,
                              AllParameterizationTypes) {
    using V = typename P::P;
    const V a = P::from_rotation_vector(1.1 * generic_axis());
    const V b = P::from_rotation_vector(0.7 * other_axis());
    const Vec3 w = other_axis();
    double sink = 0.0;
    const long before = g_allocations.load();
    for (int i = 0; i < 10; ++i) {
        sink += P::matrix(a).sum();
        sink += P::compose(a, b).sum();
        sink += P::spatial_tangent(a).sum() + P::material_tangent(a).sum();
        sink += P::spatial_tangent_inverse(a).sum() + P::material_tangent_inverse(a).sum();
        sink += P::spatial_tangent_derivative(a, b).sum();
        sink += P::material_tangent_derivative(a, b).sum();
        sink += P::spatial_tangent_inverse_derivative(a, w).sum();
        sink += P::material_tangent_inverse_derivative(a, w).sum();
        sink += P::to_rotation_vector(P::rescale(a, b)).sum();
    }
    const long after = g_allocations.load();
    BOOST_TEST(after == before);
    BOOST_TEST(std::isfinite(sink));
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace rotbeam::test
