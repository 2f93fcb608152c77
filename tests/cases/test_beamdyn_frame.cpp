// Results in BeamDyn's frame (runs/beamdyn_frame.hpp, `run --frame beamdyn`): the imported
// roll-up deck's tip, read from the result's `beamdyn` block exactly as BeamDyn prints TipTDxr …
// TipRDzr, against BeamDyn's own output (tests/data/beamdyn/bd_isotropic_rollup/bd_driver.out);
// the same columns in the result's CSV (steps_csv.hpp, history_csv.hpp) against the JSON block
// and BeamDyn's output.
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "cases/loader/beamdyn_deck.hpp"
#include "cases/loader/case_loader.hpp"
#include "runs/beamdyn_frame.hpp"
#include "runs/history_csv.hpp"
#include "runs/run_case.hpp"
#include "runs/steps_csv.hpp"
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

// A CSV file's columns by header name; a cell that is not a number (a stability assessment) reads
// as NaN, which equals nothing.
std::map<std::string, std::vector<double>> csv_columns(const std::string& text) {
    std::istringstream in(text);
    std::string line;
    std::getline(in, line);
    std::vector<std::string> names;
    std::istringstream header(line);
    for (std::string cell; std::getline(header, cell, ',');) names.push_back(cell);
    std::map<std::string, std::vector<double>> columns;
    while (std::getline(in, line)) {
        std::istringstream row(line);
        std::string cell;
        for (const std::string& name : names) {
            std::getline(row, cell, ',');
            char* end = nullptr;
            const double x = std::strtod(cell.c_str(), &end);
            const bool number = !cell.empty() && end == cell.c_str() + cell.size();
            columns[name].push_back(number ? x : std::nan(""));
        }
    }
    return columns;
}

// The result of a deck's driver with its `beamdyn` block.
nlohmann::json run_in_beamdyns_frame(const std::string& driver) {
    RunRequest request;
    request.case_path = driver;
    request.model = load_case(driver);
    nlohmann::json r = run_case(request);
    add_beamdyn_frame(root_dcm(cases::read_beamdyn_deck(driver)), r);
    return r;
}

// Every BeamDyn-frame column of a CSV equals the result's `beamdyn` block at every step: the CSV
// writes 17 significant digits, so a double reads back exactly (no tolerance). `group` is
// "points" or "reactions", `vectors` the block's two vectors per name.
void check_columns_equal_json(const std::map<std::string, std::vector<double>>& columns,
                              const nlohmann::json& steps, const std::string& group,
                              const std::vector<std::string>& vectors) {
    const nlohmann::json& first = steps[0]["beamdyn"][group];
    BOOST_TEST(!first.empty());
    for (const auto& [name, block] : first.items()) {
        for (const std::string& v : vectors) {
            for (std::size_t i = 0; i < 3; ++i) {
                const std::string column = name + "_" + v + "xyz"[i] + "r";
                BOOST_TEST_CONTEXT(column) {
                    BOOST_REQUIRE(columns.count(column) == 1);
                    const std::vector<double>& values = columns.at(column);
                    BOOST_REQUIRE(values.size() == steps.size());
                    for (std::size_t k = 0; k < steps.size(); ++k) {
                        BOOST_TEST(values[k] ==
                                   steps[k]["beamdyn"][group][name][v][i].get<double>());
                    }
                }
            }
        }
    }
}

// The result's `beamdyn` tip block as written (no conversion in the test: TD against TipTD*, RD
// against TipRD*) against the last row of BeamDyn's roll-up output, to half a unit of its last
// printed digit (argued at rollup_tip_in_beamdyns_frame_matches_its_printed_output).
void expect_beamdyns_printed_rollup_tip(const nlohmann::json& r) {
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
    const nlohmann::json r = run_in_beamdyns_frame(kDeck + "bd_driver.inp");
    expect_beamdyns_printed_rollup_tip(r);
    BOOST_TEST(r["beamdyn_frame"]["dcm"][0][0].get<double>() == 1.0);
}

// A root frame turned about x (GlbDCM rows (1, 0, 0), (0, 0.8, 0.6), (0, −0.6, 0.8): exact in
// decimal, a rotation to round-off) places the roll-up's blade along GlbDCMᵀ ẑ, while its tip
// moment about −x, a global vector, is the same vector in the turned root frame: the same problem
// turned. So the global tip displacement is GlbDCMᵀ times the unturned deck's, and the result in
// BeamDyn's frame (TD = GlbDCM u) is the unturned deck's, which BeamDyn printed: the root
// transform of the import and the frame of the output checked together. Tolerance: BeamDyn's
// printed digits as above (5e-9); rotbeam's two runs agree to round-off (1e-12 of |u|: the turned
// deck's equations are the unturned ones in rotated components).
BOOST_AUTO_TEST_CASE(turned_root_frame_gives_the_turned_answer_and_beamdyns_printed_tip) {
    const std::filesystem::path file =
        test::changed_driver(kDeck + "bd_driver.inp", "rotbeam-turned-rollup",
                             {{"0.0000000E+00  1.0000000E+00  0.0000000E+00",
                               "0.0000000E+00  8.0000000E-01  6.0000000E-01"},
                              {"0.0000000E+00  0.0000000E+00  1.0000000E+00",
                               "0.0000000E+00 -6.0000000E-01  8.0000000E-01"},
                              {"\"bd_primary.inp\"", "\"" + kDeck + "bd_primary.inp\""}});
    const nlohmann::json turned = run_in_beamdyns_frame(file.string());
    std::filesystem::remove(file);
    const nlohmann::json plain = run_in_beamdyns_frame(kDeck + "bd_driver.inp");
    Mat3 dcm;
    dcm << 1, 0, 0, 0, 0.8, 0.6, 0, -0.6, 0.8;
    const auto vec = [](const nlohmann::json& j) {
        return Vec3(j[0].get<double>(), j[1].get<double>(), j[2].get<double>());
    };
    const Vec3 u_turned = vec(turned["steps"].back()["points"]["tip"]["displacement"]);
    const Vec3 u_plain = vec(plain["steps"].back()["points"]["tip"]["displacement"]);
    BOOST_TEST_MESSAGE("turned root frame: tip u " << u_turned.transpose() << ", GlbDCMᵀ u_plain "
                                                   << (dcm.transpose() * u_plain).transpose());
    BOOST_TEST((u_turned - dcm.transpose() * u_plain).norm() <= 1e-12 * u_plain.norm());
    expect_beamdyns_printed_rollup_tip(turned);
    BOOST_TEST(turned["beamdyn_frame"]["dcm"][1][2].get<double>() == 0.6);
}

// The load steps' CSV of the roll-up carries tip_TDxr … tip_RDzr: equal to the JSON block at every
// step, and its last row against BeamDyn's printed TipTD*, TipRD* to the tolerance argued above.
BOOST_AUTO_TEST_CASE(rollup_csv_has_beamdyns_frame_columns) {
    const nlohmann::json r = run_in_beamdyns_frame(kDeck + "bd_driver.inp");
    const auto columns = csv_columns(steps_csv(r));
    check_columns_equal_json(columns, r["steps"], "points", {"TD", "RD"});
    const auto bd = test::last_output_row(kDeck + "bd_driver.out");
    for (const std::string v : {"TD", "RD"}) {
        for (const char* axis : {"xr", "yr", "zr"}) {
            const double csv = columns.at("tip_" + v + axis).back();
            BOOST_TEST_CONTEXT(v << axis << ": " << csv) {
                BOOST_TEST(std::abs(csv - bd.at("Tip" + v + axis)) <= 5e-9 + 1e-12);
            }
        }
    }
}

// A dynamic deck with a turning root (its steps carry reactions): the time history's CSV carries
// the points' TD, RD and the support's F, M in BeamDyn's frame, equal to the JSON block.
BOOST_AUTO_TEST_CASE(turning_deck_history_csv_has_beamdyns_frame_columns) {
    const nlohmann::json r = run_in_beamdyns_frame(std::string(ROTBEAM_SOURCE_DIR) +
                                                   "/tests/data/beamdyn/rotating-cantilever/"
                                                   "bd_driver.inp");
    BOOST_REQUIRE(r["steps"].size() > 1);
    const auto columns = csv_columns(history_csv(r));
    check_columns_equal_json(columns, r["steps"], "points", {"TD", "RD"});
    check_columns_equal_json(columns, r["steps"], "reactions", {"F", "M"});
}

BOOST_AUTO_TEST_SUITE_END()
