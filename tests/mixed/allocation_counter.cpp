// Interposes the C allocator of the test executable: every heap allocation (operator new and
// Eigen's aligned_malloc both end in malloc) is counted, then served by glibc's own malloc. Not
// under the sanitizers (allocation_counter.hpp says why).
#include "tests/mixed/allocation_counter.hpp"

#include <atomic>
#include <cstddef>

#if ROTBEAM_COUNT_ALLOCATIONS
extern "C" void* __libc_malloc(std::size_t size);

namespace {
std::atomic<long> g_allocations{0};
}

long rotbeam::test::allocation_count() { return g_allocations.load(); }

extern "C" void* malloc(std::size_t size) {
    ++g_allocations;
    return __libc_malloc(size);
}
#else
long rotbeam::test::allocation_count() { return 0; }
#endif
