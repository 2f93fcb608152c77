// Table III of seed 002: the joined beam's lowest natural frequencies, the paper's columns (the
// case file's frequency references, grouped by their source) next to every modal run of the suite.
#include <algorithm>
#include <cmath>
#include <iomanip>
#include <map>
#include <sstream>

#include "cases/loader/case_loader.hpp"
#include "core/choices.hpp"
#include "report_dynamics.hpp"
#include "runs/catalog.hpp"

namespace rotbeam::cli {

namespace {

struct PaperColumn {
    std::string source, formulation;
    std::map<int, double> hz;  // mode → frequency
};

std::vector<PaperColumn> paper_columns(const Model& model) {
    std::vector<PaperColumn> columns;
    for (const ReferenceValue& r : model.references) {
        if (r.quantity != "frequency" || r.value.size() != 1) continue;
        auto it = std::find_if(columns.begin(), columns.end(),
                               [&](const PaperColumn& c) { return c.source == r.source; });
        if (it == columns.end()) {
            const auto f = r.applies_to.find("formulation");
            columns.push_back({r.source, f == r.applies_to.end() ? "" : f->second, {}});
            it = columns.end() - 1;
        }
        it->hz[r.mode] = r.value[0];
    }
    return columns;
}

std::string fixed2(double v) {
    std::ostringstream s;
    s << std::fixed << std::setprecision(2) << v;
    return s.str();
}

// A column of runs: the settings (without the parameterization), the parameterizations whose
// frequencies agree to the printed digits, and those frequencies.
struct RunColumn {
    std::string formulation, settings;
    std::vector<std::string> rotations;
    std::vector<double> hz;
};

std::string settings(const nlohmann::json& r) {
    std::ostringstream s;
    s << r.value("elements", 0) / std::max<size_t>(1, r["elements_per_member"].size())
      << " el./member";
    if (parse_choice<Formulation>(r.value("formulation", "")) == Formulation::displacement) {
        s << ", order " << r.value("order", 0) << ", " << r["options"].value("quadrature", "")
          << " quadrature";
    }
    s << ", " << r["options"].value("mass_rule", "") << " mass";
    return s.str();
}

std::vector<RunColumn> run_columns(const std::vector<const nlohmann::json*>& runs) {
    std::vector<RunColumn> columns;
    for (const nlohmann::json* r : runs) {
        RunColumn c{r->value("formulation", ""), settings(*r), {r->value("rotation", "")}, {}};
        for (const auto& f : (*r)["frequencies_hz"]) c.hz.push_back(f.get<double>());
        const auto same = [&](const RunColumn& o) {
            if (o.formulation != c.formulation || o.settings != c.settings) return false;
            if (o.hz.size() != c.hz.size()) return false;
            for (size_t i = 0; i < c.hz.size(); ++i) {
                if (fixed2(o.hz[i]) != fixed2(c.hz[i])) return false;
            }
            return true;
        };
        const auto it = std::find_if(columns.begin(), columns.end(), same);
        if (it == columns.end()) {
            columns.push_back(c);
        } else if (std::find(it->rotations.begin(), it->rotations.end(), c.rotations[0]) ==
                   it->rotations.end()) {
            it->rotations.push_back(c.rotations[0]);
        }
    }
    return columns;
}

}  // namespace

std::string table_three_section(const std::vector<nlohmann::json>& runs) {
    std::vector<const nlohmann::json*> mine;
    std::vector<std::string> refused;
    for (const nlohmann::json& r : runs) {
        if (r.value("case", "") != "joined-beam") continue;
        if (r.contains("frequencies_hz")) {
            mine.push_back(&r);
        } else {
            refused.push_back(r.value("formulation", "") + "/" + r.value("rotation", ""));
        }
    }
    if (mine.empty()) return {};
    const Model model = load_case(resolve_case_path("joined-beam"), {});
    const std::vector<PaperColumn> paper = paper_columns(model);
    std::ostringstream md;
    md << "## Table III: natural frequencies of the joined beam\n\n"
       << "The lowest " << model.analysis.modal.modes
       << " natural frequencies [Hz] of the undeformed joined beam (seed 002 Example 3): the "
          "paper's columns (from the case file's references) and every modal run of the suite: at "
          "the case's mesh, with the settings of each published column (as `verify` runs them) "
          "and refined for a mesh-converged column; parameterizations whose frequencies agree to "
          "the printed digits share a column. Each has its relative difference to the paper column "
          "of its own "
          "formulation (GEBT for mixed, ANSYS BEAM188 for displacement).\n\n| mode |";
    for (const PaperColumn& c : paper) md << " paper: " << c.source << " |";
    const std::vector<RunColumn> columns = run_columns(mine);
    for (const RunColumn& c : columns) {
        md << " " << c.formulation << " (";
        for (size_t i = 0; i < c.rotations.size(); ++i) md << (i ? ", " : "") << c.rotations[i];
        md << "), " << c.settings << " |";
    }
    md << "\n|---|";
    for (size_t i = 0; i < paper.size() + columns.size(); ++i) md << "---|";
    md << "\n";
    for (int mode = 1; mode <= model.analysis.modal.modes; ++mode) {
        md << "| " << mode << " |";
        for (const PaperColumn& c : paper) {
            const auto it = c.hz.find(mode);
            md << " " << (it == c.hz.end() ? std::string("—") : fixed2(it->second)) << " |";
        }
        for (const RunColumn& column : columns) {
            if (static_cast<int>(column.hz.size()) < mode) {
                md << " — |";
                continue;
            }
            const double hz = column.hz[mode - 1];
            md << " " << fixed2(hz);
            for (const PaperColumn& c : paper) {
                const auto it = c.hz.find(mode);
                if (c.formulation != column.formulation || it == c.hz.end()) continue;
                md << " (" << std::showpos << std::fixed << std::setprecision(2)
                   << 100.0 * (hz - it->second) / it->second << " %)" << std::noshowpos
                   << std::defaultfloat;
            }
            md << " |";
        }
        md << "\n";
    }
    md << "\n";
    if (!refused.empty()) {
        md << "Not available:";
        for (const std::string& s : refused) md << " " << s << ";";
        md.seekp(-1, std::ios_base::cur);
        md << ".\n\n";
    }
    return md.str();
}

}  // namespace rotbeam::cli
