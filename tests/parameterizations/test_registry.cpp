// The parameterization registry: names, dispatch by name, the error for an unknown name.
#include <boost/test/unit_test.hpp>

#include "core/errors.hpp"
#include "samples.hpp"

namespace rotbeam::test {

BOOST_AUTO_TEST_SUITE(parameterization_registry)

BOOST_AUTO_TEST_CASE(names_list_every_parameterization_in_order) {
    const std::vector<std::string> expected = {"quaternion", "wiener-milenkovic", "rodrigues",
                                               "rotation-vector", "euler-angles"};
    BOOST_TEST(param::parameterization_names() == expected, boost::test_tools::per_element());
}

BOOST_AUTO_TEST_CASE(dispatch_calls_the_named_type) {
    for (const std::string& name : param::parameterization_names()) {
        const std::string_view seen =
            param::dispatch_parameterization(name, []<class P>() { return P::kName; });
        BOOST_TEST(seen == name);
    }
    const int size =
        param::dispatch_parameterization("quaternion", []<class P>() { return P::kSize; });
    BOOST_TEST(size == 4);
}

BOOST_AUTO_TEST_CASE(unknown_name_throws_input_error_listing_valid_names) {
    try {
        param::dispatch_parameterization("cayley", []<class P>() { return P::kSize; });
        BOOST_ERROR("no exception");
    } catch (const InputError& e) {
        const std::string message = e.what();
        BOOST_TEST(message.find("'cayley'") != std::string::npos);
        for (const std::string& name : param::parameterization_names()) {
            BOOST_TEST(message.find(name) != std::string::npos);
        }
    }
}

BOOST_AUTO_TEST_CASE(for_each_visits_every_type_once) {
    int count = 0;
    int size_sum = 0;
    param::for_each_parameterization([&]<class P>() {
        ++count;
        size_sum += P::kSize;
    });
    BOOST_TEST(count == 5);
    BOOST_TEST(size_sum == 4 + 3 + 3 + 3 + 3);
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace rotbeam::test
