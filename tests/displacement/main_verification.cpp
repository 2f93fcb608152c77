#define BOOST_TEST_MODULE displacement_verification
#include <boost/test/unit_test.hpp>
