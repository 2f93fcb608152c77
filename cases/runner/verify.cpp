// `rotbeam verify`: the published-tolerance gate. Every reference of the selected cases is
// computed with the combination it applies to (applies_to; otherwise the case's own
// discretization) and compared with its published value and tolerance. Exit 1 on any gated miss.
#include <cmath>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>

#include "arguments.hpp"
#include "cases/loader/case_loader.hpp"
#include "commands.hpp"
#include "core/errors.hpp"
#include "core/results.hpp"
#include "core/static_driver.hpp"
#include "run_case.hpp"

namespace rotbeam::cli {

// The --set overrides that put a case into the discretization a reference applies to (its
// `elements` is per member and set on the model, not by an override).
std::vector<std::string> reference_overrides(const ReferenceValue& ref) {
    static const std::map<std::string, std::string> keys = {
        {"formulation", "discretization.formulation"},
        {"rotation", "discretization.rotation"},
        {"order", "discretization.order"},
        {"quadrature", "discretization.quadrature"},
        {"quadrature_points", "discretization.quadrature_points"},
        {"interpolation", "discretization.interpolation"},
        {"update", "discretization.update"},
        {"mass_rule", "discretization.mass_rule"}};
    std::vector<std::string> overrides;
    for (const auto& [key, value] : ref.applies_to) {
        const auto it = keys.find(key);
        if (it != keys.end()) overrides.push_back(it->second + "=" + value);
    }
    return overrides;
}

namespace {

std::string combination_key(const ReferenceValue& ref) {
    std::string key;
    for (const auto& [k, v] : ref.applies_to) key += k + "=" + v + " ";
    return key;
}

const nlohmann::json* find_step(const nlohmann::json& result, const ReferenceValue& ref) {
    for (const auto& step : result["steps"]) {
        if (ref.load_factor && step.contains("load_factor") &&
            std::abs(step["load_factor"].get<double>() - *ref.load_factor) <=
                1e-9 * std::max(1.0, std::abs(*ref.load_factor))) {
            return &step;
        }
        if (ref.time && step.contains("time") &&
            std::abs(step["time"].get<double>() - *ref.time) <= 1e-9) {
            return &step;
        }
    }
    return nullptr;
}

// The computed values for the reference's components, or an explanation why there are none.
std::vector<double> computed_values(const Model& model, const nlohmann::json& result,
                                    const ReferenceValue& ref, std::string& why) {
    std::vector<double> out;
    // Steps that converged before a failure still count (Table I's columns end where each
    // parameterization stops); a missing step reports the run's status.
    const std::string status_note =
        result["status"].get<std::string>() + ": " + result["message"].get<std::string>();
    if (ref.quantity == "frequency") {
        if (!has_solution(result["status"].get<std::string>())) {
            why = status_note;
            return out;
        }
        const auto& f = result.value("frequencies_hz", nlohmann::json::array());
        if (ref.mode < 1 || ref.mode > static_cast<int>(f.size())) {
            why = "mode " + std::to_string(ref.mode) + " not computed";
            return out;
        }
        out.push_back(f[ref.mode - 1].get<double>());
        return out;
    }
    const nlohmann::json* step = find_step(result, ref);
    if (!step || !(*step)["points"].contains(ref.point)) {
        why = has_solution(result["status"].get<std::string>())
                  ? "no result at that load factor/time and point"
                  : status_note;
        return out;
    }
    const nlohmann::json& p = (*step)["points"][ref.point];
    std::vector<double> full;
    if (ref.quantity == "displacement" || ref.quantity == "position") {
        for (int i = 0; i < 3; ++i) full.push_back(p["displacement"][i].get<double>());
        if (ref.quantity == "position") {
            const int index = model.point_index(ref.point);
            for (int i = 0; i < 3; ++i) full[i] += model.points[index].position[i];
        }
    } else if (ref.quantity == "rotation_angle") {
        full.push_back(p["rotation_angle"].get<double>());
    } else {
        why = "unknown quantity '" + ref.quantity + "'";
        return out;
    }
    if (ref.components.empty()) return full;
    for (int c : ref.components) out.push_back(full.at(static_cast<size_t>(c)));
    return out;
}

std::string format_vector(const std::vector<double>& v) {
    std::ostringstream s;
    s << std::setprecision(6);
    if (v.size() == 1) {
        s << v[0];
        return s.str();
    }
    s << "[";
    for (size_t i = 0; i < v.size(); ++i) s << (i ? ", " : "") << v[i];
    s << "]";
    return s.str();
}

struct Row {
    std::string case_name, id, quantity, combination, published, computed, difference, tolerance,
        verdict;
};

Row compare(const Model& model, const nlohmann::json& result, const ReferenceValue& ref) {
    Row row{
        model.name, ref.id, ref.quantity, combination_key(ref), format_vector(ref.value), "-", "-",
        "",         ""};
    std::ostringstream tol;
    tol << std::setprecision(3) << ref.tolerance << (ref.relative ? " rel" : " abs");
    row.tolerance = tol.str();
    if (!result.value("available", true)) {
        row.computed = result["message"].get<std::string>();
        row.verdict = "unavailable";
        return row;
    }
    std::string why;
    const std::vector<double> computed = computed_values(model, result, ref, why);
    if (computed.size() != ref.value.size()) {
        row.computed = why.empty() ? "component count mismatch" : why;
        row.verdict = ref.gated ? "FAIL" : "recorded";
        return row;
    }
    double worst = 0.0;
    bool pass = true;
    for (size_t i = 0; i < computed.size(); ++i) {
        const double d = std::abs(computed[i] - ref.value[i]);
        const double allowed =
            ref.relative ? ref.tolerance * std::abs(ref.value[i]) : ref.tolerance;
        worst =
            std::max(worst, ref.relative && ref.value[i] != 0.0 ? d / std::abs(ref.value[i]) : d);
        if (!(d <= allowed)) pass = false;
    }
    row.computed = format_vector(computed);
    std::ostringstream diff;
    diff << std::setprecision(3) << worst << (ref.relative ? " rel" : "");
    row.difference = diff.str();
    row.verdict = !ref.gated ? (pass ? "recorded (ok)" : "recorded") : (pass ? "pass" : "FAIL");
    return row;
}

void print_table(const std::vector<Row>& rows, std::ostream& os) {
    const char* headers[] = {"case",     "reference",  "quantity",  "combination", "published",
                             "computed", "difference", "tolerance", "result"};
    std::vector<size_t> width(9);
    auto cells = [](const Row& r) {
        return std::vector<std::string>{r.case_name,   r.id,        r.quantity,
                                        r.combination, r.published, r.computed,
                                        r.difference,  r.tolerance, r.verdict};
    };
    for (int i = 0; i < 9; ++i) width[i] = std::string(headers[i]).size();
    for (const Row& r : rows) {
        const auto c = cells(r);
        for (int i = 0; i < 9; ++i)
            width[i] = std::min<size_t>(60, std::max(width[i], c[i].size()));
    }
    auto line = [&](const std::vector<std::string>& c) {
        for (int i = 0; i < 9; ++i) {
            std::string cell = c[i].size() > 60 ? c[i].substr(0, 57) + "..." : c[i];
            os << std::left << std::setw(static_cast<int>(width[i])) << cell
               << (i < 8 ? "  " : "\n");
        }
    };
    line({headers, headers + 9});
    for (const Row& r : rows) line(cells(r));
}

std::vector<Row> verify_rows(const std::vector<std::string>& cases) {
    std::vector<Row> rows;
    for (const std::string& c : cases) {
        const std::string path = resolve_case_path(c);
        const Model base = load_case(path, {});
        std::map<std::string, std::vector<const ReferenceValue*>> groups;
        for (const ReferenceValue& ref : base.references)
            groups[combination_key(ref)].push_back(&ref);
        for (const auto& [key, refs] : groups) {
            Model model = load_case(path, reference_overrides(*refs.front()));
            const auto elements = refs.front()->applies_to.find("elements");
            if (elements != refs.front()->applies_to.end()) {
                for (Member& m : model.members) m.elements = std::stoi(elements->second);
            }
            const nlohmann::json result = run_case(RunRequest{path, model});
            for (const ReferenceValue* ref : refs) rows.push_back(compare(model, result, *ref));
        }
    }
    return rows;
}

}  // namespace

std::string published_references_markdown(const std::vector<std::string>& cases) {
    const std::vector<Row> rows = verify_rows(cases);
    if (rows.empty()) return {};
    std::ostringstream md;
    md << "## Published numbers\n\nEvery published reference of the cases run (the case files' "
          "`references`: Table I, Table II and the other 45° bend values, Table III), computed "
          "with the discretization it belongs to, as `rotbeam verify` does. `recorded` entries "
          "are published values that are not converged solutions (benchmarks.md §1); "
          "`unavailable` ones need an analysis that is not implemented yet.\n\n"
          "| case | reference | combination | published | computed | difference | tolerance | "
          "result |\n|---|---|---|---|---|---|---|---|\n";
    for (const Row& r : rows) {
        md << "| " << r.case_name << " | " << r.id << " | "
           << (r.combination.empty() ? "the case's own" : r.combination) << " | " << r.published
           << " | " << r.computed << " | " << r.difference << " | " << r.tolerance << " | "
           << r.verdict << " |\n";
    }
    return md.str() + "\n";
}

int command_verify(const Args& args) {
    const CommandSpec spec{
        "verify",
        "[CASE ...]",
        0,
        -1,
        "Run every applicable published reference of the given cases (default: the whole catalog) "
        "and compare with its tolerance. Prints a table; exit 1 on any gated miss.",
        {{"json", "FILE", "also write the table as JSON"}}};
    const ParsedArguments a = parse_arguments(spec, args);
    if (a.help) {
        std::cout << help_text(spec);
        return 0;
    }
    std::vector<std::string> cases = a.positional;
    if (cases.empty()) cases = catalog_cases();
    const std::vector<Row> rows = verify_rows(cases);
    nlohmann::json table = nlohmann::json::array();
    print_table(rows, std::cout);
    int misses = 0, gated = 0, unavailable = 0;
    for (const Row& r : rows) {
        if (r.verdict == "FAIL") ++misses;
        if (r.verdict == "pass" || r.verdict == "FAIL") ++gated;
        if (r.verdict == "unavailable") ++unavailable;
        table.push_back({{"case", r.case_name},
                         {"reference", r.id},
                         {"quantity", r.quantity},
                         {"combination", r.combination},
                         {"published", r.published},
                         {"computed", r.computed},
                         {"difference", r.difference},
                         {"tolerance", r.tolerance},
                         {"result", r.verdict}});
    }
    std::cout << "\nverify: " << gated - misses << " gated references passed, " << misses
              << " missed; " << rows.size() - gated - unavailable << " recorded only; "
              << unavailable << " unavailable (analysis not implemented yet)\n";
    if (const auto file = a.value("json")) write_file_atomically(*file, table.dump(2) + "\n");
    return misses > 0 ? 1 : 0;
}

}  // namespace rotbeam::cli
