// `rotbeam study extremes`, second half: the roll-up in ONE load step to λ = 1, 2, 4 with step
// cutting disabled (the damped Newton alone: how robust is it?), and mesh refinement of the
// roll-up until round-off dominates (where the error stops falling, and why); then the study
// that plans the four parts' runs and assembles their sections.
#include <cmath>

#include "core/results.hpp"
#include "core/static_driver.hpp"
#include "studies.hpp"
#include "study_extremes.hpp"
#include "study_math.hpp"
#include "study_plot.hpp"

namespace rotbeam::cli {

namespace {

struct Refined {
    std::string label;
    Combination combination;
    int order;
    std::vector<int> elements;
};

std::vector<Refined> round_off_series(bool quick) {
    const int top = quick ? 128 : 1024;
    std::vector<int> n2, n4, nm;
    for (int n = 2; n <= top; n *= 2) n2.push_back(n);
    for (int n = 1; n <= top / 4; n *= 2) n4.push_back(n);
    for (int n = 16; n <= (quick ? 256 : 2048); n *= 2) nm.push_back(n);
    return {{"displacement/quaternion/p2",
             {Formulation::displacement, param::id_of<param::Quaternion>()},
             2,
             n2},
            {"displacement/quaternion/p4",
             {Formulation::displacement, param::id_of<param::Quaternion>()},
             4,
             n4},
            {"displacement/rotation-vector/p4",
             {Formulation::displacement, param::id_of<param::RotationVector>()},
             4,
             n4},
            {"mixed/rotation-vector",
             {Formulation::mixed, param::id_of<param::RotationVector>()},
             1,
             nm},
            {"mixed/quaternion", {Formulation::mixed, param::id_of<param::Quaternion>()}, 1, nm}};
}

const std::vector<double> kSingleStepLambdas = {1.0, 2.0, 4.0};

RunSpec single_step_spec(const Combination& c, double lambda) {
    return RunSpec{"cantilever-moment",
                   c,
                   {"analysis.load_factors=[" + sci(lambda, 3) + "]", "analysis.substeps=1",
                    "analysis.max_step_cuts=0"},
                   0};
}

RunSpec round_off_spec(const Refined& s, int n) {
    std::vector<std::string> ov = {"analysis.load_factors=[0.8]", "analysis.substeps=2"};
    if (s.combination.formulation == Formulation::displacement) {
        ov.push_back("discretization.order=" + std::to_string(s.order));
    }
    return RunSpec{"cantilever-moment", s.combination, ov, n};
}

}  // namespace

void plan_extremes_single_step(const StudyOptions&, std::vector<StudyRun>& plan) {
    for (const Combination& c : all_combinations(true)) {
        for (double lambda : kSingleStepLambdas) plan_case_run(plan, single_step_spec(c, lambda));
    }
}

void plan_extremes_round_off(const StudyOptions& o, std::vector<StudyRun>& plan) {
    for (const Refined& s : round_off_series(o.quick)) {
        for (int n : s.elements) plan_case_run(plan, round_off_spec(s, n));
    }
}

nlohmann::json extremes_single_step(const StudyOptions& o, const StudyResults& results,
                                    std::ostringstream& md) {
    const std::vector<double>& lambdas = kSingleStepLambdas;
    md << "### One load step\n\nThe roll-up (catalog mesh: 16 elements, displacement order 4) "
          "solved in a single load step to λ = 1, 2 and 4 with step cutting disabled "
          "(`analysis.max_step_cuts=0`): the damped Newton alone. Entries: Newton iterations and "
          "tip error ‖Δu‖/L, or how it failed.\n\n| combination | λ = 1 | λ = 2 | λ = 4 |\n"
          "|---|---|---|---|\n";
    nlohmann::json out = nlohmann::json::array();
    PanelFigure figure;
    for (const Combination& c : all_combinations(true)) {
        const std::string panel =
            c.formulation == Formulation::mixed
                ? std::string("mixed")
                : "displacement, " + std::string(choice_name(*c.interpolation)) + " interpolation";
        std::vector<double> failures;
        std::ostringstream row, data;
        data << "# lambda newton_iterations\n";
        bool unavailable = false;
        for (double lambda : lambdas) {
            const nlohmann::json& r = result_for(results, single_step_spec(c, lambda));
            const std::string status = r.value("status", "error");
            unavailable = status == "unavailable";
            if (unavailable) break;
            const bool ok = has_solution(status) && converged_steps_exist(r);
            const double e = ok ? rollup_tip_error(r["steps"].back(), 12.0) : kNoValue;
            const int it = total_newton_iterations(r);
            row << " " << (ok ? std::to_string(it) + " it, " + sci(e) : status) << " |";
            if (ok) {
                data << lambda << " " << it << "\n";
            } else {
                data << "\n";  // no line across a failed run
                failures.push_back(lambda);
            }
            out.push_back({{"combination", c.label()},
                           {"lambda", lambda},
                           {"status", status},
                           {"newton_iterations", it},
                           {"error", ok ? nlohmann::json(e) : nlohmann::json()},
                           {"message", r.value("message", "")}});
        }
        if (unavailable) continue;
        md << "| " << c.label() << " |" << row.str() << "\n";
        const std::string rel =
            "data/extremes_single_" + std::to_string(figure.files.size()) + ".dat";
        write_text(o, rel, data.str());
        figure.add(panel, out_path(o, rel), c.rotation_name());
        for (double lambda : failures) figure.add_failure(panel, lambda);
    }
    plot_panels(o, figure,
                {{"xcol", "1"},
                 {"ycol", "2"},
                 {"xlabel", "load factor λ reached in one step [-]"},
                 {"ylabel", "Newton iterations (converged runs only) [-]"},
                 {"plottitle",
                  "Roll-up in one load step, no step cutting: Newton iterations of the "
                  "converged runs (red crosses: diverged or singular)"},
                 {"outbase", out_path(o, "extremes-single-step")},
                 {"logx", "0"},
                 {"logy", "0"}});
    md << "\n![extremes-single-step.png](extremes-single-step.png)\n\n";
    return out;
}

nlohmann::json extremes_round_off(const StudyOptions& o, const StudyResults& results,
                                  std::ostringstream& md) {
    md << "### Refinement towards round-off\n\nThe roll-up at λ = 0.8 (exact) refined by "
          "doubling the elements, to find where the error stops falling. `smallest` is the "
          "smallest error and where it occurs; `floor` says whether the series reached a floor "
          "(the error stopped falling before the finest mesh) or was still falling at the finest "
          "mesh run (then round-off was not reached and `smallest` is only the last point); `order "
          "before` the observed order up to it; `slope after` the log-log slope of the error past "
          "it (positive: it grows again).\n\n| series | elements | smallest | at N | floor | order "
          "before | slope after |\n|---|---|---|---|---|---|---|\n";
    nlohmann::json out = nlohmann::json::array();
    PanelFigure figure;
    for (const Refined& s : round_off_series(o.quick)) {
        Series series{s.label, {}, {}, {}, {}};
        for (int n : s.elements) {
            const nlohmann::json& r = result_for(results, round_off_spec(s, n));
            const bool ok = has_solution(r.value("status", "")) && converged_steps_exist(r);
            series.add(n, r.value("dofs", 0), r.value("wall_seconds", 0.0),
                       ok ? rollup_tip_error(r["steps"].back(), 12.0) : kNoValue);
        }
        const int f = floor_index(series.error);
        const size_t fi = static_cast<size_t>(std::max(f, 0));
        const std::vector<double> n_before(series.elements.begin(),
                                           series.elements.begin() + fi + 1);
        const std::vector<double> e_before(series.error.begin(), series.error.begin() + fi + 1);
        const std::vector<double> n_after(series.elements.begin() + fi, series.elements.end());
        const std::vector<double> e_after(series.error.begin() + fi, series.error.end());
        const double before = fit_order(n_before, e_before);
        const double after = n_after.size() >= 2 ? -fit_order(n_after, e_after) : kNoValue;
        const bool reached = f >= 0 && fi + 1 < series.error.size();
        md << "| " << s.label << " | " << s.elements.front() << " … " << s.elements.back() << " | "
           << (f >= 0 ? sci(series.error[fi]) : "—") << " | "
           << (f >= 0 ? std::to_string(static_cast<int>(series.elements[fi])) : "—") << " | "
           << (reached ? "reached" : "not reached (still falling)") << " | " << sci(before, 2)
           << " | " << sci(after, 2) << " |\n";
        out.push_back({{"series", s.label},
                       {"elements", series.elements},
                       {"error", series.error},
                       {"floor_index", f},
                       {"order_before", before},
                       {"floor_reached", reached},
                       {"slope_after", after}});
        figure.add("roll-up λ = 0.8, elements doubled",
                   write_series(
                       o, "data/extremes_roundoff_" + std::to_string(figure.files.size()) + ".dat",
                       series),
                   s.label);
    }
    plot_panels(o, figure,
                {{"xcol", "1"},
                 {"ycol", "4"},
                 {"xlabel", "elements N [-]"},
                 {"ylabel", "tip error ‖Δu‖/L [-]"},
                 {"plottitle", "Roll-up λ = 0.8: tip error under mesh doubling"},
                 {"outbase", out_path(o, "extremes-round-off")},
                 {"logx", "1"},
                 {"logy", "1"}});
    md << "\n![extremes-round-off.png](extremes-round-off.png)\n\n";
    return out;
}

namespace {

std::vector<StudyRun> extremes_plan(const StudyOptions& o) {
    std::vector<StudyRun> plan;
    plan_extremes_slenderness(o, plan);
    plan_extremes_tiny_loads(o, plan);
    plan_extremes_single_step(o, plan);
    plan_extremes_round_off(o, plan);
    return plan;
}

nlohmann::json extremes_combine(const StudyOptions& o, const StudyResults& results) {
    std::ostringstream md;
    md << "## Study: the extremes\n\n";
    nlohmann::json out = {{"study", "extremes"}, {"quick", o.quick}};
    out["slenderness"] = extremes_slenderness(o, results, md);
    out["tiny_loads"] = extremes_tiny_loads(o, results, md);
    out["single_step"] = extremes_single_step(o, results, md);
    out["round_off"] = extremes_round_off(o, results, md);
    write_text(o, "study-extremes.md", md.str());
    out["schema_version"] = kSchemaVersion;
    write_text(o, "study-extremes.json", out.dump(1) + "\n");
    return out;
}

}  // namespace

SplitStudy extremes_study() { return {extremes_plan, extremes_combine}; }

nlohmann::json study_extremes(const StudyOptions& o) {
    return run_split_study(extremes_study(), o);
}

}  // namespace rotbeam::cli
