#define BOOST_TEST_MODULE rotbeam error estimates
#include <boost/test/unit_test.hpp>
