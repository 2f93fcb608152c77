// `rotbeam study speed-accuracy`: statics — error against in-process wall time (median of
// repeats, timing.hpp) across meshes and orders on the roll-up (λ = 0.8, exact) and the 45° bend
// (P = 600, continuum reference) for every combination, the Pareto front across combinations,
// which combination wins at which accuracy (in words); dynamics — every time scheme on the joined
// beam and the free vibration (studies/dynamic_speed.hpp); and the "model only what the scene
// requires" counters of every catalog analysis.
#include "study_speed.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "bench.hpp"
#include "cases/loader/case_loader.hpp"
#include "core/results.hpp"
#include "core/static_driver.hpp"
#include "runs/catalog.hpp"
#include "runs/timing.hpp"
#include "studies/dynamic_speed.hpp"
#include "studies/study_math.hpp"
#include "studies/study_plot.hpp"

namespace rotbeam::cli {

namespace {

struct Mesh {
    int order, elements;
};

std::vector<Mesh> meshes(Formulation formulation, bool quick) {
    std::vector<Mesh> m;
    if (formulation == Formulation::mixed) {
        for (int n = 8; n <= (quick ? 128 : 512); n *= 2) m.push_back({1, n});
        return m;
    }
    const std::vector<std::pair<int, int>> ranges =
        quick ? std::vector<std::pair<int, int>>{{1, 64}, {2, 16}, {4, 8}, {8, 2}}
              : std::vector<std::pair<int, int>>{{1, 128}, {2, 64}, {4, 16}, {8, 8}, {12, 2}};
    for (const auto& [p, top] : ranges) {
        for (int n = (p == 1 ? 4 : 1); n <= top; n *= 2) m.push_back({p, n});
    }
    return m;
}

struct SpeedCase {
    std::string key, case_name, title, ylabel;
    std::vector<std::string> overrides;
    bool exact_rollup;
};

std::vector<SpeedCase> speed_cases() {
    return {{"rollup",
             "cantilever-moment",
             "Roll-up λ = 0.8: error vs time",
             "tip error ‖Δu‖/L [-]",
             {"analysis.load_factors=[0.8]", "analysis.substeps=2"},
             true},
            {"bend",
             "bend-45",
             "45° bend P = 600 lbf: error vs time",
             "tip error ‖Δu‖/‖u_{ref}‖ [-]",
             {kExactBendTip, "analysis.load_factors=[600]", "analysis.substeps=5"},
             false}};
}

struct Point {
    std::string combination;
    Mesh mesh;
    double seconds, error;
    int dofs;
};

// One timed point: the first run gives the error, the repeats the median time.
Point speed_point(const SpeedCase& c, const Combination& comb, const Mesh& m,
                  const nlohmann::json& reference, int repeats, bool& unavailable) {
    std::vector<std::string> o = c.overrides;
    if (comb.formulation == Formulation::displacement) {
        o.push_back("discretization.order=" + std::to_string(m.order));
    }
    const RunSpec spec{c.case_name, comb, o, m.elements};
    nlohmann::json r = run_spec(spec);
    unavailable = r.value("status", "") == "unavailable";
    Point p{
        comb.label() +
            (comb.formulation == Formulation::displacement ? "/p" + std::to_string(m.order) : ""),
        m, kNoValue, kNoValue, r.value("dofs", 0)};
    if (unavailable || !has_solution(r.value("status", "")) || !converged_steps_exist(r)) return p;
    const nlohmann::json& step = r["steps"].back();
    p.error = c.exact_rollup
                  ? rollup_tip_error(step, 12.0)
                  : reference_tip_error(step, reference,
                                        point_displacement(reference["steps"].back()).norm());
    p.seconds = time_in_process([&] { run_spec(spec); }, repeats, 0.5).median_seconds;
    return p;
}

}  // namespace

namespace {

std::string ms_text(double seconds) {
    std::ostringstream s;
    s.precision(3);
    s << seconds * 1e3 << " ms";
    return s.str();
}

// Which combination wins where: the fastest point reaching each accuracy level.
void winners_in_words(const std::vector<Point>& points, std::ostringstream& md) {
    md << "Fastest discretization reaching each accuracy:\n\n";
    for (double level : {1e-2, 1e-4, 1e-6, 1e-8, 1e-10, 1e-12}) {
        const Point* best = nullptr;
        for (const Point& p : points) {
            if (std::isfinite(p.error) && p.error <= level &&
                (!best || p.seconds < best->seconds)) {
                best = &p;
            }
        }
        md << "- error ≤ " << sci(level, 0) << ": ";
        if (best) {
            md << best->combination << ", " << best->mesh.elements << " elements (" << best->dofs
               << " unknowns), " << ms_text(best->seconds) << " (error " << sci(best->error)
               << ")\n";
        } else {
            md << "no combination reached it on the grid\n";
        }
    }
    md << "\n";
}

// The Pareto front of all points: its table, its data file (for the plot) and its JSON.
nlohmann::json front_table(const StudyOptions& o, const SpeedCase& c,
                           const std::vector<Point>& points, std::ostringstream& md) {
    std::vector<double> cost, error;
    for (const Point& p : points) {
        cost.push_back(p.seconds);
        error.push_back(p.error);
    }
    const std::vector<bool> front = pareto_front(cost, error);
    std::vector<const Point*> on_front;
    for (size_t i = 0; i < points.size(); ++i)
        if (front[i]) on_front.push_back(&points[i]);
    std::sort(on_front.begin(), on_front.end(),
              [](const Point* a, const Point* b) { return a->seconds < b->seconds; });
    std::ostringstream front_data;
    front_data.precision(10);
    md << "### " << c.title
       << "\n\nPareto front (no other run is both faster and more "
          "accurate):\n\n| combination | elements | unknowns | time | error "
          "|\n|---|---|---|---|---|\n";
    nlohmann::json out = nlohmann::json::array();
    for (const Point* p : on_front) {
        front_data << p->seconds << " " << std::max(p->error, 1e-17) << "\n";
        md << "| " << p->combination << " | " << p->mesh.elements << " | " << p->dofs << " | "
           << ms_text(p->seconds) << " | " << sci(p->error) << " |\n";
        out.push_back({{"combination", p->combination},
                       {"elements", p->mesh.elements},
                       {"dofs", p->dofs},
                       {"seconds", p->seconds},
                       {"error", p->error}});
    }
    md << "\n";
    write_text(o, "data/speed_" + c.key + "_front.dat", front_data.str());
    return out;
}

nlohmann::json speed_case(const StudyOptions& o, const SpeedCase& c, std::ostringstream& md) {
    const nlohmann::json reference =
        c.exact_rollup ? nlohmann::json() : continuum_reference(c.case_name, c.overrides);
    const int repeats = o.quick ? 3 : 5;
    std::vector<Point> points;
    PanelFigure figure;
    for (const Combination& comb : all_combinations(false)) {
        std::map<std::string, Series> by_label;
        std::map<std::string, std::string> panel_of;
        std::vector<std::string> order;
        for (const Mesh& m : meshes(comb.formulation, o.quick)) {
            bool unavailable = false;
            const Point p = speed_point(c, comb, m, reference, repeats, unavailable);
            if (unavailable) break;
            points.push_back(p);
            if (!by_label.count(p.combination)) order.push_back(p.combination);
            by_label[p.combination].label = p.combination;
            panel_of[p.combination] = comb.formulation == Formulation::mixed
                                          ? std::string("mixed (second order, h)")
                                          : "displacement, order " + std::to_string(m.order);
            by_label[p.combination].add(m.elements, p.dofs, p.seconds, p.error);
        }
        for (const std::string& label : order) {
            figure.add(
                panel_of[label],
                write_series(
                    o, "data/speed_" + c.key + "_" + std::to_string(figure.files.size()) + ".dat",
                    by_label[label]),
                comb.rotation_name());
        }
    }
    const nlohmann::json out = {
        {"case", c.key}, {"front", front_table(o, c, points, md)}, {"points", points.size()}};
    winners_in_words(points, md);
    plot_panels(o, figure,
                {{"xcol", "3"},
                 {"ycol", "4"},
                 {"xlabel", "in-process wall time to solution, median of repeats [s]"},
                 {"ylabel", c.ylabel},
                 {"plottitle", c.title + ": one panel per discretization family, the "
                                         "parameterizations inside, the Pareto front of all in "
                                         "every panel"},
                 {"outbase", out_path(o, "speed-" + c.key)},
                 {"logx", "1"},
                 {"logy", "1"},
                 {"extra", out_path(o, "data/speed_" + c.key + "_front.dat")},
                 {"extratitle", "Pareto front (all combinations)"}});
    md << "![speed-" << c.key << ".png](speed-" << c.key << ".png)\n\n";
    return out;
}

}  // namespace

namespace {

const char* analysis_name(AnalysisKind k) {
    switch (k) {
        case AnalysisKind::static_:
            return "static";
        case AnalysisKind::dynamic:
            return "dynamic";
        case AnalysisKind::modal:
            return "modal";
    }
    return "static";
}

// What each catalog analysis assembled (the result's `counters`), with its own combination; a
// dynamic case is shortened to 10 time steps (the counters show which terms exist, not how many
// steps there are).
nlohmann::json counters_table(const StudyOptions& o, std::ostringstream& md) {
    const char* keys[] = {"residual_evaluations",   "jacobian_evaluations", "elastic_terms",
                          "inertial_terms",         "damping_terms",        "follower_stiffness",
                          "distributed_load_terms", "gravity_terms"};
    md << "### Model only what the scene requires\n\nThe assembly counters of every catalog "
          "analysis with its own formulation and parameterization (dynamic cases shortened to 10 "
          "time steps). A static case must show no inertial terms, an undamped case no damping "
          "terms, a case without follower loads no follower stiffness.\n\n"
          "| case | analysis | combination | status | residuals | Jacobians | elastic | inertial | "
          "damping | follower | distributed | gravity |\n|---|---|---|---|---|---|---|---|---|---|"
          "---|---|\n";
    nlohmann::json out = nlohmann::json::array();
    for (const std::string& name : catalog_cases()) {
        const Model model = load_case(resolve_case_path(name));
        if (o.quick && model.analysis.kind == AnalysisKind::dynamic) continue;
        std::vector<std::string> ov;
        if (model.analysis.kind == AnalysisKind::dynamic) {
            ov.push_back("analysis.end_time=" + sci(10.0 * model.analysis.dynamics.time_step, 17));
        }
        const Combination c{model.discretization.formulation, model.discretization.rotation};
        const nlohmann::json r = run_spec({name, c, ov, 0});
        md << "| " << name << " | " << analysis_name(model.analysis.kind) << " | " << c.label()
           << " | "
           << (r.value("available", true) ? r.value("status", "error")
                                          : std::string("not available yet"))
           << " |";
        for (const char* k : keys) {
            md << " " << (r.contains("counters") ? r["counters"].value(k, 0L) : 0L) << " |";
        }
        md << "\n";
        out.push_back({{"case", name},
                       {"status", r.value("status", "error")},
                       {"counters", r.value("counters", nlohmann::json::object())}});
    }
    md << "\n";
    return out;
}

}  // namespace

nlohmann::json study_speed_accuracy(const StudyOptions& o) {
    std::ostringstream md;
    md << "## Study: speed versus accuracy\n\nEvery combination across meshes and orders "
          "(displacement: order 1 … 12; mixed: 8 … 512 elements), error against the in-process "
          "wall time of run_case (median of repeats, timing.hpp) on a shared 2-core machine. The "
          "black staircase is the Pareto front across all combinations.\n\n";
    nlohmann::json out = {
        {"study", "speed-accuracy"}, {"quick", o.quick}, {"cases", nlohmann::json::array()}};
    for (const SpeedCase& c : speed_cases()) out["cases"].push_back(speed_case(o, c, md));
    out["dynamics"] = dynamic_speed_section(o, md);
    out["counters"] = counters_table(o, md);
    out["assembly_savings"] = assembly_savings(o, md);
    write_text(o, "study-speed-accuracy.md", md.str());
    out["schema_version"] = kSchemaVersion;
    write_text(o, "study-speed-accuracy.json", out.dump(1) + "\n");
    return out;
}

}  // namespace rotbeam::cli
