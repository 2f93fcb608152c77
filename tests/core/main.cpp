#define BOOST_TEST_MODULE rotbeam core
#include <boost/test/unit_test.hpp>
