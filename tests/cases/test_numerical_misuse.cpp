// Numerical misuse is reported, not absorbed: a tangent singular from the first load step stops
// the run with a status naming the step and the load factors; a member whose elements are too
// short for double arithmetic and two distinct points at one place are refused by the loader
// naming the keys and the numbers; a result that still holds a non-finite number says where
// (docs/solver-convergence.md, "A singular tangent"; docs/case-format.md, "Geometry that double
// precision resolves").
#include <boost/test/unit_test.hpp>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "core/non_finite.hpp"
#include "core/results.hpp"
#include "runs/run_case.hpp"
#include "tests/cases/catalog_model.hpp"

using namespace rotbeam;

namespace {

// A straight bar clamped at both ends, axially rigid (zero first compliance row), pushed
// sideways at its middle, in the mixed formulation: its axial force is statically indeterminate
// and no compliance fixes it, so the tangent is singular at every state and every load (a null
// vector: a constant axial force along the bar, which does no work against any deformation the
// section allows). Exactly, not to round-off: the kinematic rows of the rigid direction are
// differences of node displacements with coefficients ±1.
const char* const kRigidBar = R"(name: rigid-bar
points:
  root: [0, 0, 0]
  mid: [0.5, 0, 0]
  tip: [1, 0, 0]
sections:
  axially-rigid:
    compliance:
      - [0, 0, 0, 0, 0, 0]
      - [0, 3.0e-8, 0, 0, 0, 0]
      - [0, 0, 3.0e-8, 0, 0, 0]
      - [0, 0, 0, 1.0e-4, 0, 0]
      - [0, 0, 0, 0, 1.0e-4, 0]
      - [0, 0, 0, 0, 0, 2.5e-5]
members:
  left: {from: root, to: mid, section: axially-rigid, elements: 4}
  right: {from: mid, to: tip, section: axially-rigid, elements: 4}
constraints:
  root: clamped
  tip: clamped
loads:
  push: {point: mid, force: [0, 0, 1]}
analysis:
  type: static
  load_factors: [1.0]
discretization:
  formulation: mixed
  rotation: quaternion
)";

bool holds(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

// The loader's message for the tip-load cantilever with `overrides`, or "" when it is accepted.
std::string refusal(const std::vector<std::string>& overrides) {
    try {
        (void)test::catalog_model("tip-load-cantilever", overrides);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

}  // namespace

BOOST_AUTO_TEST_CASE(a_tangent_singular_at_the_first_step_stops_the_run_naming_the_step) {
    const Model model = load_case_text(kRigidBar, "rigid-bar.yaml");
    const nlohmann::json r = run_case(RunRequest{"rigid-bar.yaml", model});
    const std::string message = r["message"].get<std::string>();
    BOOST_TEST(r["status"] == "diverged");
    BOOST_TEST(holds(message, "at load step 1 (target load factor 1)"), message);
    BOOST_TEST(holds(message, "(singular tangent matrix); last converged load factor 0"), message);
    BOOST_TEST(r["steps"].empty());  // nothing was solved, nothing is reported
    BOOST_TEST(all_finite(r));
}

BOOST_AUTO_TEST_CASE(elements_below_the_smallest_resolved_length_are_refused_by_name) {
    // Absolute: 8 elements of 1.25e-156, below √DBL_MIN = 1.49e-154 (the audit's input, which
    // ended `error`, non-finite values, without naming the member).
    const std::string tiny = refusal({"points.tip=[1e-155,0,0]"});
    BOOST_TEST(holds(tiny,
                     "members.beam: length 1e-155 in 8 element(s) of 1.25e-156, below "
                     "1.49e-154 (sqrt of the smallest normal double"),
               tiny);
    BOOST_TEST(refusal({"points.tip=[1e-152,0,0]"}).empty());
    // Relative: next to coordinates of 1, √ε ≈ 1.49e-8 is the shortest element. 8 elements of
    // 1.25e-8 are refused, of 2.5e-8 accepted.
    const std::string close = refusal({"points.root=[1,0,0]", "points.tip=[1.0000001,0,0]"});
    BOOST_TEST(holds(close,
                     "members.beam: length 1e-07 in 8 element(s) of 1.25e-08, below "
                     "1.49e-08 (sqrt(eps) = 1.49e-08 of the largest coordinate 1,"),
               close);
    BOOST_TEST(refusal({"points.root=[1,0,0]", "points.tip=[1.0000002,0,0]"}).empty());
}

BOOST_AUTO_TEST_CASE(two_points_at_one_place_are_refused_naming_both) {
    // A second member ending at a point of its own, at the tip's place: not joined to the first.
    const std::vector<std::string> twin = {"points.tip2=[1,0,0]",
                                           "members.beam2={from: root, to: tip2, "
                                           "section: square, elements: 8}"};
    const std::string m = refusal(twin);
    BOOST_TEST(holds(m, ":--set: points.tip2: at the place of points.tip (the same coordinates)"),
               m);
    // 1e-6 apart at coordinates of 1 is two places.
    BOOST_TEST(refusal({"points.tip2=[1,0,1e-6]", twin[1]}).empty());
}

BOOST_AUTO_TEST_CASE(a_non_finite_result_names_where) {
    // Past the loader (the model edited after loading): elements of 1.25e-156, which end with
    // non-finite numbers in the displacement formulation.
    Model model = test::catalog_model("tip-load-cantilever", {});
    model.points[1].position = Vec3(1e-155, 0.0, 0.0);
    const nlohmann::json r = run_case(RunRequest{"tip-load-cantilever.yaml", model});
    const std::string message = r["message"].get<std::string>();
    BOOST_TEST(r["status"] == "error");
    BOOST_TEST(holds(message, "non-finite values in the solution, first at steps[0]."), message);
    BOOST_TEST(all_finite(r));
}

BOOST_AUTO_TEST_CASE(first_non_finite_gives_the_key_path) {
    nlohmann::json j = {{"a", 1.0}, {"steps", {{{"x", {0.0, 2.0}}}, {{"x", {0.0, NAN}}}}}};
    BOOST_TEST(first_non_finite(j) == "steps[1].x[1]");
    j["steps"][1]["x"][1] = 3.0;
    BOOST_TEST(first_non_finite(j).empty());
}
