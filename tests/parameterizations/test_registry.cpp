// The parameterization registry: ids, names, dispatch by id, parsing a name.
#include <boost/test/unit_test.hpp>
#include <optional>
#include <stdexcept>

#include "samples.hpp"

namespace rotbeam::test {

BOOST_AUTO_TEST_SUITE(parameterization_registry)

BOOST_AUTO_TEST_CASE(names_list_every_parameterization_in_order) {
    const std::vector<std::string> expected = {"quaternion", "wiener-milenkovic", "rodrigues",
                                               "rotation-vector", "euler-angles"};
    BOOST_TEST(param::parameterization_names() == expected, boost::test_tools::per_element());
}

BOOST_AUTO_TEST_CASE(ids_are_registry_positions_and_dispatch_calls_their_type) {
    const std::vector<ParameterizationId> ids = param::parameterization_ids();
    BOOST_TEST_REQUIRE(ids.size() == param::parameterization_names().size());
    for (std::size_t i = 0; i < ids.size(); ++i) {
        BOOST_TEST(static_cast<std::size_t>(ids[i]) == i);
        const std::string_view seen =
            param::dispatch_parameterization(ids[i], []<class P>() { return P::kName; });
        BOOST_TEST(seen == param::parameterization_names()[i]);
        BOOST_TEST(param::name_of(ids[i]) == param::parameterization_names()[i]);
    }
    const int size = param::dispatch_parameterization(param::id_of<param::Quaternion>(),
                                                      []<class P>() { return P::kSize; });
    BOOST_TEST(size == 4);
    // The default of a case that names no rotation.
    BOOST_TEST((ParameterizationId{} == param::id_of<param::Quaternion>()));
}

BOOST_AUTO_TEST_CASE(names_parse_to_ids_and_unknown_names_to_nothing) {
    for (const std::string& name : param::parameterization_names()) {
        const std::optional<ParameterizationId> id = param::parse_parameterization(name);
        BOOST_TEST_REQUIRE(id.has_value(), name);
        BOOST_TEST(param::name_of(*id) == name);
    }
    BOOST_TEST(!param::parse_parameterization("euler").has_value());
    BOOST_TEST(!param::parse_parameterization("cayley").has_value());
    BOOST_TEST(!param::parse_parameterization("").has_value());
    BOOST_TEST(!param::parse_parameterization("Quaternion").has_value());
}

BOOST_AUTO_TEST_CASE(an_id_outside_the_registry_is_a_logic_error) {
    const auto invalid = static_cast<ParameterizationId>(param::AllParameterizations::kSize);
    BOOST_CHECK_THROW(param::dispatch_parameterization(invalid, []<class P>() { return P::kSize; }),
                      std::logic_error);
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
