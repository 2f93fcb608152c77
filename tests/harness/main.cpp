#define BOOST_TEST_MODULE test_harness
#include <boost/test/unit_test.hpp>
#include <iostream>

#include "tests/harness/coverage.hpp"

namespace {
// Prints the coverage count once every test has run (also under --run_test filters, which then
// count only what they ran).
struct PrintCoverage {
    ~PrintCoverage() { std::cout << rotbeam::test::coverage_report() << '\n'; }
};
}  // namespace

BOOST_TEST_GLOBAL_FIXTURE(PrintCoverage);
