#define BOOST_TEST_MODULE rotbeam continuum reference solver
#include <boost/test/unit_test.hpp>
