#define BOOST_TEST_MODULE rotbeam analytic oracles
#include <boost/test/unit_test.hpp>
