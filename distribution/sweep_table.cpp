// The sweep table (docs/sweeps.md, "Output"): one row per run × reported step × named point (a
// modal run: per mode), with the swept values as columns, the run's status, the point's
// displacement and rotation angle (or the mode's frequency) and their error estimates
// (docs/error-estimates.md). sweep.csv has every load step of a static run and the last step of a
// dynamic run (its history stays in the run's JSON); index.md and index.html the last step of
// each run unless output.steps is `all`.
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <sstream>

#include "core/atomic_file.hpp"
#include "distribution/sweep_runs.hpp"
#include "reports/report.hpp"
#include "runs/run_file.hpp"

namespace rotbeam::cli {

namespace fs = std::filesystem;

namespace {

// The result columns, after the run's own (run, case, combination, swept keys, status).
const std::vector<std::string> kQuantities = {
    "step",  "value",     "point",         "u1",
    "u2",    "u3",        "angle",         "frequency_hz",
    "u_err", "angle_err", "frequency_err", "estimate_reliable"};

using SweepRow = std::map<std::string, nlohmann::json>;  // column → number, string, bool or null

// The value at `path` in `j`, null when absent.
nlohmann::json at(const nlohmann::json& j, std::initializer_list<const char*> path) {
    const nlohmann::json* node = &j;
    for (const char* key : path) {
        if (!node->is_object() || !node->contains(key)) return nullptr;
        node = &(*node)[key];
    }
    return *node;
}

// Both estimates reliable (null when the step has none).
nlohmann::json reliable(const nlohmann::json& a, const nlohmann::json& b) {
    if (!a.is_boolean() || !b.is_boolean()) return nullptr;
    return a.get<bool>() && b.get<bool>();
}

// The rows of one step: one per named point.
void point_rows(const SweepRow& base, const nlohmann::json& step, const char* kind,
                std::vector<SweepRow>& rows) {
    const nlohmann::json points = at(step, {"points"});
    if (!points.is_object()) return;
    for (const auto& [name, p] : points.items()) {
        SweepRow row = base;
        row["step"] = kind;
        row["value"] = step[kind];
        row["point"] = name;
        const nlohmann::json u = at(p, {"displacement"});
        const char* components[] = {"u1", "u2", "u3"};
        for (size_t k = 0; k < 3; ++k)
            row[components[k]] = u.is_array() && u.size() == 3 ? u[k] : nlohmann::json();
        row["angle"] = at(p, {"rotation_angle"});
        const nlohmann::json e = at(step, {"estimate"});
        row["u_err"] = at(e, {name.c_str(), "displacement", "error"});
        row["angle_err"] = at(e, {name.c_str(), "rotation", "error"});
        row["estimate_reliable"] = reliable(at(e, {name.c_str(), "displacement", "reliable"}),
                                            at(e, {name.c_str(), "rotation", "reliable"}));
        rows.push_back(std::move(row));
    }
}

// Every row of one run; `last_only`: a static run's last load step alone.
std::vector<SweepRow> run_rows(const SweepRow& base, const nlohmann::json& result, bool last_only) {
    std::vector<SweepRow> rows;
    const nlohmann::json modes = at(result, {"modes"});
    const nlohmann::json steps = at(result, {"steps"});
    if (modes.is_array() && !modes.empty()) {
        for (size_t i = 0; i < modes.size(); ++i) {
            SweepRow row = base;
            row["step"] = "mode";
            row["value"] = i + 1;
            row["frequency_hz"] = at(modes[i], {"frequency_hz"});
            row["frequency_err"] = at(modes[i], {"estimate", "frequency", "error"});
            const nlohmann::json r = at(modes[i], {"estimate", "frequency", "reliable"});
            row["estimate_reliable"] = r.is_boolean() ? r : nlohmann::json();
            rows.push_back(std::move(row));
        }
    } else if (steps.is_array() && !steps.empty()) {
        const bool dynamic = steps.back().contains("time");
        const size_t first = last_only || dynamic ? steps.size() - 1 : 0;
        for (size_t i = first; i < steps.size(); ++i)
            point_rows(base, steps[i], dynamic ? "time" : "load_factor", rows);
    }
    if (rows.empty()) rows.push_back(base);  // a run without a solution: its status alone
    return rows;
}

std::string csv_cell(const nlohmann::json& v) {
    if (v.is_null()) return "";
    if (v.is_string()) {
        const std::string s = v.get<std::string>();
        if (s.find_first_of(",\"\n") == std::string::npos) return s;
        std::string q = "\"";
        for (const char c : s) {
            if (c == '"') q.push_back('"');
            q.push_back(c);
        }
        q.push_back('"');
        return q;
    }
    return v.dump();  // numbers: the shortest text that reads back to the same double
}

std::string md_cell(const nlohmann::json& v) {
    if (v.is_null()) return "";
    if (v.is_number_float()) {
        char text[32];
        std::snprintf(text, sizeof text, "%.6g", v.get<double>());
        return text;
    }
    std::string s = v.is_string() ? v.get<std::string>() : v.dump();
    std::string escaped;
    for (const char c : s) {
        if (c == '|') escaped.push_back('\\');
        escaped.push_back(c);
    }
    return escaped;
}

}  // namespace

void write_sweep_report(const std::string& out, const Sweep& sweep,
                        const std::vector<PlannedRun>& runs) {
    bool interpolation = false, wm_map = false;
    for (const SweepRun& r : sweep.runs) {
        interpolation = interpolation || !r.interpolation.empty();
        wm_map = wm_map || !r.wm_map.empty();
    }
    std::vector<std::string> columns = {"run", "case", "formulation", "rotation"};
    if (interpolation) columns.push_back("interpolation");
    if (wm_map) columns.push_back("wm_map");
    columns.insert(columns.end(), sweep.keys.begin(), sweep.keys.end());
    columns.push_back("status");
    columns.insert(columns.end(), kQuantities.begin(), kQuantities.end());
    std::vector<SweepRow> all, shown;
    std::map<std::string, int> statuses;
    for (size_t i = 0; i < runs.size(); ++i) {
        const SweepRun& s = sweep.runs[i];
        const nlohmann::json result =
            *read_run_file(runs[i].output, RunFileKind::case_run, std::nullopt);
        SweepRow base = {{"run", fs::path(runs[i].output).stem().string()},
                         {"case", s.case_name},
                         {"formulation", s.formulation},
                         {"rotation", s.rotation},
                         {"status", result.value("status", "")}};
        if (interpolation) base["interpolation"] = s.interpolation;
        if (wm_map) base["wm_map"] = s.wm_map;
        for (size_t k = 0; k < sweep.keys.size(); ++k) base[sweep.keys[k]] = s.values[k];
        ++statuses[result.value("status", "")];
        for (SweepRow& r : run_rows(base, result, false)) all.push_back(std::move(r));
        for (SweepRow& r : run_rows(base, result, !sweep.all_steps)) shown.push_back(std::move(r));
    }
    std::ostringstream csv, md;
    for (size_t c = 0; c < columns.size(); ++c) csv << (c ? "," : "") << columns[c];
    csv << "\n";
    for (const SweepRow& row : all) {
        for (size_t c = 0; c < columns.size(); ++c) {
            const auto v = row.find(columns[c]);
            csv << (c ? "," : "") << (v == row.end() ? "" : csv_cell(v->second));
        }
        csv << "\n";
    }
    md << "# Sweep " << sweep.name << "\n\n`" << fs::path(sweep.file).filename().string()
       << "`: " << runs.size() << " runs (";
    bool first = true;
    for (const auto& [status, n] : statuses) {
        md << (first ? "" : ", ") << n << " " << (status.empty() ? "(no status)" : status);
        first = false;
    }
    md << "). Every step of every run with full precision: [sweep.csv](sweep.csv); each run's "
          "result: `runs/`. Below: "
       << (sweep.all_steps ? "every step" : "the last step")
       << " of each run (every mode of a modal run), per named point; `u_err` and `angle_err` "
          "are the run's error estimates of the displacement and the rotation angle, empty "
          "where the run has none.\n\n|";
    for (const std::string& c : columns) md << " " << c << " |";
    md << "\n|";
    for (size_t c = 0; c < columns.size(); ++c) md << "---|";
    md << "\n";
    for (const SweepRow& row : shown) {
        md << "|";
        for (const std::string& c : columns) {
            const auto v = row.find(c);
            md << " " << (v == row.end() ? "" : md_cell(v->second)) << " |";
        }
        md << "\n";
    }
    write_file_atomically((fs::path(out) / "sweep.csv").string(), csv.str());
    write_file_atomically((fs::path(out) / "index.md").string(), md.str());
    write_file_atomically((fs::path(out) / "index.html").string(),
                          markdown_page_html(md.str(), out));
    std::cout << "sweep table: " << (fs::path(out) / "sweep.csv").string() << ", "
              << (fs::path(out) / "index.md").string() << "\n";
}

}  // namespace rotbeam::cli
