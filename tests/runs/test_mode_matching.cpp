// Mode shapes on stations and the matching of modes across meshes by MAC
// (runs/mode_matching.hpp).
#include <boost/test/unit_test.hpp>

#include "runs/mode_matching.hpp"

using namespace rotbeam;

BOOST_AUTO_TEST_SUITE(mode_matching)

BOOST_AUTO_TEST_CASE(mac_is_one_for_proportional_and_zero_for_orthogonal_shapes) {
    const std::vector<double> a = {1, 2, 0, -1}, b = {-2, -4, 0, 2}, c = {2, -1, 5, 0};
    BOOST_TEST(std::abs(modal_assurance(a, b) - 1.0) < 1e-15);
    BOOST_TEST(modal_assurance(a, c) == 0.0);
    BOOST_TEST(modal_assurance(a, {}) == 0.0);
}

// Two close modes in the other order, one mode missing and a spurious one: the match follows the
// shapes, not the order, and leaves the missing one unmatched.
BOOST_AUTO_TEST_CASE(modes_are_matched_by_shape_not_by_order) {
    const std::vector<double> bend = {0, 1, 2, 3}, twist = {3, 2, 1, 0}, axial = {1, -1, 1, -1};
    const std::vector<double> twist_coarse = {3.1, 2.0, 0.9, 0.1}, bend_coarse = {0.1, 1, 2.1, 2.9};
    const std::vector<double> spurious = {1, 1, -1, -1};
    const std::vector<int> m =
        match_modes({bend, twist, axial}, {twist_coarse, spurious, bend_coarse}, kMatchMac);
    BOOST_TEST(m[0] == 2);
    BOOST_TEST(m[1] == 0);
    BOOST_TEST(m[2] == -1);
}

// Stations interpolate linearly between the nodes of a straight member: a member from (0,0,0) to
// (8,0,0) with nodes at x = 0, 4, 8 (listed out of order) whose displacement is x² e_z gives
// 0, 4, 8, 12, 16, 28, 40, 52, 64 at x = 0, 1, …, 8. A node off the member does not enter.
BOOST_AUTO_TEST_CASE(stations_interpolate_along_a_straight_member) {
    Model model;
    model.points = {{"a", Vec3::Zero()}, {"b", Vec3(8, 0, 0)}};
    Member member;
    member.start_point = 0;
    member.end_point = 1;
    model.members = {member};
    std::vector<NodeDisplacement> nodes;
    for (double x : {4.0, 0.0, 8.0}) nodes.push_back({Vec3(x, 0, 0), Vec3(0, 0, x * x)});
    nodes.push_back({Vec3(1, 1, 0), Vec3(0, 0, 1e3)});
    const std::vector<double> s = station_displacements(model, nodes);
    BOOST_TEST_REQUIRE(s.size() == 3u * kModeStationsPerMember);
    const double expected[kModeStationsPerMember] = {0, 4, 8, 12, 16, 28, 40, 52, 64};
    for (int k = 0; k < kModeStationsPerMember; ++k) {
        BOOST_TEST(std::abs(s[3 * k + 2] - expected[k]) < 1e-12);
        BOOST_TEST(s[3 * k] == 0.0);
    }
}

BOOST_AUTO_TEST_SUITE_END()
