// `rotbeam study convergence` (statics): h-refinement for every combination and
// p-refinement for the displacement formulation on the roll-up at λ = 0.8 (exact, core/oracles/
// rollup.hpp), the 45° bend at P = 600 and the precessing helix at κL = 2.5 (continuum reference);
// observed orders (least squares and the last three points above the round-off floor) and
// log-log plots against elements and unknowns with reference slopes. λ = 0.8 and κL = 2.5 keep
// every rotation below π so every parameterization can take part (their limits are the
// singularity study's job).
#include <cmath>
#include <sstream>

#include "core/results.hpp"
#include "core/static_driver.hpp"
#include "studies.hpp"
#include "study_common.hpp"
#include "study_math.hpp"
#include "study_plot.hpp"
#include "study_runs.hpp"

namespace rotbeam::cli {

namespace {

// Errors below this are round-off (the solver's 1e-12 scaled-residual tolerance); the fits skip
// them. Against the exact roll-up that is the only floor.
constexpr double kFitFloor = 1e-12;
// The continuum reference's verified accuracy (docs/reference-solutions.md, "Measured accuracy":
// 1.8e-11 on the roll-up and the helices). An error against it below this says nothing about the
// finite elements, so fits against the reference use only errors 100x above it.
constexpr double kReferenceAccuracy = 1.8e-11;
constexpr double kReferenceFitFloor = 100.0 * kReferenceAccuracy;

struct ConvergenceCase {
    std::string key, case_name, title, ylabel;
    std::vector<std::string> overrides;
    bool exact_rollup = false;
};

std::vector<ConvergenceCase> convergence_cases() {
    return {{"rollup",
             "cantilever-moment",
             "Roll-up, λ = 0.8 (exact solution)",
             "tip error ‖Δu‖/L [-]",
             {"analysis.load_factors=[0.8]", "analysis.substeps=2"},
             true},
            {"bend",
             "bend-45",
             "45° bend, P = 600 lbf (continuum reference)",
             "tip error ‖Δu‖/‖u_{ref}‖ [-]",
             {kExactBendTip, "analysis.load_factors=[600]", "analysis.substeps=10"},
             false},
            {"helix",
             "helix-precessing",
             "Precessing helix, κL = 2.5 (continuum reference)",
             "tip error ‖Δu‖/L [-]",
             {"analysis.load_factors=[2.5]", "analysis.substeps=10"},
             false}};
}

struct Refinement {
    std::string name;                   // h-p1, h-p2, p, h
    std::vector<int> elements, orders;  // parallel lists
};

std::vector<Refinement> refinements(Formulation formulation, bool quick) {
    auto h = [](int order, std::vector<int> n) {
        return Refinement{"h-p" + std::to_string(order), n, std::vector<int>(n.size(), order)};
    };
    if (formulation == Formulation::mixed) {
        const std::vector<int> n =
            quick ? std::vector<int>{4, 8, 16, 32} : std::vector<int>{4, 8, 16, 32, 64, 128};
        return {Refinement{"h", n, std::vector<int>(n.size(), 1)}};
    }
    const std::vector<int> p =
        quick ? std::vector<int>{2, 4, 6, 8} : std::vector<int>{2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12};
    return {h(1, quick ? std::vector<int>{2, 4, 8, 16} : std::vector<int>{2, 4, 8, 16, 32, 64}),
            h(2, quick ? std::vector<int>{1, 2, 4, 8} : std::vector<int>{1, 2, 4, 8, 16, 32}),
            Refinement{"p", std::vector<int>(p.size(), 2), p}};
}

double step_error(const ConvergenceCase& c, const nlohmann::json& result, double length,
                  const nlohmann::json& reference) {
    if (!has_solution(result.value("status", "")) || !converged_steps_exist(result))
        return kNoValue;
    const nlohmann::json& step = result["steps"].back();
    if (c.exact_rollup) return rollup_tip_error(step, length);
    const double scale =
        c.key == "bend" ? point_displacement(reference["steps"].back()).norm() : length;
    return reference_tip_error(step, reference, scale);
}

// Point i of a refinement: the case at its elements (and order, displacement only).
RunSpec refinement_spec(const ConvergenceCase& c, const Combination& comb, const Refinement& r,
                        size_t i) {
    std::vector<std::string> o = c.overrides;
    if (comb.formulation == Formulation::displacement) {
        o.push_back("discretization.order=" + std::to_string(r.orders[i]));
    }
    return RunSpec{c.case_name, comb, o, r.elements[i]};
}

// Where the results go in the plan.
std::string reference_key(const ConvergenceCase& c) { return c.key + "/reference"; }
std::string run_key(const ConvergenceCase& c, const Combination& comb, const Refinement& r,
                    size_t i) {
    return c.key + "/" + comb.label() + "/" + r.name + "/" + std::to_string(i);
}

// A refinement series from its runs' results; the series ends at a combination the program
// refuses ("unavailable", with the message as its note).
Series refinement_series(const ConvergenceCase& c, const Combination& comb, const Refinement& r,
                         const nlohmann::json& reference, const StudyResults& results,
                         std::string& note) {
    Series s{comb.formulation_name() + "/" + comb.rotation_name() + "/" + r.name, {}, {}, {}, {}};
    for (size_t i = 0; i < r.elements.size(); ++i) {
        const RunSpec spec = refinement_spec(c, comb, r, i);
        const nlohmann::json& result = result_of(results, run_key(c, comb, r, i));
        if (result.value("status", "") == "unavailable") {
            note = result.value("message", "");
            return s;
        }
        const double length = member_length(build_model(spec));
        s.add(r.elements[i], result.value("dofs", 0), result.value("wall_seconds", 0.0),
              step_error(c, result, length, reference));
        if (!std::isfinite(s.error.back()) && note.empty()) {
            note = result.value("status", "") + ": " + result.value("message", "").substr(0, 80);
        }
    }
    return s;
}

}  // namespace

namespace {

std::string panel_title(const Combination& comb, const Refinement& r) {
    if (comb.formulation == Formulation::mixed) return "mixed, h-refinement";
    if (r.name == "p") return "displacement, p-refinement on 2 elements";
    return "displacement, h-refinement, order " + r.name.substr(3);
}

std::string order_text(double q) {
    if (!std::isfinite(q)) return "—";
    std::ostringstream s;
    s.precision(2);
    s << std::fixed << q;
    return s.str();
}

// One case from its runs' results: every combination × refinement; data files, two figures, the
// table rows.
nlohmann::json convergence_case(const StudyOptions& o, const ConvergenceCase& c,
                                const StudyResults& results, std::ostringstream& md) {
    const nlohmann::json reference =
        c.exact_rollup ? nlohmann::json() : result_of(results, reference_key(c));
    nlohmann::json out = {{"case", c.key}, {"series", nlohmann::json::array()}};
    PanelFigure by_elements, by_unknowns;
    double refx = kNoValue, refy = kNoValue, refd = kNoValue;
    for (const Combination& comb : all_combinations(false)) {
        for (const Refinement& r : refinements(comb.formulation, o.quick)) {
            std::string note;
            const Series s = refinement_series(c, comb, r, reference, results, note);
            const bool p_series = r.name == "p";
            const double floor = c.exact_rollup ? kFitFloor : kReferenceFitFloor;
            const double ls = fit_order(p_series ? s.dofs : s.elements, s.error, floor);
            const double tail = tail_order(p_series ? s.dofs : s.elements, s.error, 3, floor);
            out["series"].push_back({{"label", s.label},
                                     {"elements", s.elements},
                                     {"dofs", s.dofs},
                                     {"error", s.error},
                                     {"order_ls", ls},
                                     {"order_tail", tail},
                                     {"fit_floor", floor},
                                     {"note", note}});
            // The element order of each point, where the formulation has one (the mixed elements
            // have their own, fixed): what the page's header names is checked against it.
            if (comb.formulation == Formulation::displacement) {
                out["series"].back()["orders"] = std::vector<int>(
                    r.orders.begin(),
                    r.orders.begin() + static_cast<std::ptrdiff_t>(s.elements.size()));
            }
            md << "| " << c.key << " | " << s.label << " | "
               << (s.error.empty() ? "—" : sci(s.error.front()) + " → " + sci(s.error.back()))
               << " | " << sci(floor, 1) << " | " << order_text(ls) << " | " << order_text(tail)
               << " | " << markdown_cell(note) << " |\n";
            if (s.error.empty()) continue;
            const std::string file =
                write_series(o,
                             "data/convergence_" + c.key + "_" +
                                 std::to_string(by_unknowns.files.size()) + ".dat",
                             s);
            by_unknowns.add(panel_title(comb, r), file, comb.rotation_name());
            if (!p_series) by_elements.add(panel_title(comb, r), file, comb.rotation_name());
            if (!std::isfinite(refy) && r.name == "h" && std::isfinite(s.error.front())) {
                refx = s.elements.front();
                refd = s.dofs.front();
                refy = s.error.front();
            }
        }
    }
    if (!std::isfinite(refy)) refx = 1.0, refd = 10.0, refy = 1e-2;
    for (const auto& [x, figure] :
         {std::pair<std::string, const PanelFigure&>{"elements", by_elements},
          std::pair<std::string, const PanelFigure&>{"unknowns", by_unknowns}}) {
        const std::string base = "convergence-" + c.key + "-" + x;
        plot_panels(o, figure,
                    {{"xcol", x == "elements" ? "1" : "2"},
                     {"ycol", "4"},
                     {"xlabel", "number of " + x + " [-]"},
                     {"ylabel", c.ylabel},
                     {"plottitle", c.title + ": error vs " + x},
                     {"outbase", out_path(o, base)},
                     {"logx", "1"},
                     {"logy", "1"},
                     {"slopes", sci(x == "elements" ? refx : refd, 6) + " " + sci(refy, 6)},
                     {"hline", c.exact_rollup ? std::string() : sci(kReferenceFitFloor, 6)},
                     {"hlabel", "fit floor = 100x the reference accuracy"}});
        out["figures"].push_back(base + ".png");
    }
    return out;
}

// The runs: the continuum reference of each case that has no exact solution, and every point of
// every refinement of every combination.
std::vector<StudyRun> convergence_plan(const StudyOptions& o) {
    std::vector<StudyRun> plan;
    for (const ConvergenceCase& c : convergence_cases()) {
        if (!c.exact_rollup) {
            plan.push_back({reference_key(c), StudyRun::Kind::continuum_reference,
                            RunSpec{c.case_name, {}, c.overrides, 0}});
        }
        for (const Combination& comb : all_combinations(false)) {
            for (const Refinement& r : refinements(comb.formulation, o.quick)) {
                for (size_t i = 0; i < r.elements.size(); ++i) {
                    plan.push_back({run_key(c, comb, r, i), StudyRun::Kind::case_run,
                                    refinement_spec(c, comb, r, i)});
                }
            }
        }
    }
    return plan;
}

nlohmann::json convergence_combine(const StudyOptions& o, const StudyResults& results) {
    std::ostringstream table;
    nlohmann::json out = {
        {"study", "convergence"}, {"quick", o.quick}, {"cases", nlohmann::json::array()}};
    for (const ConvergenceCase& c : convergence_cases()) {
        out["cases"].push_back(convergence_case(o, c, results, table));
    }
    // The p-refinement is the last of the displacement refinements; held in a variable, since a
    // range-for over a member of the returned temporary would read it after it is destroyed.
    const std::vector<Refinement> displacement = refinements(Formulation::displacement, o.quick);
    std::string orders;
    for (int p : displacement.back().orders) {
        orders += (orders.empty() ? "" : ", ") + std::to_string(p);
    }
    std::ostringstream md;
    md << "## Study: convergence\n\nh-refinement of every combination (displacement: order 1 and "
          "2; mixed: its second-order elements) and p-refinement of the displacement formulation "
          "(2 elements, orders "
       << orders
       << ") on the roll-up at λ = 0.8 (exact), the 45° bend at P = 600 and the precessing helix "
          "at κL = 2.5 (continuum reference, verified to "
       << sci(kReferenceAccuracy, 1)
       << "). Observed order: least-squares slope over all points above the `fit floor`, and "
          "over the last three such points. The floor is the solver's "
       << sci(kFitFloor, 0)
       << " against the exact roll-up and 100× the reference's verified accuracy, "
       << sci(kReferenceFitFloor, 1)
       << ", against the continuum reference: a smaller error measures the reference, not the "
          "elements. For p-refinement the slope is against unknowns; its convergence is "
          "exponential, so that number only grows with p. Figures: one panel per refinement, the "
          "parameterizations inside (nested markers where they coincide).\n\n"
       << "| case | combination/refinement | error (coarsest → finest) | fit floor | order (LS) | "
          "order (last 3) | note |\n|---|---|---|---|---|---|---|\n"
       << table.str() << "\n";
    for (const auto& c : out["cases"]) {
        for (const auto& f : c["figures"]) {
            md << "![" << f.get<std::string>() << "](" << f.get<std::string>() << ")\n\n";
        }
    }
    write_text(o, "study-convergence.md", md.str());
    out["schema_version"] = kSchemaVersion;
    write_text(o, "study-convergence.json", out.dump(1) + "\n");
    return out;
}

}  // namespace

SplitStudy convergence_study() { return {convergence_plan, convergence_combine}; }

nlohmann::json study_convergence(const StudyOptions& o) {
    return run_split_study(convergence_study(), o);
}

}  // namespace rotbeam::cli
