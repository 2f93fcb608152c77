// The kinetic (Ziegler) criterion of static equilibria without a potential
// (core/static_stability_kinetic.hpp): the eigenvalues of the linearized free motion
// M q̈ + K q = 0 about the converged state, read per load step by `rotbeam run`: Beck's column
// against its closed-form flutter load, and a conservative load assessed both ways.
#define BOOST_TEST_MODULE rotbeam kinetic stability
#include <boost/test/unit_test.hpp>
#include <string>
#include <vector>

#include "cases/loader/case_loader.hpp"
#include "core/static_driver.hpp"
#include "core/static_stability_kinetic.hpp"
#include "runs/make_problem.hpp"
#include "runs/run_case.hpp"

using namespace rotbeam;

namespace {

nlohmann::json run_kinetic_case(const std::string& case_name, const std::vector<std::string>& set) {
    const std::string path = std::string(ROTBEAM_SOURCE_DIR) + "/cases/" + case_name + ".yaml";
    return run_case(RunRequest{path, load_case(path, set, CaseParts::case_file)});
}

const char* const kKineticRotations[] = {"quaternion", "wiener-milenkovic", "rodrigues",
                                         "rotation-vector", "euler-angles"};

// The tip-load cantilever (cases/tip-load-cantilever.yaml: steel, L = 1 m, square 0.01 m,
// EI = 175 N m²) with steel's density, 8 elements of order 4 and a compressive tip force P along
// the beam (dead or follower).
std::vector<std::string> column_with_mass(double P, const std::string& frame) {
    return {"loads.tip-force.force=[-" + std::to_string(P) + ",0,0]",
            "loads.tip-force.frame=" + frame, "sections.square.density=7850",
            "discretization.order=4", "analysis.load_factors=[0.5,1.0]"};
}

}  // namespace

BOOST_AUTO_TEST_SUITE(kinetic_stability)

// Beck's column: a clamped–free column under a compressive follower tip force loses stability by
// flutter at P_cr = 20.05 EI/L² (Beck 1952; Euler–Bernoulli, uniform mass) = 3509 N here, with
// no divergence before it (its straight state has no adjacent equilibrium). The discrete model
// differs from that continuum by its frequency error (8 × p4: within 2.7e-5 of the Timoshenko
// beam's, tests/displacement/test_modal.cpp) and by shear and rotary inertia (EI/(κGA L²) =
// 2.6e-5, ρI/(ρA L²) = 8.3e-6; shear lowers the flutter load): measured by bisection, the model
// flutters between 0.9992 and 0.9994 P_cr (docs/solver-convergence.md, No potential). The bracket
// ±1 % leaves more than ten times that difference.
// Below: every step `stable` by the kinetic criterion; above: `unstable`, the run's status
// `unstable-equilibrium`, one fluttering mode per bending plane (square section: two), none
// divergent, its growth rate far above its error estimate.
BOOST_AUTO_TEST_CASE(beck_column_flutters_above_its_critical_load_only) {
    const double critical = 20.05 * 175.0;
    const nlohmann::json below =
        run_kinetic_case("tip-load-cantilever", column_with_mass(0.99 * critical, "follower"));
    BOOST_TEST_REQUIRE(has_solution(below["status"].get<std::string>()), below["message"]);
    for (const auto& step : below["steps"]) {
        BOOST_TEST_MESSAGE("0.99 P_cr, λ " << step["load_factor"] << ": " << step["stability"]);
        BOOST_TEST(step["stability"]["assessment"] == "stable");
        BOOST_TEST(step["stability"]["criterion"] == "kinetic");
        BOOST_TEST(step["stability"]["kinetic"]["modes"] == kKineticModes);
    }
    const nlohmann::json above =
        run_kinetic_case("tip-load-cantilever", column_with_mass(1.01 * critical, "follower"));
    BOOST_TEST_MESSAGE("1.01 P_cr: " << above["steps"].back()["stability"]);
    BOOST_TEST(above["status"] == kUnstableEquilibrium, above["message"]);
    BOOST_TEST(above["steps"][0]["stability"]["assessment"] == "stable");
    const nlohmann::json& last = above["steps"].back()["stability"];
    BOOST_TEST(last["assessment"] == "unstable");
    BOOST_TEST(last["criterion"] == "kinetic");
    BOOST_TEST(last["kinetic"]["fluttering"] == 2);
    BOOST_TEST(last["kinetic"]["divergent"] == 0);
    BOOST_TEST(last["kinetic"]["growth_rate"].get<double>() >
               1e3 * last["kinetic"]["growth_rate_error"].get<double>());
}

// A conservative load assessed both ways: the dead compressive force on the straight column has
// the Euler load P_E = π² EI/(4 L²) = 431.8 N, doubled by the square section, the second at 9 P_E.
// At 300 N the energy criterion reads `stable` and no kinetic eigenvalue grows; at 1000 N the
// Hessian has two negative eigenvalues (tests/runs/test_static_stability.cpp) and the linearized
// motion two divergent modes (real s > 0), no flutter (a symmetric K has real ω²) — in every
// parameterization.
BOOST_AUTO_TEST_CASE(energy_and_kinetic_criteria_agree_on_the_euler_column) {
    for (const char* rotation : kKineticRotations) {
        for (const double P : {300.0, 1000.0}) {
            std::vector<std::string> set = column_with_mass(P, "dead");
            set.push_back(std::string("discretization.rotation=") + rotation);
            set.push_back("analysis.load_factors=[1.0]");
            const std::string path =
                std::string(ROTBEAM_SOURCE_DIR) + "/cases/tip-load-cantilever.yaml";
            const Model model = load_case(path, set, CaseParts::case_file);
            std::unique_ptr<StaticProblem> problem = make_static_problem(model);
            NewtonSettings settings;
            settings.assess_stability = true;
            StaticStability energy;
            const StaticOutcome out =
                run_static(*problem, {1.0}, settings,
                           [&](const StepRecord& step) { energy = step.stability; });
            BOOST_TEST_REQUIRE(has_solution(out.status), out.message);
            auto* system = dynamic_cast<KineticSystem*>(problem.get());
            BOOST_TEST_REQUIRE(system != nullptr);
            const StaticStability kinetic =
                assess_kinetic_stability(system->kinetic_spectrum(kKineticModes));
            BOOST_TEST_MESSAGE(rotation << ", P = " << P << " N: energy "
                                        << to_string(energy.assessment) << " (" << energy.negative
                                        << "), kinetic " << to_string(kinetic.assessment) << " ("
                                        << kinetic.negative << ") " << kinetic.reason);
            BOOST_TEST((energy.criterion == StaticStability::Criterion::energy), rotation);
            BOOST_TEST((kinetic.criterion == StaticStability::Criterion::kinetic), rotation);
            BOOST_TEST_REQUIRE(kinetic.kinetic.has_value());
            const bool buckled = P > 2.0 * 431.8;
            BOOST_TEST((energy.assessment == (buckled ? StaticStability::Assessment::unstable
                                                      : StaticStability::Assessment::stable)),
                       rotation);
            BOOST_TEST((kinetic.assessment == energy.assessment), rotation);
            BOOST_TEST(energy.negative == (buckled ? 2 : 0), rotation);
            BOOST_TEST(kinetic.kinetic->divergent == energy.negative, rotation);
            BOOST_TEST(kinetic.kinetic->fluttering == 0, rotation);
        }
    }
}

BOOST_AUTO_TEST_SUITE_END()
