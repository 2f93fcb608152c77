#define BOOST_TEST_MODULE mixed
#include <boost/test/unit_test.hpp>
