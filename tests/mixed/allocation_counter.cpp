// Interposes the C allocator of the test executable: every heap allocation (operator new and
// Eigen's aligned_malloc end in malloc; Eigen's zero-initialised work arrays, e.g. the supernodal
// SparseLU solve's, in calloc) is counted, then served by glibc's own functions. Not under the
// sanitizers (allocation_counter.hpp says why).
#include "tests/mixed/allocation_counter.hpp"

#include <atomic>
#include <cstddef>

#if ROTBEAM_COUNT_ALLOCATIONS
// glibc's exported implementations, declared here because no header declares them.
// NOLINTBEGIN(bugprone-reserved-identifier)
extern "C" void* __libc_malloc(std::size_t n);
extern "C" void* __libc_calloc(std::size_t n, std::size_t m);
extern "C" void* __libc_realloc(void* p, std::size_t n);
// NOLINTEND(bugprone-reserved-identifier)

namespace {
std::atomic<long> g_allocations{0};
}

long rotbeam::test::allocation_count() { return g_allocations.load(); }

extern "C" void* malloc(std::size_t size) {
    ++g_allocations;
    return __libc_malloc(size);
}
extern "C" void* calloc(std::size_t n, std::size_t size) {
    ++g_allocations;
    return __libc_calloc(n, size);
}
extern "C" void* realloc(void* p, std::size_t size) {
    ++g_allocations;
    return __libc_realloc(p, size);
}
#else
long rotbeam::test::allocation_count() { return 0; }
#endif
