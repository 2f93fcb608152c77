// The estimate of one quantity from its companions (estimates/quantity_estimate.hpp) and the
// bookkeeping of add_estimate (estimates/estimate.hpp) on synthetic companion results: every
// way an estimate can be missing or unreliable says so.
#include <boost/test/unit_test.hpp>
#include <cmath>

#include "core/errors.hpp"
#include "estimates/companions.hpp"
#include "estimates/dynamic_companions.hpp"
#include "estimates/estimate.hpp"
#include "estimates/history_estimate.hpp"
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

// The same power laws seen from the run at h with companions at 2h and 4h: e₁ = |q_h − q_2h|,
// e₂ = |q_2h − q_4h|. Exact for q_h = q + C h^r: e₂ = 2^r e₁ and e_h = e₁ / (2^r − 1).
BOOST_AUTO_TEST_CASE(richardson_from_coarser_meshes_recovers_the_error_of_an_exact_power_law) {
    for (const double r : {1.6, 2.0, 2.4}) {
        const Sequence s = power_law(0.3, 1.0, r);  // values at 1, 1/2, 1/4: the run is at 1/4
        const double e_run = 0.3 * std::pow(0.25, r);
        const QuantityEstimate e = h_refinement(s.e2, s.e1, 2.0, 1e-14, HSequence::coarser);
        BOOST_TEST(e.reliable);
        BOOST_TEST(*e.observed_order == r, boost::test_tools::tolerance(1e-12));
        BOOST_TEST(e.error == e_run, boost::test_tools::tolerance(1e-12));
    }
    // Outside the window: extrapolated with the theoretical order, e₁ / 3, and not reliable.
    const Sequence s = power_law(0.3, 1.0, 1.0);
    const QuantityEstimate e = h_refinement(s.e2, s.e1, 2.0, 1e-14, HSequence::coarser);
    BOOST_TEST(!e.reliable);
    BOOST_TEST(*e.observed_order == 1.0, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(e.error == s.e2 / 3.0, boost::test_tools::tolerance(1e-12));
    // Coarser meshes closer together than the finer ones: not converging.
    const QuantityEstimate n = h_refinement(3e-4, 1e-4, 2.0, 1e-14, HSequence::coarser);
    BOOST_TEST(!n.reliable);
    BOOST_TEST(n.reason.find("not monotone") != std::string::npos);
    BOOST_TEST(n.reason.find("q_2h - q_4h") != std::string::npos);
    // The run and 2h agree to round-off, 4h does not: the quantity is resolved at 2h already.
    const QuantityEstimate a = h_refinement(1e-13, 1e-5, 2.0, 1e-12, HSequence::coarser);
    BOOST_TEST(a.reliable);
    BOOST_TEST(a.error == 1e-13);
    BOOST_TEST(a.reason.find("2h companion agree to round-off") != std::string::npos);
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

// Coarser companions halve and quarter the mixed formulation's elements, which must divide by 4;
// the displacement formulation keeps its p+1 companion (no coarser p-estimate of e_p exists).
BOOST_AUTO_TEST_CASE(coarser_companions_halve_and_quarter_the_elements) {
    Model m = two_point_model(Formulation::mixed);
    m.members[0].elements = 12;
    m.analysis.estimate_companions = CompanionSide::coarser;
    const CompanionPlan h = plan_companions(m);
    BOOST_TEST(h.method == "2h,4h");
    BOOST_TEST(h.refusal.empty());
    BOOST_TEST_REQUIRE(h.companions.size() == 2u);
    BOOST_TEST(h.companions[0].model.members[0].elements == 6);
    BOOST_TEST(h.companions[1].model.members[0].elements == 3);
    BOOST_TEST(h.companions[1].label == "1/4 elements");
    m.members[0].elements = 10;
    const CompanionPlan refused = plan_companions(m);
    BOOST_TEST(refused.companions.empty());
    BOOST_TEST(refused.refusal.find("divisible by 4; member 'beam' has 10") != std::string::npos);
    Model d = two_point_model(Formulation::displacement);
    d.analysis.estimate_companions = CompanionSide::coarser;
    BOOST_TEST(plan_companions(d).method == "p+1");
}

// In time, coarser companions double a fixed step ("2dt", ratio 1/2), which must land on the run's
// output times; adaptive steps keep tolerance/4 on both sides.
BOOST_AUTO_TEST_CASE(coarser_time_companions_double_a_fixed_step_onto_the_output_times) {
    Model m = two_point_model(Formulation::mixed);
    m.analysis.kind = AnalysisKind::dynamic;
    m.analysis.estimate_companions = CompanionSide::coarser;
    DynamicSettings& d = m.analysis.dynamics;
    d.integrator = Integrator::trapezoidal;
    d.time_step = 1e-3;
    d.end_time = 0.1;
    d.output_interval = 4e-3;
    const DynamicPlan p = plan_dynamic_companions(m);
    BOOST_TEST(p.space.method == "2h,4h");
    BOOST_TEST(p.time_method == "2dt");
    BOOST_TEST(p.time_ratio == 0.5);
    BOOST_TEST(p.time_refusal.empty());
    BOOST_TEST_REQUIRE(p.time.size() == 1u);
    BOOST_TEST(p.time[0].model.analysis.dynamics.time_step == 2e-3);
    for (const double every : {5e-3, 0.0}) {  // off the 2 ms grid; every step
        d.output_interval = every;
        const DynamicPlan refused = plan_dynamic_companions(m);
        BOOST_TEST(refused.time.empty());
        BOOST_TEST(refused.time_refusal.find("multiple of 2 dt") != std::string::npos,
                   refused.time_refusal);
    }
    d.output_interval = 4e-3;
    d.time_tolerance = 1e-4;
    BOOST_TEST(plan_dynamic_companions(m).time_method == "tolerance/4");
}

// The phase of a 2dt companion is 2^q that of the run: a largest difference D = 2A sin(φ (2^q −
// 1)/2) gives back the run's φ.
BOOST_AUTO_TEST_CASE(the_phase_from_a_coarser_companion_is_the_runs) {
    const double phi = 0.02, A = 1.5;
    for (const double q : {1.0, 2.0, 4.0}) {
        const double D = 2.0 * A * std::sin(phi * (std::exp2(q) - 1.0) / 2.0);
        BOOST_TEST(accumulated_phase(D, A, q, 0.5) == phi, boost::test_tools::tolerance(1e-12));
        const double Df = 2.0 * A * std::sin(phi * (1.0 - std::exp2(-q)) / 2.0);
        BOOST_TEST(accumulated_phase(Df, A, q, 2.0) == phi, boost::test_tools::tolerance(1e-12));
    }
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
