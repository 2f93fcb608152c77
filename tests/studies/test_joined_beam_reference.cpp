// The joined-beam dynamic references (studies/joined_beam_dynamics.hpp): the time error covers the
// joint's rotation as well as its displacement, and a reference whose two fixed-step runs do not
// agree to the requested fraction of the amplitude is refused, never used.
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "parameterizations/quaternion.hpp"
#include "parameterizations/wiener_milenkovic.hpp"
#include "studies/joined_beam_dynamics.hpp"
#include "studies/study_common.hpp"

using namespace rotbeam::cli;

namespace {

History straight_line(double slope) {
    History h;
    for (int i = 0; i <= 4; ++i) {
        const double t = 0.25 * i;
        h.time.push_back(t);
        h.x.push_back(0.0);
        h.y.push_back(0.0);
        h.z.push_back(slope * t);
    }
    return h;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(joined_beam_reference)

BOOST_AUTO_TEST_CASE(the_response_error_is_the_larger_of_displacement_and_rotation) {
    const JointResponse reference{straight_line(1.0), straight_line(2.0)};
    // Displacement off by 1 % of its amplitude at the end, rotation by 5 % of its amplitude.
    JointResponse u = reference;
    u.displacement.z.back() += 0.01;
    u.rotation.z.back() += 0.1;
    BOOST_TEST(response_error(u, reference) == 0.05, boost::test_tools::tolerance(1e-12));
    u.rotation = reference.rotation;
    BOOST_TEST(response_error(u, reference) == 0.01, boost::test_tools::tolerance(1e-12));
    // A rotation history on another output grid is never compared silently.
    u.rotation.time.back() = 1.5;
    BOOST_TEST(std::isnan(response_error(u, reference)));
}

BOOST_AUTO_TEST_CASE(a_reference_whose_two_steps_disagree_is_refused) {
    // The joined beam 0–10 ms, displacement/quaternion, Gauss–Legendre 3 at 1 ms and 0.5 ms: the
    // pair differs by far more than 1e-14 of the amplitude (the order-6 error of 1 ms steps on a
    // response whose 170–400 Hz modes are excited is ~1e-8 … 1e-5) and far less than 1.
    ResponseWindow w = quick_window();
    w.end_time = 0.01;
    w.output_interval = 0.001;
    const Combination c{rotbeam::Formulation::displacement,
                        rotbeam::param::id_of<rotbeam::param::Quaternion>()};
    const ReferenceResponse strict = same_mesh_reference(c, w, 1e-3, "", 1e-14);
    BOOST_TEST(strict.status.rfind("not converged", 0) == 0, strict.status);
    BOOST_TEST(strict.history.size() == 0u);
    BOOST_TEST(strict.step_difference > 1e-14);
    const ReferenceResponse loose = same_mesh_reference(c, w, 1e-3, "", 1.0);
    BOOST_TEST(loose.status == "converged");
    BOOST_TEST(loose.history.size() == 11u);
    BOOST_TEST(loose.rotation.size() == 11u);
    BOOST_TEST(loose.step_difference == strict.step_difference);
    BOOST_TEST(loose.step_difference < 1e-3);
}

// A TimeSetting's Newton tolerance reaches the time steps of both formulations: the displacement
// formulation's stage iteration (Gauss–Legendre 3) and the mixed formulation's Radau IIA, whose
// default is its own 1e-10 (core/dae_driver.hpp); fewer iterations when looser, the history
// within what the looser tolerance allows, and the result's options state the tolerance used.
// The joined beam 0–0.1 s at 1 ms: measured 1e-12 → 1e-7 takes Gauss–Legendre 3 from 630 to 330
// stage iterations over the 100 steps; asserted only fewer. The histories: each step's stages stop
// within the tolerance of the scaled increment (lengths by the model's length scale: the longest
// member, 1.12 m, in the displacement formulation, the total length, 2.24 m, in the mixed;
// rotations in rad), and the error left grows at most linearly over the 100 steps, so
// ≤ 100 × 1e-7 × 2.24 m = 2.2e-5 m; relative to the joint's largest displacement (0.27 m by
// 0.1 s) ≤ 8.3e-5, asserted ≤ 1e-4.
BOOST_AUTO_TEST_CASE(a_newton_tolerance_reaches_the_time_steps_of_both_formulations) {
    ResponseWindow w = quick_window();
    w.end_time = 0.1;
    w.output_interval = 0.01;
    struct Scheme {
        Combination combination;
        rotbeam::Integrator integrator;
        double default_tolerance;
    };
    const Scheme schemes[] = {
        {{rotbeam::Formulation::displacement, rotbeam::param::id_of<rotbeam::param::Quaternion>()},
         rotbeam::Integrator::gauss_legendre_3,
         1e-12},
        {{rotbeam::Formulation::mixed, rotbeam::param::id_of<rotbeam::param::WienerMilenkovic>()},
         rotbeam::Integrator::radau_iia_3,
         1e-10}};
    for (const Scheme& scheme : schemes) {
        const Combination& c = scheme.combination;
        BOOST_TEST_CONTEXT(c.label()) {
            TimeSetting tight{scheme.integrator, 1e-3, 0.0};
            TimeSetting loose = tight;
            loose.newton_tolerance = 1e-7;
            BOOST_TEST(loose.label() == "dt=0.001, newton=1e-07");
            const nlohmann::json a = run_spec(response_spec(c, tight, w));
            const nlohmann::json b = run_spec(response_spec(c, loose, w));
            BOOST_TEST(a.value("status", "") == "converged", a.value("message", ""));
            BOOST_TEST(b.value("status", "") == "converged", b.value("message", ""));
            BOOST_TEST(a["options"]["residual_tolerance"].get<double>() ==
                       scheme.default_tolerance);
            BOOST_TEST(b["options"]["residual_tolerance"].get<double>() == 1e-7);
            BOOST_TEST(b["options"]["increment_tolerance"].get<double>() == 1e-7);
            BOOST_TEST_MESSAGE(c.label() << " iterations: newton " << scheme.default_tolerance
                                         << " " << dynamic_newton_iterations(a) << ", 1e-7 "
                                         << dynamic_newton_iterations(b));
            BOOST_TEST(dynamic_newton_iterations(b) < dynamic_newton_iterations(a));
            const double moved = response_error(joint_response(b), joint_response(a));
            BOOST_TEST_MESSAGE(c.label() << " history moved by " << moved << " of its amplitude");
            BOOST_TEST(moved > 0.0);
            BOOST_TEST(moved <= 1e-4);
        }
    }
}

BOOST_AUTO_TEST_CASE(a_cached_reference_is_read_back_and_judged_by_the_agreement_asked) {
    // Written once, read back with the same histories; a stricter agreement refuses the cached
    // pair as it refuses a computed one.
    ResponseWindow w = quick_window();
    w.end_time = 0.005;
    w.output_interval = 0.001;
    const Combination c{rotbeam::Formulation::displacement,
                        rotbeam::param::id_of<rotbeam::param::Quaternion>()};
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / "rotbeam_test_joined_beam_reference";
    std::filesystem::remove_all(dir);
    const ReferenceResponse computed = same_mesh_reference(c, w, 1e-3, dir.string(), 1.0);
    const ReferenceResponse cached = same_mesh_reference(c, w, 1e-3, dir.string(), 1.0);
    BOOST_TEST(!computed.from_cache);
    BOOST_TEST(cached.from_cache);
    BOOST_TEST(cached.status == "converged");
    BOOST_TEST(cached.history.z == computed.history.z);
    BOOST_TEST(cached.rotation.y == computed.rotation.y);
    BOOST_TEST(cached.step_difference == computed.step_difference);
    const ReferenceResponse strict = same_mesh_reference(c, w, 1e-3, dir.string(), 1e-14);
    BOOST_TEST(strict.from_cache);
    BOOST_TEST(strict.status.rfind("not converged", 0) == 0, strict.status);
    BOOST_TEST(strict.history.size() == 0u);
    std::filesystem::remove_all(dir);
}

BOOST_AUTO_TEST_SUITE_END()
