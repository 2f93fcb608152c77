// Counts heap allocations of the test executable (allocation_counter.cpp interposes malloc).
#pragma once

namespace rotbeam::test {
long allocation_count();
}
