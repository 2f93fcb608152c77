// The estimate of one quantity from its companions (estimates/quantity_estimate.hpp) and the
// bookkeeping of add_estimate (estimates/estimate.hpp) on synthetic companion results: every
// way an estimate can be missing or unreliable says so.
#include <boost/test/unit_test.hpp>
#include <cmath>

#include "core/errors.hpp"
#include "estimates/companions.hpp"
#include "estimates/estimate.hpp"
#include "estimates/quantity_estimate.hpp"

namespace rotbeam::estimate {

namespace {

using json = nlohmann::json;

// A sequence q_h = q + C h^r sampled at h, h/2, h/4: (e₁, e₂, true error of q_h).
struct Sequence {
    double e1, e2, true_error;
};
Sequence power_law(double C, double h, double r) {
    const auto q = [&](double hh) { return C * std::pow(hh, r); };
    return {std::abs(q(h) - q(h / 2)), std::abs(q(h / 2) - q(h / 4)), std::abs(q(h))};
}

// A static result with one step and one point "tip" displaced by `u` along x, unrotated.
json static_result(const std::string& status, const std::vector<double>& tip_x) {
    json steps = json::array();
    double lambda = 0.5;
    for (const double u : tip_x) {
        steps.push_back({{"load_factor", lambda},
                         {"points",
                          {{"tip",
                            {{"displacement", {u, 0.0, 0.0}},
                             {"rotation_matrix", {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}}}}}});
        lambda += 0.5;
    }
    return {{"status", status}, {"message", ""}, {"steps", steps}};
}

Model two_point_model(Formulation formulation) {
    Model m;
    m.points = {{"root", Vec3::Zero()}, {"tip", Vec3(2.0, 0.0, 0.0)}};
    Member beam;
    beam.name = "beam";
    beam.elements = 4;
    m.members = {beam};
    m.discretization.formulation = formulation;
    m.discretization.order = 3;
    return m;
}

const ModePairing kNoModes = [](const json&, const json&) { return std::vector<int>(); };

}  // namespace

BOOST_AUTO_TEST_CASE(richardson_recovers_the_error_of_an_exact_power_law) {
    for (const double r : {1.6, 2.0, 2.4}) {
        const Sequence s = power_law(0.3, 0.25, r);
        const QuantityEstimate e = h_refinement(s.e1, s.e2, 2.0, 1e-14);
        BOOST_TEST(e.reliable);
        BOOST_TEST(*e.observed_order == r, boost::test_tools::tolerance(1e-12));
        BOOST_TEST(e.error == s.true_error, boost::test_tools::tolerance(1e-12));
    }
}

BOOST_AUTO_TEST_CASE(an_order_outside_the_window_is_estimated_but_not_reliable) {
    const Sequence s = power_law(0.3, 0.25, 1.0);  // first order where second is expected
    const QuantityEstimate e = h_refinement(s.e1, s.e2, 2.0, 1e-14);
    BOOST_TEST(!e.reliable);
    BOOST_TEST(*e.observed_order == 1.0, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(e.error == s.e1 / 0.75, boost::test_tools::tolerance(1e-12));  // theoretical order
    BOOST_TEST(e.reason.find("observed order") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(a_non_monotone_sequence_is_not_reliable) {
    const QuantityEstimate e = h_refinement(1e-4, 3e-4, 2.0, 1e-14);
    BOOST_TEST(!e.reliable);
    BOOST_TEST(e.reason.find("not monotone") != std::string::npos);
    BOOST_TEST(std::isfinite(e.error));
    BOOST_TEST(e.error > 0.0);
}

// Converged companions: the run's error is its difference from them, reliable, with no order.
BOOST_AUTO_TEST_CASE(companions_agreeing_to_round_off_give_the_runs_difference) {
    const QuantityEstimate e = h_refinement(1e-5, 0.0, 2.0, 1e-12);
    BOOST_TEST(e.reliable);
    BOOST_TEST(e.error == 1e-5);
    BOOST_TEST(!e.observed_order.has_value());
    BOOST_TEST(e.reason.find("agree to round-off") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(a_quantity_unchanged_by_refinement_is_estimated_at_the_floor) {
    const QuantityEstimate e = h_refinement(0.0, 0.0, 2.0, 1e-12);
    BOOST_TEST(e.reliable);
    BOOST_TEST(e.error == 0.0);
}

BOOST_AUTO_TEST_CASE(p_refinement_is_the_difference_and_states_its_assumption) {
    const QuantityEstimate e = p_refinement(2.5e-7);
    BOOST_TEST(e.error == 2.5e-7);
    BOOST_TEST(e.reliable);
    BOOST_TEST(e.reason.find("spectral") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(p_refinement_with_decaying_differences_is_reliable) {
    // e_k = 0.3^k: d₂ / d₁ = 0.3, and d₁ = 0.7 e_p, inside [1 − r, 1 + r].
    const double e2 = 0.09, e3 = 0.027, e4 = 0.0081;
    const QuantityEstimate e = p_refinement(e2 - e3, e3 - e4, e2 - e4, 1e-12);
    BOOST_TEST(e.reliable);
    BOOST_TEST(e.error == e2 - e3);
    BOOST_TEST(e.error / e2 >= 0.5);
}

BOOST_AUTO_TEST_CASE(p_refinement_without_decay_is_not_reliable_and_stays_on_the_safe_side) {
    // Errors of orders p and p+1 equal in size (the crossing of two h-rates), order p+2 ahead:
    // d₁ alone would be 0.17 e_p; the value is the larger difference, d₀₂ ≈ e_p.
    const double ep = 1.0e-8, ep1 = 0.83e-8, ep2 = 1e-10;
    const QuantityEstimate e = p_refinement(ep - ep1, ep1 - ep2, ep - ep2, 1e-12);
    BOOST_TEST(!e.reliable);
    BOOST_TEST(e.error == ep - ep2);
    BOOST_TEST(e.reason.find("no p-decay") != std::string::npos);
    // Order p+1 worse than p: d₁ is the larger.
    const QuantityEstimate w = p_refinement(4.0, 5.0, 1.0, 1e-12);
    BOOST_TEST(!w.reliable);
    BOOST_TEST(w.error == 4.0);
}

BOOST_AUTO_TEST_CASE(p_refinement_at_round_off_is_reliable) {
    const QuantityEstimate e = p_refinement(3e-13, 5e-13, 4e-13, 1e-12);
    BOOST_TEST(e.reliable);
    BOOST_TEST(e.error == 5e-13);
}

BOOST_AUTO_TEST_CASE(the_plan_chooses_the_method_per_formulation) {
    const CompanionPlan p = plan_companions(two_point_model(Formulation::displacement));
    BOOST_TEST(p.method == "p+1");
    // Order 3 < kSpectralOrder: the p+1 companion and the p+2 one of the decay check.
    BOOST_TEST_REQUIRE(p.companions.size() == 2u);
    BOOST_TEST(p.companions[0].model.discretization.order == 4);
    BOOST_TEST(p.companions[0].model.members[0].elements == 4);
    BOOST_TEST(p.companions[1].model.discretization.order == 5);
    Model high = two_point_model(Formulation::displacement);
    high.discretization.order = kSpectralOrder;
    BOOST_TEST(plan_companions(high).companions.size() == 1u);
    // The dynamic estimate's space companions have no decay check.
    BOOST_TEST(
        plan_space_companions(two_point_model(Formulation::displacement)).companions.size() == 1u);
    const CompanionPlan h = plan_companions(two_point_model(Formulation::mixed));
    BOOST_TEST(h.method == "h/2,h/4");
    BOOST_TEST_REQUIRE(h.companions.size() == 2u);
    BOOST_TEST(h.companions[0].model.members[0].elements == 8);
    BOOST_TEST(h.companions[1].model.members[0].elements == 16);
    Model dynamic = two_point_model(Formulation::displacement);
    dynamic.analysis.kind = AnalysisKind::dynamic;
    BOOST_TEST(!plan_companions(dynamic).refusal.empty());
    BOOST_TEST(plan_companions(dynamic).companions.empty());
}

// With the trapezoidal rule each companion doubles refine, the p+2 one again beyond the p+1 one,
// so that both differences of the decay check fall with p and with refine alike.
BOOST_AUTO_TEST_CASE(trapezoidal_companions_double_refine_at_each_step) {
    Model m = two_point_model(Formulation::displacement);
    m.discretization.quadrature = Quadrature::trapezoidal;
    m.discretization.refine = 3;
    const CompanionPlan p = plan_companions(m);
    BOOST_TEST_REQUIRE(p.companions.size() == 2u);
    BOOST_TEST(p.companions[0].model.discretization.refine == 6);
    BOOST_TEST(p.companions[1].model.discretization.refine == 12);
    BOOST_TEST(p.companions[1].model.discretization.order == 5);
    BOOST_TEST(p.companions[1].label == "order 5, refine 12");
}

BOOST_AUTO_TEST_CASE(an_untrustworthy_run_gets_no_companions_and_says_why) {
    json result = static_result("diverged", {0.1});
    int calls = 0;
    add_estimate(
        two_point_model(Formulation::mixed), result,
        [&](const Model&) {
            ++calls;
            return json();
        },
        kNoModes);
    BOOST_TEST(calls == 0);
    BOOST_TEST(result["estimate"]["status"] == "not-estimated");
    BOOST_TEST(result["estimate"]["reason"].get<std::string>().find("diverged") !=
               std::string::npos);
    BOOST_TEST(!result["steps"][0].contains("estimate"));
}

BOOST_AUTO_TEST_CASE(a_companion_that_stops_early_leaves_the_later_steps_without_estimate) {
    // Mixed: the run at h, companions at h/2 (both steps) and h/4 (diverged after the first).
    json result = static_result("converged", {1.0 + 0.16, 2.0 + 0.16});
    const std::vector<json> companions = {static_result("converged", {1.04, 2.04}),
                                          static_result("diverged", {1.01})};
    std::size_t next = 0;
    add_estimate(
        two_point_model(Formulation::mixed), result,
        [&](const Model&) { return companions.at(next++); }, kNoModes);
    BOOST_TEST(next == 2u);
    const json& first = result["steps"][0]["estimate"]["tip"]["displacement"];
    BOOST_TEST(first["reliable"].get<bool>());
    BOOST_TEST(first["observed_order"].get<double>() == 2.0, boost::test_tools::tolerance(1e-9));
    BOOST_TEST(first["error"].get<double>() == 0.16, boost::test_tools::tolerance(1e-9));
    const json& second = result["steps"][1]["estimate"];
    BOOST_TEST(second["status"] == "not-estimated");
    BOOST_TEST(second["reason"].get<std::string>().find("4x elements") != std::string::npos);
    BOOST_TEST(result["estimate"]["status"] == "partial");
    BOOST_TEST(result["estimate"]["missing"].get<int>() == 1);
    BOOST_TEST(result["estimate"]["companions"].size() == 2u);
}

BOOST_AUTO_TEST_CASE(a_companion_the_formulation_refuses_gives_no_estimate_and_says_why) {
    json result = static_result("converged", {0.5});
    add_estimate(
        two_point_model(Formulation::displacement), result,
        [](const Model&) -> json { throw InputError("refused: no such combination"); }, kNoModes);
    BOOST_TEST(result["estimate"]["status"] == "not-estimated");
    BOOST_TEST(result["estimate"]["companions"][0]["status"] == "error");
    BOOST_TEST(result["steps"][0]["estimate"]["reason"].get<std::string>().find("refused") !=
               std::string::npos);
}

}  // namespace rotbeam::estimate
