#include "study_common.hpp"

#include <cmath>
#include <filesystem>
#include <map>
#include <sstream>

#include "cases/loader/case_loader.hpp"
#include "core/errors.hpp"
#include "core/oracles/rollup.hpp"
#include "core/results.hpp"
#include "effectivity_motion.hpp"
#include "gnuplot.hpp"
#include "manufactured_rod_case.hpp"
#include "parameterizations/registry.hpp"
#include "runs/catalog.hpp"
#include "runs/continuum_json.hpp"
#include "runs/run_case.hpp"

namespace rotbeam::cli {

const char* const kExactBendTip = "points.tip=[70.71067811865476, 29.289321881345245, 0]";

namespace fs = std::filesystem;

std::vector<Combination> all_combinations(bool with_interpolation) {
    return comb::all_combinations(with_interpolation);
}

oracle::ManufacturedRod manufactured_rod() {
    oracle::ManufacturedRod rod;
    rod.stiffness = oracle::manufactured_section();
    return rod;
}

namespace {

Model manufactured_rod_model(const RunSpec& spec) {
    Model model = oracle::manufactured_model(
        manufactured_rod(), spec.elements > 0 ? spec.elements : 2, kManufacturedRodSteps);
    const Combination& c = spec.combination;
    model.discretization.formulation = c.formulation;
    model.discretization.rotation = c.rotation;
    if (c.interpolation) model.discretization.displacement.interpolation = *c.interpolation;
    if (c.wm_map) model.discretization.mixed.wm_map = *c.wm_map;
    const std::string order_key = "discretization.order=";
    const std::string coarser = "analysis.estimate_companions=coarser";
    for (const std::string& o : spec.overrides) {
        if (o == coarser) {
            model.analysis.estimate_companions = CompanionSide::coarser;
            continue;
        }
        if (o.rfind(order_key, 0) != 0) {
            throw InputError(std::string(kManufacturedRodCase) + ": " + o + ": only " + order_key +
                             "N and " + coarser + " apply to the built-in model");
        }
        try {
            model.discretization.order = std::stoi(o.substr(order_key.size()));
        } catch (const std::exception&) {
            throw InputError(std::string(kManufacturedRodCase) + ": " + o + ": not an order");
        }
    }
    return model;
}

}  // namespace

Model build_model(const RunSpec& spec) {
    if (spec.case_name == kManufacturedRodCase) return manufactured_rod_model(spec);
    if (spec.case_name == kManufacturedMotionCase) return motion_run_model(motion_spec_of(spec));
    const Combination& c = spec.combination;
    std::vector<std::string> overrides = {
        "discretization.formulation=" + std::string(choice_name(c.formulation)),
        "discretization.rotation=" + std::string(param::name_of(c.rotation))};
    if (c.interpolation) {
        overrides.push_back("discretization.interpolation=" +
                            std::string(choice_name(*c.interpolation)));
    }
    if (c.wm_map) {
        overrides.push_back("discretization.wm_map=" + std::string(choice_name(*c.wm_map)));
    }
    overrides.insert(overrides.end(), spec.overrides.begin(), spec.overrides.end());
    Model model = load_case(resolve_case_path(spec.case_name), overrides);
    if (spec.elements > 0) {
        for (Member& m : model.members) m.elements = spec.elements;
    }
    return model;
}

nlohmann::json run_spec(const RunSpec& spec, bool estimate) {
    try {
        if (spec.case_name == kManufacturedMotionCase) {
            const MotionRunSpec m = motion_spec_of(spec);
            return estimate ? estimated_motion_run(m)
                            : motion_result_json(run_manufactured_motion(m));
        }
        const Model model = build_model(spec);
        if (estimate) {
            SolvedPath solved;
            RunRequest request{spec.case_name, model, false};
            request.path = &solved;
            nlohmann::json result = run_case(request);
            add_run_estimate(request, result);
            return result;
        }
        return run_case(RunRequest{spec.case_name, model, false});
    } catch (const InputError& e) {
        return {{"status", "unavailable"},
                {"message", e.what()},
                {"steps", nlohmann::json::array()},
                {"dofs", 0},
                {"wall_seconds", 0.0}};
    }
}

bool converged_steps_exist(const nlohmann::json& result) {
    return result.contains("steps") && !result["steps"].empty();
}

double member_length(const Model& model) {
    ROTBEAM_VERIFY(model.members.size() == 1, "member_length: single-member cases only");
    const Member& m = model.members.front();
    return (model.points[static_cast<size_t>(m.end_point)].position -
            model.points[static_cast<size_t>(m.start_point)].position)
        .norm();
}

Vec3 point_displacement(const nlohmann::json& step, const std::string& point) {
    const auto& u = step["points"][point]["displacement"];
    return Vec3(u[0].get<double>(), u[1].get<double>(), u[2].get<double>());
}

double rollup_tip_error(const nlohmann::json& step, double length) {
    const double lambda = step["load_factor"].get<double>();
    const Vec3 exact = oracle::rollup_tip(length, lambda).displacement;
    return (point_displacement(step) - exact).norm() / length;
}

double reference_tip_error(const nlohmann::json& step, const nlohmann::json& reference,
                           double scale) {
    const double lambda = step["load_factor"].get<double>();
    for (const auto& r : reference["steps"]) {
        if (std::abs(r["load_factor"].get<double>() - lambda) <= 1e-12 * std::abs(lambda)) {
            return (point_displacement(step) - point_displacement(r)).norm() / scale;
        }
    }
    return kNoValue;
}

std::mutex& gsl_mutex() {
    static std::mutex m;
    return m;
}

nlohmann::json continuum_reference(const std::string& case_name,
                                   const std::vector<std::string>& overrides) {
    const std::lock_guard<std::mutex> lock(gsl_mutex());
    const std::string path = resolve_case_path(case_name);
    return continuum_result_json(load_case(path, overrides), path);
}

int total_newton_iterations(const nlohmann::json& result) {
    int n = 0;
    for (const auto& s : result["steps"]) n += s.value("newton_iterations", 0);
    return n;
}

std::string write_series(const StudyOptions& o, const std::string& relative_path,
                         const Series& series) {
    std::ostringstream s;
    s.precision(12);
    s << "# " << series.label << ": elements dofs seconds error\n";
    bool broken = false, written = false;
    for (size_t i = 0; i < series.error.size(); ++i) {
        // A run without a result breaks the curve (a blank line: gnuplot does not join across
        // it), so a failed setting is never bridged by a line between its neighbours.
        if (!std::isfinite(series.error[i])) {
            broken = written;
            continue;
        }
        if (broken) s << "\n";
        broken = false;
        written = true;
        s << series.elements[i] << " " << series.dofs[i] << " " << series.seconds[i] << " "
          << std::max(series.error[i], 1e-17) << "\n";  // log axes: exact zero drawn at 1e-17
    }
    write_text(o, relative_path, s.str());
    return out_path(o, relative_path);
}

std::string join_words(const std::vector<std::string>& words) {
    std::string s;
    for (const std::string& w : words) s += (s.empty() ? "" : " ") + w;
    return s;
}

std::string out_path(const StudyOptions& o, const std::string& relative_path) {
    return (fs::path(o.out_dir) / relative_path).string();
}

void write_text(const StudyOptions& o, const std::string& relative_path, const std::string& text) {
    const fs::path p = fs::path(o.out_dir) / relative_path;
    fs::create_directories(p.parent_path());
    write_file_atomically(p.string(), text);
}

void plot(const std::string& script, const std::vector<std::pair<std::string, std::string>>& vars) {
    std::map<std::string, std::string> m(vars.begin(), vars.end());
    run_gnuplot_script(script, m);
}

std::string sci(double value, int digits) {
    if (!std::isfinite(value)) return "—";
    std::ostringstream s;
    s.precision(digits);
    s << std::scientific << value;
    return s.str();
}

std::string fixed(double value, int digits) {
    if (!std::isfinite(value)) return "—";
    return fixed_as_printed(value, digits);
}

std::string fixed_as_printed(double value, int digits) {
    std::ostringstream s;
    s.precision(digits);
    s << std::fixed << value;
    return s.str();
}

std::string quoted(const std::string& s) { return "\"" + s + "\""; }

std::string markdown_cell(const std::string& text) {
    std::string cell;
    cell.reserve(text.size());
    for (const char c : text) {
        if (c == '\\' || c == '|' || c == '`' || c == '<' || c == '*' || c == '_') cell += '\\';
        cell += (c == '\n' || c == '\r') ? ' ' : c;
    }
    return cell;
}

}  // namespace rotbeam::cli
