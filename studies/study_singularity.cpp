// `rotbeam study singularity` (statics): every combination and interpolation
// strategy on the roll-up to λ = 4 (two full turns; exact) and on the helices to κL = 4π
// (continuum reference): the largest tip rotation reached, how the run stopped (diverged,
// singular, or wrong branch = converged but off the answer), Newton iterations against λ, and the
// mixed formulation's reach against the mesh, λ*(N).
//
// Every converged step is compared, not only the last: a run can be "converged" on another
// equilibrium branch and return to the right one later (classify_reach in study_math.hpp).
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

// Accuracy tolerance on ‖Δu_tip‖/L along the path. Another equilibrium branch is O(0.1–1) L away
// and appears as a jump (classify_reach); the catalog meshes' discretization errors are below this
// on the roll-up and the isotropic helix (16 order-4 displacement elements ~1e-7, 16 mixed elements
// ≤ ~7e-3 up to λ = 4), while on the precessing helix the coarse mixed mesh drifts past it
// smoothly ("lost accuracy").
constexpr double kWrongBranchTolerance = 2e-2;

struct PathCase {
    std::string key, case_name, title;
    double end = 0.0;  // last load factor
    int steps = 0;     // reported steps (equal increments)
    int substeps = 1;
    bool exact_rollup = false;
    std::string angle_unit;  // how the load factor reads as a tip rotation
    double angle_per_unit = 0.0;
};

std::vector<PathCase> path_cases(bool quick) {
    std::vector<PathCase> c = {
        {"rollup", "cantilever-moment-4", "roll-up to λ = 4", 4.0, 32, 1, true, "λ", kPi},
        {"helix", "helix", "helix to κL = 4π", 4.0 * kPi, 32, 1, false, "κL", 1.0}};
    if (!quick) {
        c.push_back({"helix-precessing", "helix-precessing", "precessing helix to κL = 4π",
                     4.0 * kPi, 32, 5, false, "κL", 1.0});
    }
    return c;
}

std::vector<std::string> path_overrides(const PathCase& c) {
    std::ostringstream list;
    list.precision(17);
    list << "analysis.load_factors=[";
    for (int i = 1; i <= c.steps; ++i) list << (i > 1 ? "," : "") << c.end * i / c.steps;
    list << "]";
    return {list.str(), "analysis.substeps=" + std::to_string(c.substeps)};
}

struct PathRun {
    Reach reach;
    std::string status, message;
    double max_error = 0.0, reach_angle = 0.0;
    std::vector<double> lambda, error, iterations;
};

RunSpec path_spec(const PathCase& c, const Combination& comb, int elements) {
    return RunSpec{c.case_name, comb, path_overrides(c), elements};
}

// Where the results go in the plan.
std::string reference_key(const PathCase& c) { return "path/" + c.key + "/reference"; }
std::string path_key(const PathCase& c, const Combination& comb) {
    return "path/" + c.key + "/" + comb.label();
}
std::string mesh_key(const Combination& comb, int elements) {
    return "mesh/" + comb.label() + "/" + std::to_string(elements);
}

// A path run from its result `r` (of path_spec(c, comb, elements)): every converged step against
// the answer, and the reach.
PathRun path_run(const PathCase& c, const Combination& comb, int elements, const nlohmann::json& r,
                 const nlohmann::json& reference) {
    const RunSpec spec = path_spec(c, comb, elements);
    PathRun p;
    p.status = r.value("status", "error");
    p.message = r.value("message", "");
    if (p.status == "unavailable") return p;
    const double length = member_length(build_model(spec));
    std::vector<ConvergedStep> steps;
    for (const auto& s : r["steps"]) {
        const double e = c.exact_rollup ? rollup_tip_error(s, length)
                                        : reference_tip_error(s, reference, length);
        steps.push_back({s["load_factor"].get<double>(), e});
        p.lambda.push_back(steps.back().load_factor);
        p.error.push_back(e);
        p.iterations.push_back(s.value("newton_iterations", 0));
    }
    p.reach = classify_reach(steps, p.status, c.steps, kWrongBranchTolerance);
    for (int i = 0; i < p.reach.steps_reached; ++i) {
        p.max_error = std::max(p.max_error, p.error[static_cast<size_t>(i)]);
        p.reach_angle = r["steps"][i]["points"]["tip"]["rotation_angle"].get<double>();
    }
    return p;
}

}  // namespace

namespace {

// "λ error iterations" rows of one run (all converged steps).
std::string path_data(const StudyOptions& o, const std::string& name, const PathRun& p) {
    std::ostringstream s;
    s.precision(10);
    s << "# load_factor tip_error newton_iterations\n";
    for (size_t i = 0; i < p.lambda.size(); ++i) {
        s << p.lambda[i] << " " << std::max(p.error[i], 1e-17) << " " << p.iterations[i] << "\n";
    }
    write_text(o, "data/" + name + ".dat", s.str());
    return out_path(o, "data/" + name + ".dat");
}

std::string panel_of(const Combination& c) {
    return c.formulation == Formulation::mixed
               ? std::string("mixed")
               : "displacement, " + std::string(choice_name(*c.interpolation)) + " interpolation";
}

void path_plots(const StudyOptions& o, const PathCase& c, const PanelFigure& figure,
                nlohmann::json& figures) {
    const std::string xlabel = c.angle_unit == "λ" ? "load factor λ (tip rotation λπ rad) [-]"
                                                   : "load factor κL [rad] (the tip angle for "
                                                     "the isotropic helix)";
    const std::string base = "singularity-" + c.key;
    plot_panels(o, figure,
                {{"xcol", "1"},
                 {"ycol", "2"},
                 {"xlabel", xlabel},
                 {"ylabel", "tip error ‖Δu‖/L [-]"},
                 {"plottitle", c.title + ": error along the path (every converged step)"},
                 {"outbase", out_path(o, base + "-error")},
                 {"logx", "0"},
                 {"logy", "1"},
                 {"hline", sci(kWrongBranchTolerance)},
                 {"hlabel", "accuracy tolerance (wrong branch / lost accuracy)"}});
    plot_panels(o, figure,
                {{"xcol", "1"},
                 {"ycol", "3"},
                 {"xlabel", xlabel},
                 {"ylabel", "Newton iterations per reported step [-]"},
                 {"plottitle", c.title + ": Newton iterations vs load"},
                 {"outbase", out_path(o, base + "-iterations")},
                 {"logx", "0"},
                 {"logy", "0"}});
    figures.push_back(base + "-error.png");
    figures.push_back(base + "-iterations.png");
}

nlohmann::json path_case(const StudyOptions& o, const PathCase& c, const StudyResults& results,
                         std::ostringstream& md) {
    const nlohmann::json reference =
        c.exact_rollup ? nlohmann::json() : result_of(results, reference_key(c));
    nlohmann::json out = {
        {"case", c.key}, {"runs", nlohmann::json::array()}, {"figures", nlohmann::json::array()}};
    PanelFigure figure;
    for (const Combination& comb : all_combinations(true)) {
        const PathRun p = path_run(c, comb, 0, result_of(results, path_key(c, comb)), reference);
        std::string message = p.message;
        if (message.size() > 110) message = message.substr(0, 107) + "...";
        out["runs"].push_back({{"combination", comb.label()},
                               {"status", p.status},
                               {"reach_load_factor", p.reach.load_factor},
                               {"reach_angle", p.reach_angle},
                               {"stopped", p.reach.stopped},
                               {"max_error", p.max_error},
                               {"message", p.message}});
        if (p.status == "unavailable") {
            md << "| " << c.key << " | " << comb.label() << " | — | — | unavailable | — | "
               << markdown_cell(message) << " |\n";
            continue;
        }
        md << "| " << c.key << " | " << comb.label() << " | "
           << fixed_as_printed(p.reach.load_factor, 3) << " | "
           << fixed_as_printed(p.reach_angle / kPi, 2) << "π | " << p.reach.stopped << " | "
           << sci(p.max_error) << " | "
           << (p.reach.stopped == "completed" ? "" : markdown_cell(message)) << " |\n";
        if (p.lambda.empty()) continue;
        figure.add(
            panel_of(comb),
            path_data(o, "singularity_" + c.key + "_" + std::to_string(figure.files.size()), p),
            comb.rotation_name());
    }
    if (!figure.files.empty()) path_plots(o, c, figure, out["figures"]);
    return out;
}

}  // namespace

namespace {

// The driver's own last converged load factor (its step cutting bisects to ~4e-4 of a step), from
// the message "... last converged load factor X ...": sharper than the reported steps.
double last_converged_factor(const std::string& message, double fallback) {
    const std::string key = "last converged load factor ";
    const size_t at = message.find(key);
    if (at == std::string::npos) return fallback;
    try {
        return std::stod(message.substr(at + key.size()));
    } catch (const std::exception&) {
        return fallback;
    }
}

// Mixed formulation: the reach on the roll-up against the mesh.
PathCase mesh_case() { return path_cases(true).front(); }
std::vector<int> singularity_meshes(bool quick) {
    return quick ? std::vector<int>{4, 16} : std::vector<int>{4, 8, 16, 32, 64};
}

nlohmann::json mixed_reach_vs_mesh(const StudyOptions& o, const StudyResults& results,
                                   std::ostringstream& md, nlohmann::json& figures) {
    const PathCase c = mesh_case();
    const std::vector<int> meshes = singularity_meshes(o.quick);
    nlohmann::json out = nlohmann::json::array();
    PanelFigure figure;
    md << "\n| mixed combination |";
    for (int n : meshes) md << " N = " << n << " |";
    md << "\n|---|";
    for (size_t i = 0; i < meshes.size(); ++i) md << "---|";
    md << "\n";
    for (const Combination& comb : all_combinations(false)) {
        if (comb.formulation != Formulation::mixed) continue;
        std::ostringstream data, row;
        data << "# elements lambda_star\n";
        bool any = false;
        for (int n : meshes) {
            const PathRun p =
                path_run(c, comb, n, result_of(results, mesh_key(comb, n)), nlohmann::json());
            if (p.status == "unavailable") break;
            any = true;
            // The solver's reach (accuracy is the table above's concern: a 4-element mesh is
            // coarse, not on another branch).
            const double last = p.lambda.empty() ? 0.0 : p.lambda.back();
            const double star =
                has_solution(p.status) ? last : last_converged_factor(p.message, last);
            double max_error = 0.0;
            for (double e : p.error) max_error = std::max(max_error, e);
            data << n << " " << star << "\n";
            row << " " << fixed_as_printed(star, 4) << (has_solution(p.status) ? " (all)" : "")
                << ", " << sci(max_error, 1) << " |";
            out.push_back({{"combination", comb.label()},
                           {"elements", n},
                           {"lambda_star", star},
                           {"status", p.status},
                           {"max_error", max_error}});
        }
        if (!any) continue;
        md << "| " << comb.label() << " |" << row.str() << "\n";
        write_text(o, "data/lambda_star_" + comb.rotation_name() + ".dat", data.str());
        figure.add("mixed formulation (λ* = 4: every step converged)",
                   out_path(o, "data/lambda_star_" + comb.rotation_name() + ".dat"), comb.label());
    }
    if (!figure.files.empty()) {
        plot_panels(
            o, figure,
            {{"xcol", "1"},
             {"ycol", "2"},
             {"xlabel", "elements N [-]"},
             {"ylabel", "largest load factor reached λ* (tip rotation λ*π) [-]"},
             {"plottitle", "Mixed formulation: reach on the roll-up against the mesh, λ*(N)"},
             {"outbase", out_path(o, "singularity-lambda-star")},
             {"logx", "1"},
             {"logy", "0"}});
        figures.push_back("singularity-lambda-star.png");
    }
    return out;
}

// The runs: the continuum reference of each path without an exact solution, every combination
// on every path, and the mixed combinations on the roll-up for every mesh of λ*(N).
std::vector<StudyRun> singularity_plan(const StudyOptions& o) {
    std::vector<StudyRun> plan;
    for (const PathCase& c : path_cases(o.quick)) {
        if (!c.exact_rollup) {
            plan.push_back({reference_key(c), StudyRun::Kind::continuum_reference,
                            RunSpec{c.case_name, {}, path_overrides(c), 0}});
        }
        for (const Combination& comb : all_combinations(true)) {
            plan.push_back({path_key(c, comb), StudyRun::Kind::case_run, path_spec(c, comb, 0)});
        }
    }
    for (const Combination& comb : all_combinations(false)) {
        if (comb.formulation != Formulation::mixed) continue;
        for (int n : singularity_meshes(o.quick)) {
            plan.push_back(
                {mesh_key(comb, n), StudyRun::Kind::case_run, path_spec(mesh_case(), comb, n)});
        }
    }
    return plan;
}

nlohmann::json singularity_combine(const StudyOptions& o, const StudyResults& results) {
    std::ostringstream table, mesh_table;
    nlohmann::json out = {{"study", "singularity"},
                          {"quick", o.quick},
                          {"wrong_branch_tolerance", kWrongBranchTolerance},
                          {"cases", nlohmann::json::array()}};
    for (const PathCase& c : path_cases(o.quick)) {
        out["cases"].push_back(path_case(o, c, results, table));
    }
    nlohmann::json figures = nlohmann::json::array();
    out["lambda_star"] = mixed_reach_vs_mesh(o, results, mesh_table, figures);
    std::ostringstream md;
    md << "## Study: singularity limits\n\nEvery combination (displacement: relative and direct "
          "interpolation) on the roll-up to λ = 4 (two full turns, 32 equal steps, exact "
          "solution) and the helices to κL = 4π (32 steps, continuum reference), each at its "
          "catalog mesh. Every converged step is compared with the answer: `wrong branch` = "
          "converged but ‖Δu_tip‖/L > "
       << sci(kWrongBranchTolerance)
       << " with a jump of more than 10× over the previous step (another equilibrium); `lost "
          "accuracy` = the error grew smoothly past that tolerance (discretization error "
          "accumulating along the path, not a branch switch). `reach` is "
          "the last load factor on the right branch and the tip rotation there; σ_min(H), ‖H⁻¹‖ "
          "and round-trip errors against the angle are the rotation study's figure.\n\n"
       << "| case | combination | reach | tip angle | stopped | max error on the branch | "
          "message |\n|---|---|---|---|---|---|---|\n"
       << table.str()
       << "\n### Mixed formulation: λ*(N)\n\nThe largest roll-up load factor the mixed "
          "formulation's solver reaches against the number of elements (the driver's last "
          "converged "
          "load factor when it stops), and the largest tip error ‖Δu‖/L along the way.\n"
       << mesh_table.str() << "\n";
    for (const auto& c : out["cases"])
        for (const auto& f : c["figures"]) figures.push_back(f);
    for (const auto& f : figures) {
        md << "![" << f.get<std::string>() << "](" << f.get<std::string>() << ")\n\n";
    }
    write_text(o, "study-singularity.md", md.str());
    out["schema_version"] = kSchemaVersion;
    write_text(o, "study-singularity.json", out.dump(1) + "\n");
    return out;
}

}  // namespace

SplitStudy singularity_study() { return {singularity_plan, singularity_combine}; }

nlohmann::json study_singularity(const StudyOptions& o) {
    return run_split_study(singularity_study(), o);
}

}  // namespace rotbeam::cli
