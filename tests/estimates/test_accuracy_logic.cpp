// Accuracy control's decisions (estimates/accuracy_control.hpp) on synthetic runs whose estimated
// error is a known function of the discretization: it stops when the estimates meet TOL/2 and
// not before, predicts the refinement instead of stepping blindly, and says why when TOL cannot
// be reached (a round-off floor, a singular chart, the budget) with `accuracy-not-reached`.
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <functional>

#include "estimates/accuracy_control.hpp"

namespace rotbeam::estimate {

namespace {

using json = nlohmann::json;

// One member between two points 1 apart: displacements are relative to 1.
Model unit_model(Formulation f, int elements, int order) {
    Model m;
    m.points = {{"root", Vec3::Zero()}, {"tip", Vec3::UnitX()}};
    Member member;
    member.name = "beam";
    member.start_point = 0;
    member.end_point = 1;
    member.elements = elements;
    m.members = {member};
    m.discretization.formulation = f;
    m.discretization.order = order;
    m.analysis.statics.load_factors = {1.0};
    return m;
}

// A converged run whose tip estimate is `error(model)`, reliable, with observed order `order`.
EstimatedRun synthetic(const std::function<double(const Model&)>& error, double order = 0.0,
                       const std::string& status = "converged") {
    return [=](const Model& model) {
        json q = {{"error", error(model)}, {"reliable", true}};
        if (order > 0.0) q["observed_order"] = order;
        json step = {{"load_factor", 1.0},
                     {"estimate", {{"tip", {{"displacement", q}, {"rotation", q}}}}}};
        return json{{"status", status},
                    {"message", status == "singular" ? "chart singular at 3.14 rad" : ""},
                    {"steps", status == "singular" ? json::array() : json::array({step})},
                    {"estimate", {{"status", "estimated"}, {"wall_seconds", 0.0}}}};
    };
}

}  // namespace

BOOST_AUTO_TEST_SUITE(accuracy_logic)

BOOST_AUTO_TEST_CASE(spectral_decay_raises_the_order_to_the_predicted_one) {
    // e_p = 10^−p: ρ = 0.1 per order; TOL 1e-6 needs e ≤ 5e-7, first met at p = 7.
    const json r = control_accuracy(
        unit_model(Formulation::displacement, 2, 2), 1e-6, {},
        synthetic([](const Model& m) { return std::pow(10.0, -m.discretization.order); }));
    BOOST_TEST(r["accuracy"]["status"] == "reached");
    BOOST_TEST(r["status"] == "converged");
    BOOST_TEST(r["accuracy"]["chosen"]["order"] == 7);
    BOOST_TEST(r["accuracy"]["chosen"]["elements"] == 2);
    // p = 2, 3 (to see the decay: 0.1 per order), then the predicted jump to 7.
    BOOST_TEST(r["accuracy"]["attempts"].size() == 3u, r["accuracy"]["attempts"].dump());
}

// Trapezoidal quadrature: an error that is the rule's alone, 0.1 refine⁻² (nothing gained by p or
// h without more points). The coarse start takes refine to twice its order 6 (12: 6.9e-4), each
// order step doubles it (the p+1 companion's discretization): order 7 at refine 24 shows the
// decay 1/4 per order, and the predicted jump of 3 orders lands on refine 192 (2.7e-6), the first
// of the doubling sequence under TOL/2 = 5e-6 (it needs ≥ 142). Without refine in the control the
// error stays at 0.1 whatever the order. With a budget of refine 100 it stops, naming refine.
BOOST_AUTO_TEST_CASE(trapezoidal_quadrature_doubles_refine_with_each_step) {
    Model model = unit_model(Formulation::displacement, 1, 6);
    model.discretization.quadrature = Quadrature::trapezoidal;
    const auto quadrature_error = [](const Model& m) {
        return 0.1 / std::pow(static_cast<double>(m.discretization.refine), 2.0);
    };
    const json r =
        control_accuracy(model, 1e-5, {}, synthetic(quadrature_error), coarse_start(model));
    BOOST_TEST(r["accuracy"]["status"] == "reached", r["accuracy"].dump());
    const json& attempts = r["accuracy"]["attempts"];
    BOOST_TEST_REQUIRE(attempts.size() == 3u, attempts.dump());
    BOOST_TEST(attempts[0]["refine"] == 12);
    BOOST_TEST(attempts[1]["refine"] == 24);
    BOOST_TEST(attempts[2]["order"] == 10);
    BOOST_TEST(attempts[2]["refine"] == 192);
    BOOST_TEST(r["accuracy"]["chosen"]["refine"] == 192);
    BOOST_TEST(r["accuracy"]["strategy"] == "p while spectral, else h; refine doubled per step");
    AccuracyBudget small;
    small.refine = 100;
    const json stopped =
        control_accuracy(model, 1e-5, small, synthetic(quadrature_error), coarse_start(model));
    BOOST_TEST(stopped["status"] == "accuracy-not-reached");
    BOOST_TEST(stopped["accuracy"]["reason"].get<std::string>().find("refine") !=
               std::string::npos);
}

BOOST_AUTO_TEST_CASE(no_spectral_decay_splits_the_elements) {
    // e = N^−4, no better with p on this mesh from order 6 on: h is taken.
    const json r = control_accuracy(
        unit_model(Formulation::displacement, 2, 6), 1e-6, {}, synthetic([](const Model& m) {
            return std::pow(static_cast<double>(m.members[0].elements), -4.0) * 0.5;
        }));
    BOOST_TEST(r["accuracy"]["status"] == "reached");
    BOOST_TEST(r["accuracy"]["chosen"]["elements"].get<int>() > 2);
}

BOOST_AUTO_TEST_CASE(mixed_predicts_the_element_count_from_the_order) {
    // e = 1/N²: from 16 elements (3.9e-3) to 5e-5 needs N ≥ 142; predicted in one step.
    const json r = control_accuracy(
        unit_model(Formulation::mixed, 16, 1), 1e-4, {},
        synthetic([](const Model& m) { return std::pow(m.members[0].elements, -2.0); }, 2.0));
    BOOST_TEST(r["accuracy"]["status"] == "reached");
    BOOST_TEST(r["accuracy"]["attempts"].size() == 2u, r["accuracy"]["attempts"].dump());
    BOOST_TEST(r["accuracy"]["chosen"]["elements"].get<int>() >= 142);
}

BOOST_AUTO_TEST_CASE(a_round_off_floor_is_reported_not_refined_forever) {
    // The estimate stagnates at 1e-4 from 100 elements on: TOL 1e-5 is below it, and the
    // element budget (4096) is not what stops it.
    const json r = control_accuracy(
        unit_model(Formulation::mixed, 16, 1), 1e-5, {},
        synthetic(
            [](const Model& m) { return std::max(std::pow(m.members[0].elements, -2.0), 1e-4); },
            2.0));
    BOOST_TEST(r["status"] == "accuracy-not-reached");
    BOOST_TEST(r["accuracy"]["reason"].get<std::string>().rfind("round-off floor", 0) == 0,
               r["accuracy"]["reason"]);
}

BOOST_AUTO_TEST_CASE(a_singular_chart_is_reported) {
    const json r = control_accuracy(unit_model(Formulation::mixed, 16, 1), 1e-4, {},
                                    synthetic([](const Model&) { return 1.0; }, 2.0, "singular"));
    BOOST_TEST(r["status"] == "accuracy-not-reached");
    BOOST_TEST(r["accuracy"]["reason"].get<std::string>().rfind("singular chart", 0) == 0);
}

BOOST_AUTO_TEST_CASE(the_budget_stops_it) {
    AccuracyBudget budget;
    budget.elements_per_member = 64;
    const json r = control_accuracy(
        unit_model(Formulation::mixed, 16, 1), 1e-8, budget,
        synthetic([](const Model& m) { return std::pow(m.members[0].elements, -2.0); }, 2.0));
    BOOST_TEST(r["status"] == "accuracy-not-reached");
    BOOST_TEST(r["accuracy"]["reason"].get<std::string>().rfind("budget", 0) == 0);
    BOOST_TEST(r["accuracy"]["chosen"]["elements"] == 64);
}

BOOST_AUTO_TEST_CASE(the_displacement_formulation_starts_coarse) {
    // The case's 16 elements at order 2; e_p = 10^−p whatever the mesh: from one element at
    // order 6 the decay is seen (6, 7) and order 7 already meets 5e-7.
    const Model model = unit_model(Formulation::displacement, 16, 2);
    const Model start = coarse_start(model);
    BOOST_TEST(start.members[0].elements == 1);
    BOOST_TEST(start.discretization.order == 6);
    const json r = control_accuracy(
        model, 1e-6, {},
        synthetic([](const Model& m) { return std::pow(10.0, -m.discretization.order); }), start);
    BOOST_TEST(r["accuracy"]["status"] == "reached");
    BOOST_TEST(r["accuracy"]["chosen"]["elements"] == 1);
    BOOST_TEST(r["accuracy"]["chosen"]["order"] == 7);
    // The mixed formulation keeps the case's mesh.
    BOOST_TEST(coarse_start(unit_model(Formulation::mixed, 16, 1)).members[0].elements == 16);
}

BOOST_AUTO_TEST_CASE(a_coarse_start_that_fails_moves_to_the_case_mesh) {
    // One element is singular (a node at the chart's singular angle); the case's 16 elements at
    // order 4 solve with e = 1e-8: the control says why it left the coarse start and reaches.
    const Model model = unit_model(Formulation::displacement, 16, 4);
    const EstimatedRun good = synthetic([](const Model&) { return 1e-8; });
    const EstimatedRun singular = synthetic([](const Model&) { return 1.0; }, 0.0, "singular");
    const json r = control_accuracy(
        model, 1e-6, {},
        [&](const Model& m) { return m.members[0].elements == 1 ? singular(m) : good(m); },
        coarse_start(model));
    BOOST_TEST(r["accuracy"]["status"] == "reached");
    BOOST_TEST(r["accuracy"]["chosen"]["elements"] == 16);
    BOOST_TEST(r["accuracy"]["attempts"].size() == 2u);
    BOOST_TEST(r["accuracy"]["attempts"][0]["next"].get<std::string>().find("coarse start") !=
               std::string::npos);
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace rotbeam::estimate
