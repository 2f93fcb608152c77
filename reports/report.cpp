#include "report.hpp"

#include <sys/utsname.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "core/choices.hpp"
#include "core/results.hpp"
#include "core/version.hpp"
#include "parameterizations/registry.hpp"
#include "report_dynamics.hpp"
#include "report_estimator_failures.hpp"
#include "report_ribbon.hpp"
#include "report_summary.hpp"
#include "report_table_one.hpp"
#include "runs/run_file.hpp"
#include "studies/gnuplot.hpp"
#include "studies/study_common.hpp"

namespace rotbeam::cli {

namespace fs = std::filesystem;

namespace {

struct Figure {
    std::string file;     // PNG name in DIR
    std::string caption;  // one sentence on what it shows
};

std::string machine_description() {
    utsname u{};
    uname(&u);
    std::ostringstream s;
    s << u.sysname << " " << u.release << " " << u.machine;
    return s.str();
}

std::string today() {
    const std::time_t t = std::time(nullptr);
    std::ostringstream s;
    s << std::put_time(std::gmtime(&t), "%Y-%m-%d %H:%M UTC");
    return s.str();
}

nlohmann::json read_json(const std::string& path) {
    std::ifstream in(path);
    if (!in) return nlohmann::json();
    try {
        return nlohmann::json::parse(in);
    } catch (const std::exception&) {
        return nlohmann::json();
    }
}

// The roll-up's tip path u1/L, u3/L against λ for every converged combination, plus the exact
// solution, as a data file per combination.
std::vector<Figure> rollup_figures(const std::string& out,
                                   const std::vector<nlohmann::json>& runs) {
    const fs::path data = fs::path(out) / "data";
    fs::create_directories(data);
    std::string files;
    for (const nlohmann::json& r : runs) {
        if (r.value("case", "") != "cantilever-moment" || r["steps"].empty()) continue;
        const std::string name =
            r["rotation"].get<std::string>() + "-" + r["formulation"].get<std::string>();
        const fs::path file = data / ("rollup_" + name + ".dat");
        std::ostringstream f;
        f << "# load_factor u1 u3 newton_iterations (" << name << ")\n";
        for (const auto& s : r["steps"]) {
            const auto& u = s["points"]["tip"]["displacement"];
            f << s["load_factor"].get<double>() << " " << u[0].get<double>() << " "
              << u[2].get<double>() << " " << s["newton_iterations"] << "\n";
        }
        write_file_atomically(file.string(), f.str());
        files += file.string() + " ";
    }
    if (files.empty()) return {};
    const std::string png = "rollup-tip.png";
    run_gnuplot_script("rollup_tip.gp",
                       {{"files", files}, {"outbase", (fs::path(out) / "rollup-tip").string()}});
    return {{png,
             "Tip displacement of the moment-loaded cantilever (seed 002 Example 1) against the "
             "load factor λ for every combination that ran, over the exact solution (lines; "
             "coinciding combinations show as nested markers), and below it each combination's "
             "tip error ‖u − u_exact‖/L, where they separate."}};
}

// Fig. 3 of seed 002: the roll-up's deformed centre lines for every reported λ, from the
// displacement/quaternion run (the one with node positions), over the exact arcs.
std::vector<Figure> rollup_shape_figures(const std::string& out,
                                         const std::vector<nlohmann::json>& runs) {
    for (const nlohmann::json& r : runs) {
        if (r.value("case", "") != "cantilever-moment" ||
            param::parse_parameterization(r.value("rotation", "")) !=
                param::id_of<param::Quaternion>() ||
            parse_choice<Formulation>(r.value("formulation", "")) != Formulation::displacement ||
            r["steps"].empty() || !r["steps"][0].contains("centerline")) {
            continue;
        }
        const fs::path file = fs::path(out) / "data" / "rollup_shapes.dat";
        fs::create_directories(file.parent_path());
        std::ostringstream f;
        std::ostringstream lambdas;
        for (const auto& s : r["steps"]) {
            f << "# lambda " << s["load_factor"].get<double>() << "\n";
            for (const auto& p : s["centerline"]) {
                f << p[1].get<double>() << " " << p[3].get<double>() << "\n";
            }
            f << "\n\n";
            lambdas << s["load_factor"].get<double>() << " ";
        }
        write_file_atomically(file.string(), f.str());
        run_gnuplot_script("rollup_shapes.gp",
                           {{"datafile", file.string()},
                            {"lambdas", lambdas.str()},
                            {"outbase", (fs::path(out) / "rollup-shapes").string()}});
        return {{"rollup-shapes.png",
                 "Seed 002 Fig. 3: deformed shapes of the moment-loaded cantilever for every "
                 "reported λ (displacement formulation, quaternion, the case's 16 elements of "
                 "order 4; points are the nodes) over the exact circular arcs (lines)."}};
    }
    return {};
}

// Columns: angle, then per parameterization σ_min(H_m) and the round-trip error ("?" where
// undefined); the header row names them for gnuplot's columnheader.
bool write_rotation_study_data(const nlohmann::json& study, const std::string& path) {
    const auto& list = study["parameterizations"];
    if (!list.is_array() || list.empty()) return false;
    std::ostringstream f;
    f << "angle";
    for (const auto& p : list) {
        const std::string name = p["name"].get<std::string>();
        f << " " << name << " " << name;  // σ_min column, round-trip column
    }
    f << "\n" << std::setprecision(10);
    const size_t n = study["angles"].size();
    auto value = [](const nlohmann::json& row, const char* key) -> std::string {
        if (!row.contains(key) || !row[key].is_number()) return "?";
        std::ostringstream s;
        s << std::setprecision(10) << row[key].get<double>();
        return s.str();
    };
    for (size_t i = 0; i < n; ++i) {
        f << study["angles"][i].get<double>();
        for (const auto& p : list) {
            const auto& row = p["samples"][i];
            f << " " << value(row, "sigma_min") << " " << value(row, "round_trip_error");
        }
        f << "\n";
    }
    write_file_atomically(path, f.str());
    return true;
}

std::vector<Figure> rotation_study_figures(const std::string& out) {
    const nlohmann::json study = read_json((fs::path(out) / "rotation-study.json").string());
    if (study.is_null()) return {};
    const fs::path data = fs::path(out) / "data" / "rotation-study.dat";
    fs::create_directories(data.parent_path());
    if (!write_rotation_study_data(study, data.string())) return {};
    run_gnuplot_script(
        "rotation_study.gp",
        {{"datafile", data.string()}, {"outbase", (fs::path(out) / "rotation-study").string()}});
    return {{"rotation-study.png",
             "Smallest singular value of the material tangent H_m and the round-trip error of each "
             "parameterization against the rotation angle (0 … 4π): where each one becomes "
             "singular."}};
}

// The contents: a link to every level-2 section of `body`, which follows the summary and the
// contents themselves (their headings come first in the page's ids, heading_id()).
std::string contents(const std::string& body) {
    std::map<std::string, int> used;
    heading_id("Summary", used);
    heading_id("Contents", used);
    std::ostringstream md;
    md << "## Contents\n\n";
    std::istringstream in(body);
    bool fenced = false;
    for (std::string line; std::getline(in, line);) {
        if (line.rfind("```", 0) == 0) fenced = !fenced;
        if (fenced || line.rfind("## ", 0) != 0) continue;
        std::string title = line.substr(3);
        // The heading's text as the HTML page has it: without code-span and emphasis marks.
        std::string plain;
        for (char c : title) {
            if (c != '`' && c != '*') plain += c;
        }
        md << "- [" << markdown_cell(plain) << "](#" << heading_id(plain, used) << ")\n";
    }
    return md.str() + "\n";
}

}  // namespace

void write_report(const std::string& out_dir, const std::vector<std::string>& run_files,
                  const std::vector<std::string>& study_names,
                  const nlohmann::json& published_checks) {
    std::vector<nlohmann::json> runs;
    for (const std::string& f : run_files) {
        // A run whose result was not written (it failed to write) has no row; a result that is
        // there was checked when the suite or the merge began and is checked again here.
        if (fs::exists(f)) runs.push_back(*read_run_file(f, RunFileKind::case_run, std::nullopt));
    }
    std::ostringstream md;
    md << "## Runs\n\nEvery static, modal and dynamic catalog case with every "
       << "parameterization and formulation at the case's own mesh. `status` is the solver's own "
       << "verdict; `displacement / frequencies` is the tip (or joint) displacement at the last "
          "converged step (the last output time of a dynamic run), or the natural frequencies of "
          "a modal run; `estimate` the run's worst estimated error relative to its scale "
          "(docs/error-estimates.md; the suite estimates every run unless `--estimate off`); "
          "`true error` the error "
          "against the exact solution (the roll-up, ‖Δu‖/L at the last converged step) or the "
          "largest difference to the published values checked at the case's own discretization "
          "(— without a reference).\n\n"
       << "| case | elements | rotation | formulation | status | steps | Newton iterations | "
          "wall [s] | displacement / frequencies [Hz] | estimate | true error |\n"
          "|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (size_t i = 0; i < runs.size(); ++i) {
        const nlohmann::json& r = runs[i];
        int iterations = 0;
        for (const auto& s : r["steps"]) iterations += s.value("newton_iterations", 0);
        std::ostringstream last;
        if (!r["steps"].empty()) {
            const auto& points = r["steps"].back()["points"];
            for (const char* name : {"tip", "joint"}) {
                if (!points.contains(name)) continue;
                const auto& u = points[name]["displacement"];
                last << std::setprecision(6) << name << " [" << u[0].get<double>() << ", "
                     << u[1].get<double>() << ", " << u[2].get<double>() << "]";
            }
        }
        if (r.contains("frequencies_hz")) {
            last << std::setprecision(6);
            for (const auto& f : r["frequencies_hz"]) last << f.get<double>() << " ";
        }
        std::string message = r.value("status", "error");
        if (message != "converged") {
            std::string m = r.value("message", "");
            if (m.size() > 90) m = m.substr(0, 87) + "...";
            message += ": " + m;
        }
        message = markdown_cell(message);
        // The row's anchor, the target of the summary's links.
        md << "| <a id=\"" << run_row_id(i) << "\"></a>" << r.value("case", "") << " | "
           << r.value("elements", 0) << " | " << r.value("rotation", "") << " | "
           << r.value("formulation", "") << " | " << message << " | " << r["steps"].size() << " | "
           << iterations << " | " << std::setprecision(3) << r.value("wall_seconds", 0.0) << " | "
           << last.str() << " | " << estimate_cell(r) << " | "
           << true_error_cell(r, published_checks) << " |\n";
    }
    md << "\n"
       << estimator_failures_section(runs) << table_one_section("cantilever-moment", runs)
       << table_three_section(runs) << joined_beam_histories_section(out_dir, runs)
       << blade_histories_section(out_dir, runs);
    {
        std::ifstream published(fs::path(out_dir) / "published.md");
        if (published) md << published.rdbuf();
    }
    std::vector<Figure> figures = rollup_figures(out_dir, runs);
    for (Figure& f : rollup_shape_figures(out_dir, runs)) figures.push_back(f);
    if (auto f = rollup_ribbon_figure(out_dir, runs)) figures.push_back({f->file, f->caption});
    for (Figure& f : rotation_study_figures(out_dir)) figures.push_back(f);
    md << "\n## Figures\n\n";
    if (figures.empty()) md << "(no figures: gnuplot missing or no data)\n";
    for (const Figure& f : figures)
        md << "![" << f.caption << "](" << f.file << ")\n\n" << f.caption << "\n\n";
    // The static studies, each a section written by its study function, when present.
    for (const std::string& name : study_names) {
        std::ifstream study(fs::path(out_dir) / ("study-" + name + ".md"));
        if (study) md << "\n" << study.rdbuf() << "\n";
    }
    const std::string body = md.str();
    std::ostringstream page;
    page << "# rotbeam report\n\nrotbeam " << kGitDescribe << ", " << machine_description() << ", "
         << today() << ".\n\n"
         << summary_section(runs, published_checks) << contents(body) << body;
    write_file_atomically((fs::path(out_dir) / "index.md").string(), page.str());
    write_file_atomically((fs::path(out_dir) / "index.html").string(),
                          markdown_page_html(page.str(), out_dir));
}

}  // namespace rotbeam::cli
