#define BOOST_TEST_MODULE rotbeam cases
#include <boost/test/unit_test.hpp>
