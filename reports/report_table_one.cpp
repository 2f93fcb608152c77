#include "report_table_one.hpp"

#include <cmath>
#include <iomanip>
#include <sstream>

#include "cases/loader/case_loader.hpp"
#include "core/oracles/rollup.hpp"
#include "runs/catalog.hpp"

namespace rotbeam::cli {

namespace {

std::string pair(double u1, double u3) {
    std::ostringstream s;
    s << std::fixed << std::setprecision(4) << "[" << u1 << ", " << u3 << "]";
    return s.str();
}

bool same(double a, double b) { return std::abs(a - b) <= 1e-9 * std::max(1.0, std::abs(b)); }

// The paper's entry at λ for one rotation (mixed references of Table I), or "—".
std::string paper_entry(const Model& model, const std::string& rotation, double lambda) {
    for (const ReferenceValue& r : model.references) {
        const auto rot = r.applies_to.find("rotation");
        if (r.quantity != "displacement" || rot == r.applies_to.end() || rot->second != rotation ||
            !r.load_factor || !same(*r.load_factor, lambda) || r.value.size() != 2) {
            continue;
        }
        std::string cell = pair(r.value[0], r.value[1]);
        if (r.published_iterations) cell += " (" + std::to_string(*r.published_iterations) + ")";
        if (!r.gated) cell += " not converged";
        return cell;
    }
    return "—";
}

// This run's tip at λ with its Newton iterations and ‖Δu‖/L to the exact tip, or why not.
std::string run_entry(const nlohmann::json& run, double lambda, const Vec3& exact, double length) {
    for (const nlohmann::json& step : run["steps"]) {
        if (!step.contains("load_factor") || !same(step["load_factor"].get<double>(), lambda)) {
            continue;
        }
        const nlohmann::json& u = step["points"]["tip"]["displacement"];
        const Vec3 v(u[0].get<double>(), u[1].get<double>(), u[2].get<double>());
        std::ostringstream s;
        s << pair(v[0], v[2]) << " (" << step.value("newton_iterations", 0) << ") "
          << std::scientific << std::setprecision(1) << (v - exact).norm() / length;
        return s.str();
    }
    return run.value("status", "error") == "error" ? std::string("not available")
                                                   : "stopped: " + run.value("status", "");
}

}  // namespace

std::string table_one_section(const std::string& case_name,
                              const std::vector<nlohmann::json>& runs) {
    std::vector<const nlohmann::json*> mine;
    for (const nlohmann::json& r : runs) {
        if (r.value("case", "") == case_name && r.contains("steps")) mine.push_back(&r);
    }
    if (mine.empty()) return {};
    const Model model = load_case(resolve_case_path(case_name), {});
    const double length = (model.points[1].position - model.points[0].position).norm();
    std::ostringstream md;
    md << "## Table I: the moment-loaded cantilever\n\n"
       << "Tip displacement [u₁, u₃] (in) of seed 002 Table I: exact, the paper's GEBT columns "
          "(Newton iterations in parentheses), and every combination of this suite at the case's "
          "mesh (iterations of the reported step, summed over its "
       << model.analysis.statics.substeps
       << " sub-steps; then ‖Δu‖/L to the exact tip). A combination that stopped says how.\n\n"
       << "| combination |";
    const std::vector<double>& lambdas = model.analysis.statics.load_factors;
    for (double lambda : lambdas) md << " λ = " << lambda << " |";
    md << "\n|---|";
    for (size_t i = 0; i < lambdas.size(); ++i) md << "---|";
    md << "\n| exact |";
    for (double lambda : lambdas) {
        const Vec3 exact = oracle::rollup_tip(length, lambda).displacement;
        md << " " << pair(exact[0], exact[2]) << " |";
    }
    for (const char* rotation : {"wiener-milenkovic", "rodrigues"}) {
        md << "\n| paper GEBT (" << rotation << ", 16 elements) |";
        for (double lambda : lambdas) md << " " << paper_entry(model, rotation, lambda) << " |";
    }
    for (const nlohmann::json* r : mine) {
        md << "\n| " << r->value("formulation", "") << ", " << r->value("rotation", "");
        if (r->value("elements", 0) > 0) md << ", " << r->value("elements", 0) << " elements";
        md << " |";
        for (double lambda : lambdas) {
            const Vec3 exact = oracle::rollup_tip(length, lambda).displacement;
            md << " " << run_entry(*r, lambda, exact, length) << " |";
        }
    }
    md << "\n";
    return md.str() + "\n";
}

}  // namespace rotbeam::cli
