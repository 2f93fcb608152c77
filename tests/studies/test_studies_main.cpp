#define BOOST_TEST_MODULE rotbeam_studies
#include <boost/test/unit_test.hpp>
