// Counts heap allocations of the test executable (allocation_counter.cpp interposes malloc).
//
// Not under the sanitizers (ROTBEAM_COUNT_ALLOCATIONS is 0 there, tests/mixed/CMakeLists.txt):
// AddressSanitizer serves malloc and free itself, and an executable that defines malloc replaces
// the sanitizer's definition, so the blocks it hands out are unknown to the sanitizer's free and
// the executable crashes before its first test. The count is what the Release build measures
// (the Newton loop's allocations), so the sanitized tests run every other check and say on their
// log that the allocation count is not checked.
#pragma once

#include <boost/test/unit_test.hpp>

namespace rotbeam::test {

inline constexpr bool kCountsAllocations = ROTBEAM_COUNT_ALLOCATIONS != 0;

// Allocations since the start; 0 when the counter is compiled out.
long allocation_count();

// Checks that nothing was allocated since `before` (a value of allocation_count()), or says on
// the test log that it cannot be checked in this build.
inline void check_no_allocation_since(long before) {
    if constexpr (kCountsAllocations) {
        BOOST_TEST(allocation_count() - before == 0);
    } else {
        BOOST_TEST_MESSAGE("allocations not counted under the sanitizers (allocation_counter.hpp)");
        static_cast<void>(before);
    }
}

}  // namespace rotbeam::test
