// Error types carry what a user needs to act.
#include <boost/test/unit_test.hpp>

#include <string>

#include "core/errors.hpp"

using namespace rotbeam;

BOOST_AUTO_TEST_SUITE(error_types)

BOOST_AUTO_TEST_CASE(singularity_error_names_parameterization_function_and_angle) {
    const SingularityError e("rodrigues", "matrix", 3.14159, "at pi");
    const std::string what = e.what();
    BOOST_TEST(what.find("rodrigues::matrix") != std::string::npos);
    BOOST_TEST(what.find("3.14159") != std::string::npos);
    BOOST_TEST(e.angle() == 3.14159);
}

BOOST_AUTO_TEST_CASE(verify_throws_with_file_and_line) {
    try {
        ROTBEAM_VERIFY(1 + 1 == 3, "arithmetic");
        BOOST_FAIL("verify did not throw");
    } catch (const std::logic_error& e) {
        const std::string what = e.what();
        BOOST_TEST(what.find("test_errors.cpp") != std::string::npos);
        BOOST_TEST(what.find("arithmetic") != std::string::npos);
    }
}

BOOST_AUTO_TEST_SUITE_END()
