// The full speed-versus-accuracy study's free-vibration references (studies/dynamic_speed.cpp:
// cases/free-vibration.yaml, 8 elements, 0–0.5 s, tip histories every 5 ms). Each is the finer of
// two fixed-step runs of the formulation's high-order scheme, used only when the two agree to
// kReferenceAgreement (1e-5) of the amplitude. The release from the static deflection puts ~1e-3
// of the tip rotation's amplitude into mesh modes at 1–40 kHz, which ring undamped for the whole
// window: a pair whose coarser step leaves them unresolved differs by their amplitude, whatever
// the scheme's order (125 / 62.5 µs: 1.1e-3, docs/studies.md). This checks that the problem's
// pairs resolve them, i.e. that the full study's free-vibration section has references at all.
// Minutes of CPU (the pairs are 10^5 and more steps; ~100 s and ~300 s): label long.
#include <boost/test/unit_test.hpp>
#include <stdexcept>

#include "studies/dynamic_speed.hpp"

using namespace rotbeam;
using namespace rotbeam::cli;

namespace {

// The problem's reference of `combination` ("displacement/quaternion"), computed (no cache).
ReferenceResponse full_reference(const std::string& combination) {
    const DynamicSpeedProblem p = dynamic_speed_problem("free_vibration", false);
    for (const Combination& c : p.combinations) {
        if (c.label() != combination) continue;
        return same_mesh_reference(c, p.window, p.coarse_step.at(c.formulation), "");
    }
    throw std::runtime_error("no combination " + combination);
}

void check_converged(const std::string& combination) {
    const ReferenceResponse r = full_reference(combination);
    BOOST_TEST_MESSAGE(r.how << ": the two steps differ by " << r.step_difference << " ("
                             << r.cpu_seconds << " s CPU)");
    BOOST_TEST(r.status == "converged", r.status);
    BOOST_TEST(r.step_difference <= kReferenceAgreement);
    BOOST_TEST(r.history.size() == 101u);  // 0, 5 ms, …, 0.5 s
}

}  // namespace

BOOST_AUTO_TEST_SUITE(free_vibration_references)

BOOST_AUTO_TEST_CASE(the_displacement_pair_resolves_the_modes_the_release_excites) {
    check_converged("displacement/quaternion");
}

BOOST_AUTO_TEST_CASE(the_mixed_pair_keeps_the_modes_radau_would_damp) {
    // Radau IIA damps the mixed mesh's 32.6 kHz pair (1.9e-4 of the tip rotation): its pair
    // agrees only once neither step damps it over the window (≈ 5 min CPU).
    check_converged("mixed/wiener-milenkovic");
}

BOOST_AUTO_TEST_SUITE_END()
