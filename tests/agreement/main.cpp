#define BOOST_TEST_MODULE rotbeam agreement of the formulations with the continuum reference
#include <boost/test/unit_test.hpp>
