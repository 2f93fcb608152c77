// The warm start of a static run (core/nodal_field.hpp, docs/accuracy-control.md "Warm start"):
// a run of order p + 1 on one element started from the solved path of order p must give the
// answer of the same run started from the undeformed beam, within the Newton tolerance, in far
// fewer Newton iterations. Every parameterization with both rotation interpolations on the 45°
// bend (three load steps; the continued chart is not at stake), and the roll-up to λ = 2 (the tip
// turns 4π: the rotation vector and Euler angles keep parameters past π without rescaling, so the
// guess must continue their chart) with the combinations that solve it on one element at order 7
// (the others diverge there with or without a warm start, which is not what is tested here).
#define BOOST_TEST_MODULE rotbeam warm start
#include <algorithm>
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <string>
#include <vector>

#include "cases/loader/case_loader.hpp"
#include "core/nodal_field.hpp"
#include "core/so3.hpp"
#include "core/static_driver.hpp"
#include "estimates/accuracy_scale.hpp"
#include "runs/run_case.hpp"

using namespace rotbeam;
using json = nlohmann::json;

namespace {

struct Combination {
    const char* rotation;
    const char* interpolation;
};

Model one_element(const std::string& name, const Combination& c, std::vector<std::string> o,
                  int order) {
    o.push_back("discretization.formulation=displacement");
    o.push_back(std::string("discretization.rotation=") + c.rotation);
    o.push_back(std::string("discretization.interpolation=") + c.interpolation);
    o.push_back("members.*.elements=1");
    o.push_back("discretization.order=" + std::to_string(order));
    return load_case(std::string(ROTBEAM_SOURCE_DIR) + "/cases/" + name + ".yaml", o,
                     CaseParts::case_file);
}

json run(const Model& model, const SolvedPath* start, SolvedPath* path) {
    RunRequest r{"", model};
    r.start = start;
    r.path = path;
    return run_case(r);
}

Vec3 displacement(const json& tip) {
    Vec3 u;
    for (int i = 0; i < 3; ++i) u[i] = tip["displacement"][i].get<double>();
    return u;
}

Mat3 rotation(const json& tip) {
    Mat3 R;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) R(i, j) = tip["rotation_matrix"][i][j].get<double>();
    }
    return R;
}

// Runs order p cold (recording its path), then order p + 1 cold and warm from that path.
void check_warm_start(const std::string& name, const Combination& c,
                      const std::vector<std::string>& overrides, int p) {
    BOOST_TEST_CONTEXT(name << ", " << c.rotation << ", " << c.interpolation << ", order " << p
                            << " -> " << p + 1) {
        SolvedPath path;
        const json coarse = run(one_element(name, c, overrides, p), nullptr, &path);
        BOOST_TEST_REQUIRE(has_solution(coarse["status"].get<std::string>()));
        BOOST_TEST_REQUIRE(path.states.size() == coarse["steps"].size());
        const Model model = one_element(name, c, overrides, p + 1);
        const json cold = run(model, nullptr, nullptr);
        const json warm = run(model, &path, nullptr);
        BOOST_TEST_REQUIRE(has_solution(cold["status"].get<std::string>()));
        BOOST_TEST_REQUIRE(has_solution(warm["status"].get<std::string>()));
        BOOST_TEST_REQUIRE(warm["steps"].size() == cold["steps"].size());
        // Same answer: each run accepts a state whose scaled algebraic error is at most its last
        // Newton correction, ≤ increment_tolerance (1e-12; displacements scaled by the member
        // length, rotations in rad), or the error bound of a stall (docs/solver-convergence.md);
        // the two states differ by at most the sum. The chord between the case's points is
        // shorter than the member, so scaling by it is the stricter test.
        const double length = estimate::reference_length(model);
        const double newton =
            newton_settings_from(model.solver, model.analysis.statics).increment_tolerance;
        int cold_iterations = 0, warm_iterations = 0;
        for (std::size_t k = 0; k < cold["steps"].size(); ++k) {
            const json& a = cold["steps"][k];
            const json& b = warm["steps"][k];
            const double bound = std::max(newton, a["convergence"]["error_bound"].get<double>()) +
                                 std::max(newton, b["convergence"]["error_bound"].get<double>());
            const json& ta = a["points"]["tip"];
            const json& tb = b["points"]["tip"];
            BOOST_TEST((displacement(ta) - displacement(tb)).norm() / length <= bound);
            BOOST_TEST(so3::rotation_angle(rotation(ta).transpose() * rotation(tb)) <= bound);
            cold_iterations += a["newton_iterations"].get<int>();
            warm_iterations += b["newton_iterations"].get<int>();
        }
        // Used: the guess is within the order-p discretization error of the solution (≤ 4e-3 of
        // the scales here), where Newton converges quadratically, e → C e²: about three
        // corrections reach 1e-12 and one more evaluation accepts. 8 per load step leaves as much
        // again for damping or a constant C > 1. A step that refused its guess is stepped from
        // the last converged state instead, as the cold run is: 80 to 210 iterations in all.
        const int steps = static_cast<int>(cold["steps"].size());
        BOOST_TEST(warm_iterations <= 8 * steps);
        BOOST_TEST(warm_iterations < cold_iterations / 4);
    }
}

const Combination kEvery[] = {{"quaternion", "relative"},        {"quaternion", "direct"},
                              {"wiener-milenkovic", "relative"}, {"wiener-milenkovic", "direct"},
                              {"rodrigues", "relative"},         {"rodrigues", "direct"},
                              {"rotation-vector", "relative"},   {"rotation-vector", "direct"},
                              {"euler-angles", "relative"},      {"euler-angles", "direct"}};

}  // namespace

BOOST_AUTO_TEST_CASE(bend_warm_start_gives_the_cold_answer_in_fewer_iterations) {
    for (const Combination& c : kEvery) check_warm_start("bend-45", c, {}, 6);
}

BOOST_AUTO_TEST_CASE(rollup_warm_start_continues_the_chart_past_pi) {
    const Combination solved[] = {{"quaternion", "relative"},
                                  {"rotation-vector", "relative"},
                                  {"rotation-vector", "direct"},
                                  {"euler-angles", "relative"},
                                  {"euler-angles", "direct"}};
    for (const Combination& c : solved) {
        check_warm_start("cantilever-moment", c, {"analysis.load_factors=[2.0]"}, 7);
    }
}

namespace {

// The summed Newton iterations of the estimate's companions.
int companion_iterations(const json& result) {
    int n = 0;
    for (const json& c : result["estimate"]["companions"]) n += c["newton_iterations"].get<int>();
    return n;
}

// The largest error bound of the run's load steps: its states' scaled algebraic error, at least
// the Newton tolerance (docs/solver-convergence.md).
double largest_bound(const json& run, double newton) {
    double bound = newton;
    for (const json& s : run["steps"]) {
        bound = std::max(bound, s["convergence"]["error_bound"].get<double>());
    }
    return bound;
}

}  // namespace

// The estimate's companions (add_run_estimate, the path of `rotbeam run`) on the 45° bend's
// catalog mesh at its order 3: order 4 starts from the run's solved path, order 5 (the decay
// check) from order 4's. The estimate must be the cold companions' within the Newton tolerance,
// with the same reliability, for far fewer Newton iterations.
BOOST_AUTO_TEST_CASE(estimate_companions_start_from_the_run_and_from_each_other) {
    const Model model = load_case(std::string(ROTBEAM_SOURCE_DIR) + "/cases/bend-45.yaml", {},
                                  CaseParts::case_file);
    BOOST_TEST_REQUIRE(model.discretization.order == 3);
    SolvedPath path;
    RunRequest request{"", model};
    request.path = &path;
    const json run = run_case(request);
    BOOST_TEST_REQUIRE(has_solution(run["status"].get<std::string>()));
    json warm = run;
    add_run_estimate(request, warm);
    json cold = run;
    add_run_estimate(RunRequest{"", model}, cold);
    BOOST_TEST_REQUIRE(warm["estimate"]["status"] == "estimated");
    BOOST_TEST_REQUIRE(cold["estimate"]["status"] == "estimated");
    BOOST_TEST_REQUIRE(warm["estimate"]["companions"].size() == 2u);

    // Each estimate is a norm of differences between the run's value (the same in both) and
    // the companions' values (|q_p − q_p+1|, or the larger of that and |q_p − q_p+2|): it moves by
    // at most the largest change of a companion value. Each companion's state, warm or cold, is
    // within its error bound of the same discrete solution, so the two differ by at most the sum
    // of the bounds: 2 (cold and warm) × 2 companions × the largest bound, the bounds taken from
    // the same two companion runs made cold here (the warm ones stop at least as close: each
    // accepts only a state within its own bound, which the acceptance rule makes of the same
    // size). Displacements are scaled by the member length as the bounds are.
    Model p1 = model, p2 = model;
    p1.discretization.order = 4;
    p2.discretization.order = 5;
    const double newton =
        newton_settings_from(model.solver, model.analysis.statics).increment_tolerance;
    const double bound = 4.0 * std::max(largest_bound(run_case(RunRequest{"", p1}), newton),
                                        largest_bound(run_case(RunRequest{"", p2}), newton));
    const double length = estimate::reference_length(model);
    for (std::size_t k = 0; k < run["steps"].size(); ++k) {
        const json& a = cold["steps"][k]["estimate"];
        const json& b = warm["steps"][k]["estimate"];
        for (const auto& [point, quantities] : a.items()) {
            BOOST_TEST_CONTEXT("step " << k << ", " << point) {
                for (const char* q : {"displacement", "rotation"}) {
                    const double scale = std::string(q) == "displacement" ? length : 1.0;
                    const double ea = quantities[q]["error"].get<double>();
                    const double eb = b[point][q]["error"].get<double>();
                    BOOST_TEST(std::abs(ea - eb) / scale <= bound);
                    BOOST_TEST(quantities[q]["reliable"] == b[point][q]["reliable"]);
                }
            }
        }
    }
    // Warm-started: each companion's guess is within the order-3 (resp. 4) discretization
    // error of its solution, so each load step needs the few quadratically converging
    // corrections argued above (≤ 8); the cold companions step each load from the last
    // converged state with sub-steps.
    const int steps = static_cast<int>(run["steps"].size());
    const int warm_iterations = companion_iterations(warm);
    const int cold_iterations = companion_iterations(cold);
    BOOST_TEST_MESSAGE("companion Newton iterations: warm " << warm_iterations << ", cold "
                                                            << cold_iterations);
    BOOST_TEST(warm_iterations <= 2 * 8 * steps);
    BOOST_TEST(warm_iterations < cold_iterations / 4);
}
