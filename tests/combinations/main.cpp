#define BOOST_TEST_MODULE rotbeam combination registry
#include <boost/test/unit_test.hpp>
