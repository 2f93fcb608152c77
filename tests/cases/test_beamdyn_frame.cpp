// Results in BeamDyn's frame (runs/beamdyn_frame.hpp, `run --frame beamdyn`): the imported
// roll-up deck's tip, read from the result's `beamdyn` block exactly as BeamDyn prints TipTDxr …
// TipRDzr, against BeamDyn's own output (tests/data/beamdyn/bd_isotropic_rollup/bd_driver.out).
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "cases/loader/beamdyn_deck.hpp"
#include "cases/loader/case_loader.hpp"
#include "runs/beamdyn_frame.hpp"
#include "runs/run_case.hpp"
#include "tests/cases/beamdyn_output.hpp"

using namespace rotbeam;

namespace {

const std::string kDeck =
    std::string(ROTBEAM_SOURCE_DIR) + "/tests/data/beamdyn/bd_isotropic_rollup/";

Mat3 root_dcm(const cases::BeamDynDeck& deck) {
    Mat3 m;
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) {
            m(r, c) = deck.root_dcm[static_cast<std::size_t>(r)][static_cast<std::size_t>(c)];
        }
    }
    return m;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(beamdyn_frame)

BOOST_AUTO_TEST_CASE(wiener_milenkovic_parameters_are_four_tan_quarter_angle) {
    // A half turn about z: 4 tan(π/4) = 4; a tiny angle: the vector itself.
    const Vec3 c = wiener_milenkovic_of(Vec3(0, 0, std::acos(-1.0)));
    BOOST_TEST(c.z() == 4.0, boost::test_tools::tolerance(1e-15));
    BOOST_TEST(wiener_milenkovic_of(Vec3(1e-10, 0, 0)).x() == 1e-10);
}

// BeamDyn prints ES16.8E2 (9 significant digits) and every row of the roll-up is the same to all of
// them, so its stop_tol no longer shows: half a unit of the last printed digit (5e-9 on values of
// order 1 to 5) is the whole tolerance; rotbeam at BeamDyn's discretization is exact to 1e-12 on
// this deck (test_beamdyn_import.cpp). The comparison takes the `beamdyn` block as written, with
// no conversion in the test: TD against TipTD*, RD against TipRD*.
BOOST_AUTO_TEST_CASE(rollup_tip_in_beamdyns_frame_matches_its_printed_output) {
    const std::string driver = kDeck + "bd_driver.inp";
    RunRequest request;
    request.case_path = driver;
    request.model = load_case(driver);
    nlohmann::json r = run_case(request);
    add_beamdyn_frame(root_dcm(cases::read_beamdyn_deck(driver)), r);
    const auto bd = test::last_output_row(kDeck + "bd_driver.out");
    const nlohmann::json& tip = r["steps"].back()["beamdyn"]["points"]["tip"];
    const char* axes[] = {"xr", "yr", "zr"};
    for (int i = 0; i < 3; ++i) {
        const double td = tip["TD"][static_cast<std::size_t>(i)].get<double>();
        const double rd = tip["RD"][static_cast<std::size_t>(i)].get<double>();
        BOOST_TEST_CONTEXT(axes[i] << ": TD " << td << ", RD " << rd) {
            BOOST_TEST(std::abs(td - bd.at(std::string("TipTD") + axes[i])) <= 5e-9 + 1e-12);
            BOOST_TEST(std::abs(rd - bd.at(std::string("TipRD") + axes[i])) <= 5e-9 + 1e-12);
        }
    }
    BOOST_TEST(r["beamdyn_frame"]["dcm"][0][0].get<double>() == 1.0);
}

BOOST_AUTO_TEST_SUITE_END()
