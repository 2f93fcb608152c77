// The catalog's stated accuracy (docs/accuracy-control.md, "The catalog's defaults"): every
// static and modal catalog case states in discretization.accuracy, per formulation, the accuracy
// its own discretization is meant to reach, and every combination of that formulation that solves
// the case meets it by its own estimate (every estimate reliable and ≤ half of it relative to its
// scale: what `run --accuracy` would accept without refining). A combination that does not solve
// the case (a chart's singular angle; the references' expected stops) has no estimate to meet it
// and is listed. A formulation the case states nothing for must say why in the case file (not
// checked here: a comment).
#include <boost/test/unit_test.hpp>

#include "cases/loader/case_loader.hpp"
#include "cases/loader/deck_case.hpp"
#include "combinations/registry.hpp"
#include "core/errors.hpp"
#include "core/static_driver.hpp"
#include "estimates/accuracy_scale.hpp"
#include "estimates/history_estimate.hpp"
#include "runs/catalog.hpp"
#include "runs/run_case.hpp"

namespace rotbeam {

namespace {

// A solved run meets the accuracy its case states by its own estimate: every estimate reliable
// and ≤ half of it relative to its scale (what `run --accuracy` accepts without refining).
void expect_stated_accuracy_met(const RunRequest& request, nlohmann::json& r, double stated,
                                const std::string& what) {
    add_run_estimate(request, r);
    const double target = stated / 2.0;
    const estimate::AccuracyMeasure m = estimate::measure_accuracy(request.model, r, target);
    BOOST_TEST(estimate::meets(m, target), what << ": stated " << stated << ", worst " << m.worst
                                                << " (" << m.worst_what << "); "
                                                << m.first_problem);
    BOOST_TEST_MESSAGE(what << ": worst " << m.worst << " (" << m.worst_what << "), stated "
                            << stated);
}

}  // namespace

BOOST_AUTO_TEST_CASE(catalog_defaults_meet_their_stated_accuracy) {
    int checked = 0;
    for (const std::string& name : cli::catalog_cases()) {
        const std::string path = cli::resolve_case_path(name);
        const Model model = load_case(path, {}, CaseParts::case_file);
        if (model.analysis.kind == AnalysisKind::dynamic) continue;
        BOOST_TEST(!model.discretization.stated_accuracy.empty(),
                   name << ": states no discretization.accuracy");
        for (const comb::Combination& c : comb::all_combinations(false)) {
            const auto stated = model.discretization.stated_accuracy.find(c.formulation);
            if (stated == model.discretization.stated_accuracy.end()) continue;
            const RunRequest request{
                path, load_case(path,
                                {"discretization.formulation=" + c.formulation_name(),
                                 "discretization.rotation=" + c.rotation_name()},
                                CaseParts::case_file)};
            nlohmann::json r = run_case(request);
            const std::string status = r["status"].get<std::string>();
            if (!has_solution(status)) {
                BOOST_TEST_MESSAGE(name << " " << c.label() << ": " << status << ", no estimate");
                continue;
            }
            expect_stated_accuracy_met(request, r, stated->second, name + " " + c.label());
            ++checked;
        }
    }
    // 13 static and modal cases; 109 of the combinations of their stated formulations solve them
    // (measured 2026-11-26: 49 of the 7 native cases; 2026-11-27: all 60 of the six static BeamDyn
    // deck entries). Fewer would mean a case or its statement went missing.
    BOOST_TEST(checked >= 109, checked << " combinations checked");
}

// The catalog's dynamic cases that state an accuracy or a refusal (the BeamDyn decks' catalog
// entries, cases/loader/deck_case.hpp): every combination of a formulation with a stated accuracy
// meets it by its own estimate (the histories relative to their amplitudes); a formulation the case
// states it refuses is refused in the stated words, before any step; a formulation the case states
// neither for (the mixed formulation of the NREL 5-MW entries: one constant-strain element over
// the blade at BeamDyn's discretization; the entry's comments say why) runs to a result and
// carries its own estimate of every history, so that the suite's matrix shows that estimate
// instead of a hole, and where that estimate reaches half an amplitude its status reads
// `inaccurate` (estimates/history_estimate.hpp), never a clean `converged`. A formulation is never
// both stated and refused. The other dynamic cases state neither for any formulation and say why
// in their files (no discretization of theirs that the suite can afford reaches an accuracy by its
// estimate).
BOOST_AUTO_TEST_CASE(dynamic_catalog_cases_meet_their_stated_accuracy_or_are_refused_as_stated) {
    int checked = 0, refused = 0, unstated = 0;
    for (const std::string& name : cli::catalog_cases()) {
        const std::string path = cli::resolve_case_path(name);
        const Model model = load_case(path, {}, CaseParts::case_file);
        if (model.analysis.kind != AnalysisKind::dynamic) continue;
        const auto& stated_accuracy = model.discretization.stated_accuracy;
        const std::map<Formulation, std::string> refusals = cases::stated_refusals(path);
        if (stated_accuracy.empty() && refusals.empty()) continue;
        for (const comb::Combination& c : comb::all_combinations(false)) {
            const auto stated = stated_accuracy.find(c.formulation);
            const auto refusal = refusals.find(c.formulation);
            BOOST_TEST(!(stated != stated_accuracy.end() && refusal != refusals.end()),
                       name << " " << c.label() << ": states an accuracy and a refusal");
            const std::vector<std::string> overrides = {
                "discretization.formulation=" + c.formulation_name(),
                "discretization.rotation=" + c.rotation_name()};
            if (refusal != refusals.end()) {
                std::string message = "ran";
                try {
                    const RunRequest request{path,
                                             load_case(path, overrides, CaseParts::case_file)};
                    run_case(request);
                } catch (const InputError& e) {
                    message = e.what();
                }
                BOOST_TEST(message.find(refusal->second) != std::string::npos,
                           name << " " << c.label() << ": '" << message << "' lacks '"
                                << refusal->second << "'");
                ++refused;
                continue;
            }
            const RunRequest request{path, load_case(path, overrides, CaseParts::case_file)};
            nlohmann::json r = run_case(request);
            BOOST_TEST_REQUIRE(has_solution(r["status"].get<std::string>()),
                               name << " " << c.label() << ": " << r["status"]);
            if (stated != stated_accuracy.end()) {
                expect_stated_accuracy_met(request, r, stated->second, name + " " + c.label());
                ++checked;
                continue;
            }
            add_run_estimate(request, r);
            // Target 1: only the measure's worst and missing count are read here.
            const estimate::AccuracyMeasure m = estimate::measure_accuracy(request.model, r, 1.0);
            const std::string status = r["status"].get<std::string>();
            BOOST_TEST((m.quantities > 0 && m.missing == 0),
                       name << " " << c.label() << ": " << m.quantities << " estimated, "
                            << m.missing << " without an estimate");
            if (m.worst >= estimate::kRelativeInaccurate) {
                BOOST_TEST(status == estimate::kInaccurate,
                           name << " " << c.label() << ": estimate " << m.worst
                                << " of an amplitude, status " << status);
            }
            BOOST_TEST_MESSAGE(name << " " << c.label() << ": states nothing; status " << status
                                    << ", worst estimate " << m.worst << " (" << m.worst_what
                                    << ")");
            ++unstated;
        }
    }
    // The two NREL 5-MW decks and the rotating cantilever deck: five displacement combinations
    // each meeting the stated accuracy, five mixed ones each run with their estimate (the decks'
    // damping runs in the mixed dynamics since 2026-11-27; they were refused before). Fewer would
    // mean an entry or its statement went missing.
    BOOST_TEST(checked >= 15, checked << " combinations checked");
    BOOST_TEST(refused + unstated >= 15,
               refused << " combinations refused, " << unstated << " run without a statement");
}

}  // namespace rotbeam
