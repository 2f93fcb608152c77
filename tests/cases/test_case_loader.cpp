// Loader: the catalog loads and means what docs/benchmarks.md says, --set overrides are applied
// and validated like the file, describe_model names what `rotbeam check` must show.
#include <algorithm>
#include <boost/test/unit_test.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "cases/loader/case_loader.hpp"
#include "cases/loader/yaml_reader.hpp"
#include "core/errors.hpp"
#include "core/geometry.hpp"
#include "parameterizations/registry.hpp"
#include "tests/cases/input_error.hpp"

using namespace rotbeam;

namespace {

std::string case_path(const std::string& name) {
    return std::string(ROTBEAM_SOURCE_DIR) + "/cases/" + name + ".yaml";
}

using test::input_error;

const ReferenceValue& reference(const Model& m, const std::string& id) {
    const auto it = std::find_if(m.references.begin(), m.references.end(),
                                 [&](const ReferenceValue& r) { return r.id == id; });
    BOOST_REQUIRE(it != m.references.end());
    return *it;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(case_loader)

BOOST_AUTO_TEST_CASE(every_catalog_case_loads_and_names_its_points) {
    const std::vector<std::string> catalog = {"cantilever-moment",
                                              "cantilever-moment-4",
                                              "bend-45",
                                              "joined-beam",
                                              "joined-beam-dead",
                                              "joined-beam-follower",
                                              "blade-mh104",
                                              "helix",
                                              "helix-precessing",
                                              "tip-load-cantilever",
                                              "free-vibration",
                                              "nrel5mw-gravity",
                                              "nrel5mw-rotating",
                                              "beamdyn-cantilever-gravity",
                                              "beamdyn-curved-beam",
                                              "beamdyn-distributed-load",
                                              "beamdyn-quadratic-twist",
                                              "beamdyn-rollup",
                                              "beamdyn-rotating-cantilever",
                                              "beamdyn-twisted-beam"};
    for (const std::string& name : catalog) {
        BOOST_TEST_CONTEXT(name) {
            const Model m = load_case(case_path(name));
            BOOST_TEST(m.name == name);
            const bool joined = name.rfind("joined-beam", 0) == 0;
            BOOST_TEST(m.point_index(joined ? "joint" : "tip") >= 0);
            if (!joined) BOOST_TEST(m.point_index("root") >= 0);
            BOOST_TEST(!describe_model(m).empty());
        }
    }
    // Every *.yaml in cases/ is in the catalog list above (a new case gets a test line).
    for (const auto& entry :
         std::filesystem::directory_iterator(std::string(ROTBEAM_SOURCE_DIR) + "/cases")) {
        if (entry.path().extension() != ".yaml") continue;
        BOOST_TEST((std::find(catalog.begin(), catalog.end(), entry.path().stem().string()) !=
                    catalog.end()),
                   entry.path().filename().string() << " is not in the catalog test");
    }
}

BOOST_AUTO_TEST_CASE(cantilever_moment_is_table_one) {
    const Model m = load_case(case_path("cantilever-moment"));
    BOOST_TEST(m.members.size() == 1u);
    BOOST_TEST(m.members[0].elements == 16);
    // EI = E·I2 = 30e6/12 = 2.5e6; the unit moment is −πEI/L e_y with L = 12.
    const Mat6 K = *m.members[0].sections[0].section.stiffness;
    BOOST_TEST(K(4, 4) == 2.5e6, boost::test_tools::tolerance(1e-14));
    BOOST_TEST(K(1, 1) == 5.0 / 6.0 * 30e6 / 2.6, boost::test_tools::tolerance(1e-14));
    BOOST_TEST(m.point_loads.at(0).moment.y() == -kPi * 2.5e6 / 12.0,
               boost::test_tools::tolerance(1e-15));
    // Table I: 6 analytical + 7 converged GEBT entries gated, 2 non-converged recorded.
    BOOST_TEST(m.references.size() == 15u);
    const auto gated = std::count_if(m.references.begin(), m.references.end(),
                                     [](const ReferenceValue& r) { return r.gated; });
    BOOST_TEST(gated == 13);
    BOOST_TEST(!reference(m, "gebt-wm-1p96").gated);
    BOOST_TEST(!reference(m, "gebt-rodrigues-1p0").gated);
    const ReferenceValue& r = reference(m, "gebt-wm-1p2");
    BOOST_TEST(r.applies_to.at("rotation") == "wiener-milenkovic");
    BOOST_TEST(r.applies_to.at("elements") == "16");
    BOOST_TEST((r.components == std::vector<int>{0, 2}));
    BOOST_TEST(r.value.at(0) == -13.8800);
}

// The gate's data: the exact column is checked with every combination (displacement at order 4,
// mixed through `also`), and the stops of Rodrigues and WM are declared beside the numbers.
BOOST_AUTO_TEST_CASE(cantilever_moment_declares_its_checks_and_expected_stops) {
    const Model m = load_case(case_path("cantilever-moment"));
    const ReferenceValue& exact = reference(m, "exact-0p4");
    BOOST_TEST(exact.applies_to.at("formulation") == "displacement");
    BOOST_TEST(!exact.scope.empty());
    BOOST_REQUIRE(exact.also.size() == 1u);
    BOOST_TEST(exact.also[0].applies_to.at("formulation") == "mixed");
    BOOST_TEST(exact.also[0].tolerance > exact.tolerance);
    BOOST_TEST(reference(m, "gebt-wm-1p6").applies_to.at("wm_map") == "plain");
    BOOST_TEST(m.expected_stops.size() == 5u);
    const auto stop = std::find_if(m.expected_stops.begin(), m.expected_stops.end(),
                                   [](const ExpectedStop& s) { return s.id == "mixed-wm-plain"; });
    BOOST_REQUIRE(stop != m.expected_stops.end());
    BOOST_TEST(stop->status == "diverged");
    BOOST_TEST(*stop->reaches == 1.6);
    BOOST_TEST(stop->stops_before == 1.96);
    BOOST_TEST(stop->applies_to.at("rotation") == "wiener-milenkovic");
}

// A status is data (any name a run may end with), but a stop must name a reported step, stop
// after what it reaches, and not be "converged"; a narrowed applies_to needs its scope.
BOOST_AUTO_TEST_CASE(expected_stops_and_narrowed_references_are_validated) {
    std::ifstream in(case_path("cantilever-moment"));
    std::stringstream buffer;
    buffer << in.rdbuf();
    const std::string text = buffer.str();
    auto with_stop = [&](const std::string& body) {
        return text +
               "expected_stops:\n  s:\n    applies_to: {formulation: mixed, rotation: "
               "rodrigues}\n    scope: why\n    justification: why\n" +
               body;
    };
    const Model m = load_case_text(
        with_stop("    reaches: 0.8\n    stops_before: 1.0\n    status: some-new-status\n"),
        "t.yaml");
    BOOST_TEST(m.expected_stops.at(0).status == "some-new-status");
    const std::string off = input_error([&] {
        load_case_text(with_stop("    stops_before: 0.9\n    status: diverged\n"), "t.yaml");
    });
    BOOST_TEST(off.find("expected_stops.s.stops_before: is not one of analysis.load_factors") !=
                   std::string::npos,
               off);
    const std::string order = input_error([&] {
        load_case_text(with_stop("    reaches: 1.0\n    stops_before: 0.8\n    status: diverged\n"),
                       "t.yaml");
    });
    BOOST_TEST(order.find("must be below stops_before") != std::string::npos, order);
    const std::string converged = input_error([&] {
        load_case_text(with_stop("    stops_before: 1.0\n    status: converged\n"), "t.yaml");
    });
    BOOST_TEST(converged.find("must name the status of a run that stops") != std::string::npos,
               converged);
    const std::string scope = input_error([&] {
        load_case_text(text +
                           "references:\n  r:\n    quantity: displacement\n    point: tip\n"
                           "    load_factor: 0.4\n    value: [0, 0, 0]\n    tolerance: 1\n"
                           "    justification: j\n    source: s\n"
                           "    applies_to: {rotation: quaternion}\n",
                       "t.yaml");
    });
    BOOST_TEST(scope.find("references.r.applies_to: names a combination") != std::string::npos,
               scope);
    const std::string none = input_error([&] {
        load_case_text(text +
                           "references:\n  r:\n    quantity: displacement\n    point: tip\n"
                           "    load_factor: 0.4\n    value: [0, 0, 0]\n    tolerance: 1\n"
                           "    justification: j\n    source: s\n    scope: s\n"
                           "    applies_to: {formulation: mixed, interpolation: direct}\n",
                       "t.yaml");
    });
    BOOST_TEST(none.find("no combination is selected") != std::string::npos, none);
}

// applies_to names the trapezoidal rule's refine like any discretization key: read as the number,
// and the override the gate makes of it (discretization.<key>=<value>, verify_plan.cpp) loads.
BOOST_AUTO_TEST_CASE(applies_to_names_the_trapezoidal_refine) {
    std::ifstream in(case_path("cantilever-moment"));
    std::stringstream buffer;
    buffer << in.rdbuf();
    const Model m =
        load_case_text(buffer.str() +
                           "references:\n  r:\n    quantity: displacement\n"
                           "    point: tip\n    load_factor: 0.4\n    value: [0, 0, 0]\n"
                           "    tolerance: 1\n    justification: j\n    source: s\n"
                           "    applies_to: {quadrature: trapezoidal, refine: 4}\n",
                       "t.yaml");
    BOOST_TEST(m.references.at(0).applies_to.at("refine") == "4");
    const Model refined =
        load_case(case_path("cantilever-moment"),
                  {"discretization.quadrature=trapezoidal",
                   "discretization.refine=" + m.references.at(0).applies_to.at("refine")});
    BOOST_TEST(refined.discretization.refine == 4);
}

BOOST_AUTO_TEST_CASE(bend45_is_the_exact_arc_with_a_unit_tip_force) {
    const Model m = load_case(case_path("bend-45"));
    const ReferenceGeometry g(m, 0);
    BOOST_TEST(std::abs(g.length() - 25.0 * kPi) < 1e-4);
    BOOST_TEST((m.point_loads.at(0).force - Vec3::UnitZ()).norm() == 0.0);
    BOOST_TEST((m.analysis.statics.load_factors == std::vector<double>{300, 450, 600}));
    BOOST_TEST(reference(m, "table-ii-600").tolerance >= 0.3);
}

BOOST_AUTO_TEST_CASE(joined_beam_has_table_three_at_the_papers_mesh) {
    const Model m = load_case(case_path("joined-beam"));
    BOOST_TEST(m.members.size() == 2u);
    BOOST_TEST((m.analysis.kind == AnalysisKind::modal));
    BOOST_TEST(m.references.size() == 10u);
    const ReferenceValue& g1 = reference(m, "gebt-mode-1");
    BOOST_TEST(g1.value.at(0) == 35.23);
    BOOST_TEST(g1.relative);
    BOOST_TEST(g1.applies_to.at("elements") == "10");
    // ρA = 13.5 kg/m and rotary inertia about e1 = ρ(I2 + I3).
    const Mat6 M = *m.members[0].sections[0].section.mass;
    BOOST_TEST(M(0, 0) == 13.5, boost::test_tools::tolerance(1e-14));
    BOOST_TEST(M(3, 3) == 2700.0 * (1.0416666666666667e-6 + 4.166666666666667e-6),
               boost::test_tools::tolerance(1e-14));
    const Model f = load_case(case_path("joined-beam-follower"));
    BOOST_TEST(f.has_follower_loads());
    BOOST_TEST(f.point_loads.at(0).time(kPi / 40.0) == 1.0, boost::test_tools::tolerance(1e-15));
}

BOOST_AUTO_TEST_CASE(blade_keeps_the_fully_populated_matrices) {
    const Model m = load_case(case_path("blade-mh104"));
    const Section& s = m.members[0].sections[0].section;
    BOOST_TEST((*s.stiffness)(0, 5) == -4.736e8);
    BOOST_TEST((*s.mass)(5, 0) == -71.6871);
    BOOST_TEST((s.compliance * *s.stiffness - Mat6::Identity()).norm() < 1e-10);
}

BOOST_AUTO_TEST_CASE(precessing_helix_takes_160_equal_steps_to_four_pi) {
    const Model m = load_case(case_path("helix-precessing"));
    const StaticSettings& s = m.analysis.statics;
    BOOST_TEST(s.load_factors.size() * static_cast<size_t>(s.substeps) >= 160u);
    BOOST_TEST(s.load_factors.back() == 4.0 * kPi, boost::test_tools::tolerance(1e-15));
}

BOOST_AUTO_TEST_CASE(overrides_set_values_lists_and_new_keys) {
    const Model m = load_case(
        case_path("cantilever-moment"),
        {"discretization.order=6", "members.beam.elements=8", "analysis.load_factors=[0.4,2]",
         "loads.tip-moment.frame=follower", "discretization.rotation=rodrigues"});
    BOOST_TEST(m.discretization.order == 6);
    BOOST_TEST(m.members[0].elements == 8);
    BOOST_TEST((m.analysis.statics.load_factors == std::vector<double>{0.4, 2.0}));
    BOOST_TEST(m.has_follower_loads());
    BOOST_TEST((m.discretization.rotation == param::id_of<param::Rodrigues>()));
    // A key absent from the file (and a section absent from the file) can be set.
    const Model t = load_case(
        case_path("tip-load-cantilever"),
        {"solver.max_iterations=7", "gravity=[0,0,-9.81]", "sections.square.density=7850"});
    BOOST_TEST(t.solver.max_iterations == 7);
    BOOST_TEST(t.gravity.z() == -9.81);
    // List items are addressed by index.
    const Model b = load_case(case_path("blade-mh104"), {"sections.mh104.mass.4.4=3.0"});
    BOOST_TEST((*b.members[0].sections[0].section.mass)(4, 4) == 3.0);
    BOOST_TEST(!input_error([&] {
                    load_case(case_path("blade-mh104"), {"sections.mh104.mass.6=[1]"});
                }).empty());
}

BOOST_AUTO_TEST_CASE(overrides_are_validated_like_the_file) {
    const std::string path = case_path("cantilever-moment");
    const std::string order = input_error([&] { load_case(path, {"discretization.order=0"}); });
    BOOST_TEST(order == path + ":--set: discretization.order: must be a positive integer, got '0'");
    const std::string typo = input_error([&] { load_case(path, {"discretization.ordr=3"}); });
    BOOST_TEST(typo.find("discretization.ordr: unknown key; did you mean 'order'?") !=
               std::string::npos);
    const std::string rotation =
        input_error([&] { load_case(path, {"discretization.rotation=rodriguez"}); });
    BOOST_TEST(rotation.find("did you mean 'rodrigues'?") != std::string::npos);
    BOOST_TEST(!input_error([&] { load_case(path, {"no-equals-sign"}); }).empty());
    BOOST_TEST(!input_error([&] { load_case(path, {"analysis.load_factors=[1, nan]"}); }).empty());
    BOOST_TEST(!input_error([&] { load_case(path, {"members.beam.elements.x=1"}); }).empty());
    // Gravity needs inertia: a section without mass is refused, naming the section.
    const std::string mass = input_error([&] { load_case(path, {"gravity=[0,0,-1]"}); });
    BOOST_TEST(mass.find("sections.square: needs mass or density") != std::string::npos, mass);
}

// Each formulation's options (core/model.hpp, DisplacementOptions and MixedOptions) are read into
// its own struct; a key of the other formulation is refused naming the key, whether the file or
// an override chose the formulation.
BOOST_AUTO_TEST_CASE(options_of_the_other_formulation_are_refused) {
    const std::string path = case_path("cantilever-moment");
    const Model d =
        load_case(path, {"discretization.interpolation=direct", "discretization.update=additive",
                         "discretization.rescale=false", "discretization.mass_rule=lumped",
                         "solver.mip=true"});
    BOOST_TEST((d.discretization.displacement.interpolation == Interpolation::direct));
    BOOST_TEST((d.discretization.displacement.update == Update::additive));
    BOOST_TEST(!d.discretization.displacement.rescale);
    BOOST_TEST((d.discretization.mass_rule() == MassRule::lumped));
    BOOST_TEST(d.discretization.displacement.mip);
    const Model m = load_case(
        path, {"discretization.formulation=mixed", "discretization.rotation=wiener-milenkovic",
               "discretization.wm_map=continuous", "discretization.mass_rule=midpoint"});
    BOOST_TEST((m.discretization.mixed.wm_map == WmMap::continuous));
    BOOST_TEST((m.discretization.mass_rule() == MassRule::midpoint));
    BOOST_TEST((m.discretization.displacement.mass_rule == MassRule::consistent));
    // The WM map with another rotation (here the case's quaternion) would be ignored: refused,
    // whether the file or an override chose the rotation.
    const std::string map = input_error([&] {
        load_case(path, {"discretization.formulation=mixed", "discretization.wm_map=plain"});
    });
    BOOST_TEST(map == path +
                          ":--set: discretization.wm_map: not an option of rotation 'quaternion' "
                          "(an option of rotation wiener-milenkovic)");

    const std::string interpolation = input_error([&] {
        load_case(path,
                  {"discretization.formulation=mixed", "discretization.interpolation=relative"});
    });
    BOOST_TEST(interpolation ==
               path +
                   ":--set: discretization.interpolation: not an option of the mixed "
                   "formulation (an option of the displacement formulation)");
    for (const char* key : {"discretization.update=additive", "discretization.rescale=true"}) {
        BOOST_TEST(input_error([&] {
                       load_case(path, {"discretization.formulation=mixed", key});
                   }).find("not an option of the mixed formulation") != std::string::npos);
    }
    const std::string wm = input_error([&] { load_case(path, {"discretization.wm_map=plain"}); });
    BOOST_TEST(wm == path +
                         ":--set: discretization.wm_map: not an option of the displacement "
                         "formulation (an option of the mixed formulation)");
    const std::string mip = input_error([&] {
        load_case(path, {"discretization.formulation=mixed", "solver.mip=false"});
    });
    BOOST_TEST(mip.find(":--set: solver.mip: the mixed formulation's section resultants are "
                        "unknowns already") != std::string::npos,
               mip);
    const std::string lumped = input_error([&] {
        load_case(path, {"discretization.formulation=mixed", "discretization.mass_rule=lumped"});
    });
    BOOST_TEST(lumped.find("discretization.mass_rule: 'lumped' is not available in the mixed "
                           "formulation") != std::string::npos,
               lumped);
}

BOOST_AUTO_TEST_CASE(errors_name_the_line_of_the_offending_key) {
    const std::string text =
        "points:\n  root: [0, 0, 0]\n  tip: [1, 0, 0]\nsections:\n  s:\n"
        "    isotropic: {E: 1, G: 1, A: 1, I2: 1, I3: 1, J: 1}\n"
        "members:\n  beam: {from: root, to: tip, section: s, elements: -2}\n"
        "analysis: {type: static, load_factors: [1]}\n";
    BOOST_TEST(input_error([&] { load_case_text(text, "x.yaml"); }) ==
               "x.yaml:8: members.beam.elements: must be a positive integer, got '-2'");
}

// analysis.estimate (docs/error-estimates.md): on unless the case says false, for every analysis
// type; anything but a boolean is refused, naming the key.
BOOST_AUTO_TEST_CASE(the_error_estimate_is_on_unless_the_case_switches_it_off) {
    const std::string path = case_path("cantilever-moment");
    BOOST_TEST(load_case(path).analysis.estimate);
    BOOST_TEST(!load_case(path, {"analysis.estimate=false"}).analysis.estimate);
    BOOST_TEST(
        !load_case(case_path("free-vibration"), {"analysis.estimate=false"}).analysis.estimate);
    const std::string bad = input_error([&] { load_case(path, {"analysis.estimate=sometimes"}); });
    BOOST_TEST(bad.find("analysis.estimate") != std::string::npos, bad);
}

// A catalog case keeps its published references beside it (cases/references/NAME.yaml): the case
// file alone (CaseParts::case_file, what `rotbeam run` reads) is the same model without them, and
// a message about a reference names the references file and its line.
BOOST_AUTO_TEST_CASE(published_references_are_read_from_beside_the_case) {
    const std::string path = case_path("cantilever-moment");
    const Model all = load_case(path);
    const Model run = load_case(path, {}, CaseParts::case_file);
    BOOST_TEST(all.references.size() == 15u);
    BOOST_TEST(run.references.empty());
    BOOST_TEST(run.name == all.name);
    BOOST_TEST(run.analysis.statics.load_factors == all.analysis.statics.load_factors,
               boost::test_tools::per_element());
    BOOST_TEST(run.point_loads.at(0).moment == all.point_loads.at(0).moment);
    BOOST_TEST(run.discretization.order == all.discretization.order);
    const std::string published = published_references_path(path).string();
    BOOST_TEST(published ==
               std::string(ROTBEAM_SOURCE_DIR) + "/cases/references/cantilever-moment.yaml");
    // A --set of a reference applies to the references file, also for the case file alone.
    const std::string message = input_error(
        [&] { load_case(path, {"references.exact-0p4.point=nowhere"}, CaseParts::case_file); });
    BOOST_TEST(message.rfind(published + ":", 0) == 0, message);
    BOOST_TEST(message.find("references.exact-0p4.point") != std::string::npos, message);
}

// A catalog entry made of a BeamDyn deck keeps its published references beside it like any case:
// the roll-up entry's exact arc and BeamDyn's printed tip are read with the imported deck (and not
// for `run`, which reads the case file alone), and a --set of a reference applies to that file.
BOOST_AUTO_TEST_CASE(a_deck_entry_reads_its_published_references) {
    const std::string path = case_path("beamdyn-rollup");
    const Model all = load_case(path);
    BOOST_TEST(all.name == "beamdyn-rollup");
    BOOST_TEST(all.members.at(0).elements ==
               16);  // the entry's `set` applied to the deck (its 1, 15)
    BOOST_TEST(all.discretization.order == 6);
    BOOST_TEST(reference(all, "exact").value.at(0) == 5.4986774284);
    BOOST_TEST(reference(all, "beamdyn-output").value.at(1) == -2.43174319);
    BOOST_TEST(load_case(path, {}, CaseParts::case_file).references.empty());
    const std::string published = published_references_path(path).string();
    const std::string message = input_error(
        [&] { load_case(path, {"references.exact.point=nowhere"}, CaseParts::case_file); });
    BOOST_TEST(message.rfind(published + ":", 0) == 0, message);
}

// One place for the numbers: a case with its own references block and a references file beside it
// is refused, naming the file.
BOOST_AUTO_TEST_CASE(a_references_block_in_the_case_and_beside_it_is_refused) {
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / "rotbeam_test_published_references";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir / "references");
    std::filesystem::copy_file(case_path("cantilever-moment"), dir / "c.yaml");
    std::filesystem::copy_file(
        std::string(ROTBEAM_SOURCE_DIR) + "/cases/references/cantilever-moment.yaml",
        dir / "references" / "c.yaml");
    BOOST_TEST(load_case((dir / "c.yaml").string()).references.size() == 15u);
    {
        std::ofstream out(dir / "c.yaml", std::ios::app);
        out << "references:\n  mine:\n    quantity: displacement\n    point: tip\n"
               "    load_factor: 0.4\n    components: [0, 2]\n    value: [-2.9181, 6.5984]\n"
               "    tolerance: 1.0e-3\n    justification: exact\n    source: test\n";
    }
    BOOST_TEST(load_case((dir / "c.yaml").string(), {}, CaseParts::case_file).references.size() ==
               1u);
    const std::string message = input_error([&] { load_case((dir / "c.yaml").string()); });
    BOOST_TEST(message.rfind((dir / "references" / "c.yaml").string() + ":", 0) == 0, message);
    BOOST_TEST(message.find("has a references block of its own") != std::string::npos, message);
    std::filesystem::remove_all(dir);
}

BOOST_AUTO_TEST_CASE(describe_model_lists_members_points_loads_and_analysis) {
    const std::string d = describe_model(load_case(case_path("bend-45")));
    for (const char* word : {"case bend-45", "root", "tip", "beam: root → tip, arc", "16 element",
                             "section square", "EI2 833333", "point tip: force (0, 0, 1)",
                             "static load factors [300, 450, 600]", "references: 5"}) {
        BOOST_TEST(d.find(word) != std::string::npos, "'" << word << "' missing in:\n" << d);
    }
}

BOOST_AUTO_TEST_CASE(the_complete_example_of_the_documentation_loads) {
    std::ifstream in(std::string(ROTBEAM_SOURCE_DIR) + "/docs/case-format.md");
    BOOST_REQUIRE(in.good());
    std::stringstream buffer;
    buffer << in.rdbuf();
    const std::string doc = buffer.str();
    const size_t start = doc.rfind("```yaml\n");
    BOOST_REQUIRE(start != std::string::npos);
    const size_t end = doc.find("```", start + 8);
    const Model m = load_case_text(doc.substr(start + 8, end - start - 8), "case-format.md");
    BOOST_TEST(m.name == "example");
    BOOST_TEST(m.members[0].sections.size() == 2u);
    // The compliance's shear rows are finite, so the displacement formulation has its stiffness.
    BOOST_TEST(m.members[0].sections[1].section.stiffness.has_value());
    BOOST_TEST(m.distributed_loads.size() == 1u);
    BOOST_TEST(m.has_follower_loads());
    BOOST_TEST(m.references.empty());  // a reference is never read off the case's own run
}

BOOST_AUTO_TEST_CASE(edit_distance_suggests_close_keys_only) {
    BOOST_TEST(cases::edit_distance("elemnts", "elements") == 1);
    BOOST_TEST(cases::closest_match("elemnts", {"elements", "section", "twist"}) == "elements");
    BOOST_TEST(cases::closest_match("zzz", {"elements", "section", "twist"}).empty());
}

// A section matrix is judged on its scaled couplings, not its units: a slender uncoupled section
// given as a matrix in SI (EI/EA = 8e-15, a unit-dependent ratio that the unscaled eigenvalue
// test refused as "not positive definite") is accepted; the same section with its two bending
// stiffnesses coupled to 1 − 1e-13 (scaled condition number 2e13) is refused, as is an EA below
// √DBL_MIN.
BOOST_AUTO_TEST_CASE(section_matrices_are_judged_scaled_and_in_range) {
    const auto with_bending = [](const std::string& coupling, const std::string& ea) {
        return "name: slender\npoints:\n  root: [0, 0, 0]\n  tip: [1, 0, 0]\nsections:\n  wire:\n"
               "    stiffness:\n      - [" +
               ea +
               ", 0, 0, 0, 0, 0]\n      - [0, 8.1e2, 0, 0, 0, 0]\n      - [0, 0, 8.1e2, 0, 0, 0]\n"
               "      - [0, 0, 0, 2.4e-11, 0, 0]\n      - [0, 0, 0, 0, 1.75e-11, " +
               coupling + "]\n      - [0, 0, 0, 0, " + coupling +
               ", 1.75e-11]\nmembers:\n  beam: {from: root, to: tip, section: wire, elements: 4}\n"
               "constraints:\n  root: clamped\nloads:\n  f: {point: tip, force: [0, 0, 1.0e-12]}\n"
               "analysis:\n  type: static\n  load_factors: [1.0]\n";
    };
    BOOST_TEST(input_error([&] { load_case_text(with_bending("0", "2.1e3"), "w.yaml"); }).empty());
    BOOST_TEST(input_error([&] {
                   load_case_text(with_bending("1.7499999999999825e-11", "2.1e3"), "w.yaml");
               }).find("numerically singular") != std::string::npos);
    BOOST_TEST(input_error([&] {
                   load_case_text(with_bending("0", "1e-160"), "w.yaml");
               }).find("outside") != std::string::npos);
}

BOOST_AUTO_TEST_SUITE_END()
