#define BOOST_TEST_MODULE test_parameterizations
#include <boost/test/unit_test.hpp>
