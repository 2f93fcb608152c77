#define BOOST_TEST_MODULE rotbeam modal checks
#include <boost/test/unit_test.hpp>
