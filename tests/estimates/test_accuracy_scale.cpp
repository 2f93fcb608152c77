// How a run's estimates are held against an accuracy (estimates/accuracy_scale.hpp), for a
// dynamic run: each responding history's largest estimated error relative to its amplitude, not
// each output time's error relative to the model's length; a history at the round-off floor (no
// `relative`) is not counted; an estimate that is not reliable at some output time makes its
// history fail any target; an output time without an estimate is missing.
#include <boost/test/unit_test.hpp>

#include "estimates/accuracy_scale.hpp"

namespace rotbeam::estimate {

namespace {

using json = nlohmann::json;

// A dynamic result at two output times: the tip moves (amplitude 2 m, largest estimated error
// 2e-4 m, so 1e-4 of its amplitude); the root is clamped (no relative error). `reliable` is the
// tip displacement's estimate at the second time.
json dynamic_result(bool reliable) {
    const json part = {{"error", 5e-5}, {"reliable", true}};
    const json q = {
        {"error", 1e-4}, {"reliable", true}, {"relative", 5e-5}, {"space", part}, {"time", part}};
    json late = q;
    late["error"] = 2e-4;
    late["relative"] = 1e-4;
    late["reliable"] = reliable;
    late["time"]["reliable"] = reliable;
    if (!reliable) late["reason"] = "time: phase 0.2 rad > 0.1 rad";
    const json rotation = {{"error", 1e-6}, {"reliable", true}, {"relative", 1e-5}};
    return {
        {"steps",
         {{{"time", 0.5}, {"estimate", {{"tip", {{"displacement", q}, {"rotation", rotation}}}}}},
          {{"time", 1.0},
           {"estimate", {{"tip", {{"displacement", late}, {"rotation", rotation}}}}}}}},
        {"estimate",
         {{"status", "estimated"},
          {"history",
           {{"tip",
             {{"displacement",
               {{"amplitude", 2.0},
                {"max_error", 2e-4},
                {"relative", 1e-4},
                {"relative_space", 4e-5},
                {"relative_time", 6e-5}}},
              {"rotation", {{"amplitude", 0.1}, {"max_error", 1e-6}, {"relative", 1e-5}}}}},
            {"root", {{"displacement", {{"amplitude", 0.0}, {"max_error", 0.0}}}}}}}}}};
}

Model far_points() {
    // 100 m between the points: an error relative to the length would be 50× smaller.
    Model m;
    m.points = {{"root", Vec3::Zero()}, {"tip", 100.0 * Vec3::UnitX()}};
    return m;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(accuracy_scale)

BOOST_AUTO_TEST_CASE(a_dynamic_run_is_measured_by_its_histories_relative_to_their_amplitudes) {
    const AccuracyMeasure m = measure_accuracy(far_points(), dynamic_result(true), 1e-4);
    BOOST_TEST(m.quantities == 2);  // tip displacement and rotation; the clamped root not
    BOOST_TEST(m.worst == 1e-4, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(m.worst_what == "tip displacement history (of its amplitude)");
    BOOST_TEST(meets(m, 1e-4));
    BOOST_TEST(!meets(m, 9e-5));
}

BOOST_AUTO_TEST_CASE(a_history_not_reliable_at_one_time_meets_no_target) {
    const AccuracyMeasure m = measure_accuracy(far_points(), dynamic_result(false), 1.0);
    BOOST_TEST(m.unreliable == 1);
    // The time part is the one not reliable (what the dynamic control tightens), the largest
    // parts those of the tip displacement's history.
    BOOST_TEST(m.time_unreliable == 1);
    BOOST_TEST(m.space_unreliable == 0);
    BOOST_TEST(m.worst_space == 4e-5);
    BOOST_TEST(m.worst_time == 6e-5);
    BOOST_TEST(!meets(m, 1.0));
    BOOST_TEST(m.first_problem.find("phase 0.2 rad") != std::string::npos, m.first_problem);
}

BOOST_AUTO_TEST_CASE(an_output_time_without_an_estimate_is_missing) {
    json r = dynamic_result(true);
    r["steps"][1]["estimate"] = {{"status", "not-estimated"},
                                 {"reason", "a companion has no state at t = 1"}};
    const AccuracyMeasure m = measure_accuracy(far_points(), r, 1.0);
    BOOST_TEST(m.missing == 1);
    BOOST_TEST(!meets(m, 1.0));
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace rotbeam::estimate
