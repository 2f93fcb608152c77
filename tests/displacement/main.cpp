#define BOOST_TEST_MODULE displacement
#include <boost/test/unit_test.hpp>
