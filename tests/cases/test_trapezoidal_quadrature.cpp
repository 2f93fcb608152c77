// The displacement formulation's trapezoidal quadrature (BeamDyn's `quadrature = 2`,
// docs/displacement-formulation.md): where its points are (the stations and their divisions,
// BeamDyn's construction for the imported NREL 5-MW blade), and what it integrates: on a prismatic
// cantilever its answer tends to the Gauss one as refine⁻², the order measured.
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <string>
#include <vector>

#include "cases/loader/beamdyn_deck.hpp"
#include "cases/loader/beamdyn_import.hpp"
#include "cases/loader/case_loader.hpp"
#include "combinations/registry.hpp"
#include "core/errors.hpp"
#include "formulations/displacement/displacement_modal.hpp"
#include "formulations/displacement/mesh.hpp"
#include "runs/run_case.hpp"
#include "tests/cases/beamdyn_output.hpp"

using namespace rotbeam;

namespace {

// A prismatic cantilever along x, L = 10 m, EI = 100 N·m² (the BeamDyn cantilever deck's
// section), one element of order 5, a small dead tip force (linear range: tip deflection
// PL³/3EI = 0.333 m for P = 0.1 N, 3 % of L; the nonlinear part is the same for every rule).
const char* const kPrismatic = R"(name: trapezoid-prismatic
units: "m, N"
points:
  root: [0, 0, 0]
  tip: [10, 0, 0]
sections:
  s:
    stiffness:
      - [10000, 0, 0, 0, 0, 0]
      - [0, 10000, 0, 0, 0, 0]
      - [0, 0, 10000, 0, 0, 0]
      - [0, 0, 0, 200, 0, 0]
      - [0, 0, 0, 0, 100, 0]
      - [0, 0, 0, 0, 0, 100]
members:
  beam: {from: root, to: tip, section: s, elements: 1}
constraints:
  root: clamped
loads:
  tip-force: {point: tip, force: [0, 0, 0.1], frame: dead}
analysis:
  type: static
  load_factors: [1]
discretization:
  formulation: displacement
  order: 5
  quadrature: full
)";

double tip_deflection(const std::vector<std::string>& overrides) {
    RunRequest request;
    request.model = load_case_text(kPrismatic, "trapezoid-prismatic.yaml", overrides);
    const nlohmann::json r = run_case(request);
    const std::string status = r["status"].get<std::string>();
    BOOST_REQUIRE((status == "converged" || status == "stalled-at-round-off"));
    return r["steps"].back()["points"]["tip"]["displacement"][2].get<double>();
}

}  // namespace

BOOST_AUTO_TEST_SUITE(trapezoidal_quadrature)

// Gauss with p+1 points is exact here (constant section: the element integrands are polynomials
// of degree ≤ 2p ≤ 2(p+1) − 1), so the Gauss tip is the element's own answer and the trapezoid's
// difference from it is its quadrature error alone. The trapezoid is not exact on those
// polynomials: its error is a series in even powers of the division length L/r (Euler–Maclaurin),
// so the observed order log₂(e_r / e_2r) tends to 2. The degree-10 integrands make the higher
// terms large at small r: measured 0.36, 1.69, 1.92 for r = 8 → 16 → 32 → 64; from r = 64 on the
// order must lie within 0.05 of 2 (the r⁻⁴ term then moves it by less than 0.03).
BOOST_AUTO_TEST_CASE(prismatic_answer_tends_to_gauss_as_refine_squared) {
    const double gauss = tip_deflection({});
    BOOST_TEST(std::abs(gauss - 0.1 * 1000.0 / 300.0) < 0.01 * gauss);  // ≈ PL³/3EI
    const std::vector<int> refine = {8, 16, 32, 64, 128, 256};
    std::vector<double> errors;
    for (int r : refine) {
        errors.push_back(std::abs(tip_deflection({"discretization.quadrature=trapezoidal",
                                                  "discretization.refine=" + std::to_string(r)}) -
                                  gauss));
    }
    for (size_t i = 0; i + 1 < errors.size(); ++i) {
        const double order = std::log2(errors[i] / errors[i + 1]);
        BOOST_TEST_MESSAGE("refine " << refine[i] << ": |trapezoid - Gauss| = " << errors[i]
                                     << " m, observed order " << order);
        BOOST_TEST(errors[i + 1] < errors[i]);
        if (refine[i] >= 64) BOOST_TEST(std::abs(order - 2.0) < 0.05);
    }
    BOOST_TEST_MESSAGE("refine " << refine.back() << ": |trapezoid - Gauss| = " << errors.back());
}

// The imported NREL 5-MW blade (one member, 49 stations, order 5, refine DEFAULT = 1): BeamDyn's
// BD_TrapezoidalPointWeight puts the points at ξ_j = 2 η_j − 1 with weights (ξ_{j+1} − ξ_{j−1})/2
// (halved at the ends), times the Jacobian L/2 of the straight member: point j at s = η_j L with
// weight (η_{j+1} − η_{j−1}) L / 2. rotbeam's mesh of the imported case has exactly those, and the
// consistent mass rule the same points.
BOOST_AUTO_TEST_CASE(imported_5mw_points_are_beamdyns_stations) {
    const cases::BeamDynDeck deck =
        cases::read_beamdyn_deck(test::kBeamDynDecks + "bd_5MW_dynamic/bd_driver.inp");
    BOOST_TEST_REQUIRE(deck.stations.size() == 49u);
    const Model model = load_case(test::kBeamDynDecks + "bd_5MW_dynamic/bd_driver.inp");
    BOOST_TEST_REQUIRE((model.discretization.quadrature == Quadrature::trapezoidal));
    BOOST_TEST(model.discretization.refine == 1);
    const form::Mesh mesh = form::build_mesh(model);
    BOOST_TEST_REQUIRE(mesh.elements.size() == 1u);
    const auto& qp = mesh.elements[0].qp;
    BOOST_TEST_REQUIRE(qp.size() == 49u);
    const double L = 61.5;  // the last key point's z
    const auto& st = deck.stations;
    for (size_t j = 0; j < qp.size(); ++j) {
        const double lo = st[j == 0 ? 0 : j - 1].eta;
        const double hi = st[j + 1 == st.size() ? j : j + 1].eta;
        BOOST_TEST_CONTEXT("point " << j + 1) {
            // Round-off of s/L → ξ → s: a few ulp of L.
            BOOST_TEST(std::abs(qp[j].s - st[j].eta * L) < 1e-13 * L);
            BOOST_TEST(std::abs(qp[j].weight - 0.5 * (hi - lo) * L) < 1e-13 * L);
        }
    }
    const form::Mesh mass = form::build_mass_mesh(model);
    BOOST_TEST(mass.elements[0].qp.size() == 49u);
}

// Refine r divides every station interval: (49 − 1) r + 1 points; with several elements each
// one gets its ends and the stations inside, and too few points for an element's nodes is
// refused naming the key.
BOOST_AUTO_TEST_CASE(refine_divides_station_intervals_and_too_few_points_are_refused) {
    const std::string deck = test::kBeamDynDecks + "bd_5MW_dynamic/bd_driver.inp";
    const form::Mesh refined = form::build_mesh(load_case(deck, {"discretization.refine=3"}));
    BOOST_TEST(refined.elements[0].qp.size() == 48u * 3u + 1u);
    const form::Mesh four = form::build_mesh(load_case(deck, {"members.*.elements=4"}));
    size_t points = 0;
    for (const auto& e : four.elements) points += e.qp.size();
    // Every station once, plus the element ends that are not stations, shared ends twice.
    BOOST_TEST(points >= 49u + 3u);
    std::string message;
    try {
        form::build_mesh(load_case(deck, {"members.*.elements=16"}));
    } catch (const InputError& e) {
        message = e.what();
    }
    BOOST_TEST(message.find("discretization.quadrature: trapezoidal") != std::string::npos);
    BOOST_TEST(message.find("raise discretization.refine") != std::string::npos);
}

// The two NREL 5-MW decks (tests/data/beamdyn: a blade turning at 1.0006 rad/s about x, and the
// same blade at rest under gravity along −y) import with trapezoidal quadrature and run in every
// parameterization of both formulations, shortened to 10 of BeamDyn's steps (the full 30 s are
// docs/beamdyn-import.md's measurement). The mixed formulation has no trapezoidal rule (the
// description says it ignores it) and no generalized-α (its trapezoidal scheme runs); it carries
// the decks' stiffness-proportional damping (damp_type 1, mu ≠ 0) as the displacement formulation
// does (formulations/mixed/mixed_damping.hpp).
BOOST_AUTO_TEST_CASE(nrel_5mw_decks_run_in_every_parameterization) {
    for (const char* name : {"bd_5MW_dynamic", "bd_5MW_dynamic_gravity_Az00"}) {
        const std::string deck = test::kBeamDynDecks + name + "/bd_driver.inp";
        const std::string text = cases::import_beamdyn(deck);
        BOOST_TEST_CONTEXT(name) {
            BOOST_TEST(text.find("  quadrature: trapezoidal\n  refine: 1\n") != std::string::npos);
            BOOST_TEST(text.find("the mixed formulation ignores it") != std::string::npos);
        }
        const double step = load_case(deck).analysis.dynamics.time_step;
        for (const comb::Combination& c : comb::all_combinations(false)) {
            std::vector<std::string> shortened = {
                "discretization.formulation=" + c.formulation_name(),
                "discretization.rotation=" + c.rotation_name(),
                "analysis.end_time=" + std::to_string(10 * step)};
            BOOST_TEST_CONTEXT(name << " " << c.label()) {
                if (c.formulation == Formulation::mixed) {
                    shortened.push_back("analysis.integrator=trapezoidal");  // no generalized-α
                }
                RunRequest request;
                request.model = load_case(deck, shortened);
                const nlohmann::json r = run_case(request);
                BOOST_TEST((r["status"].get<std::string>() == "converged" ||
                            r["status"].get<std::string>() == "stalled-at-round-off"));
                const auto& tip = r["steps"].back()["points"]["tip"]["displacement"];
                BOOST_TEST(std::isfinite(tip[0].get<double>()));
            }
        }
    }
}

BOOST_AUTO_TEST_SUITE_END()
