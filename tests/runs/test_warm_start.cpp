// The warm start of a static run (core/nodal_field.hpp, docs/accuracy-control.md "Warm start"):
// a run of order p + 1 on one element started from the solved path of order p must give the
// answer of the same run started from the undeformed beam, within the Newton tolerance, in far
// fewer Newton iterations. Every parameterization with both rotation interpolations on the 45°
// bend (three load steps; the continued chart is not at stake), and the roll-up to λ = 2 (the tip
// turns 4π: the rotation vector and Euler angles keep parameters past π without rescaling, so the
// guess must continue their chart) with the combinations that solve it on one element at order 7
// (the others diverge there with or without a warm start, which is not what is tested here).
#define BOOST_TEST_MODULE rotbeam warm start
#include <boost/test/unit_test.hpp>
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
        const double newton = model.solver.increment_tolerance;
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
