// The published-tolerance gate (docs/case-format.md, "references"): every reference of the
// selected cases computed with every combination its applies_to (and each `also` entry) selects,
// in the discretization it names, and compared with its value and that check's tolerance; a pair
// whose combination ends at an expected stop first is not run. Every expected stop is checked on
// every combination it selects. Used by `rotbeam verify` and by the suite's published numbers.
#include "distribution/gate.hpp"

#include <cmath>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>

#include "cases/loader/case_loader.hpp"
#include "core/errors.hpp"
#include "core/results.hpp"
#include "core/static_driver.hpp"
#include "distribution/verify_plan.hpp"
#include "runs/catalog.hpp"
#include "runs/run_case.hpp"

namespace rotbeam::cli {

// The --set overrides that put a case into the discretization a reference applies to (its
// `elements` is per member and set on the model, not by an override).
std::vector<std::string> reference_overrides(const ReferenceValue& ref) {
    return discretization_overrides(ref.applies_to);
}

namespace {

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
    // Ten digits: the tightest tolerances (1e-9 on values of order 10) must be visible.
    std::ostringstream s;
    s << std::setprecision(10);
    if (v.size() == 1) {
        s << v[0];
        return s.str();
    }
    s << "[";
    for (size_t i = 0; i < v.size(); ++i) s << (i ? ", " : "") << v[i];
    s << "]";
    return s.str();
}

// One (reference × discretization) pair: the computed value against the published one with
// the check's tolerance. An unavailable result is a miss of a gated reference.
Row compare(const Model& model, const nlohmann::json& result, const ReferenceValue& ref,
            const Settings& settings, double tolerance) {
    Row row{model.name,
            ref.id,
            ref.quantity,
            settings_label(settings),
            format_vector(ref.value),
            "-",
            "-",
            "",
            ""};
    std::ostringstream tol;
    tol << std::setprecision(3) << tolerance << (ref.relative ? " rel" : " abs");
    row.tolerance = tol.str();
    if (!result.value("available", true)) {
        row.computed = "unavailable: " + result["message"].get<std::string>();
        row.verdict = ref.gated ? "FAIL" : "recorded";
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
        const double allowed = ref.relative ? tolerance * std::abs(ref.value[i]) : tolerance;
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

bool same_factor(double a, double b) {
    return std::abs(a - b) <= 1e-9 * std::max(1.0, std::abs(b));
}

// The expected stop of a case that ends this run before the reference's load factor, if any.
const ExpectedStop* stop_before(const Model& base, const Model* model, const ReferenceValue& ref) {
    if (!model || !ref.load_factor) return nullptr;
    for (const ExpectedStop& stop : base.expected_stops) {
        if (model_has(*model, stop.applies_to) &&
            (stop.stops_before < *ref.load_factor ||
             same_factor(stop.stops_before, *ref.load_factor)))
            return &stop;
    }
    return nullptr;
}

// The last converged load factor of a static run (0 without a converged step).
double last_converged(const nlohmann::json& result) {
    double last = 0.0;
    for (const auto& step : result["steps"]) {
        if (step.contains("load_factor")) last = std::max(last, step["load_factor"].get<double>());
    }
    return last;
}

std::string number(double x) {
    std::ostringstream s;
    s << std::setprecision(6) << x;
    return s.str();
}

// An expected stop on one combination: the status it names, converged up to `reaches` and not at
// or past `stops_before`. Anything else (farther, shorter, another status, unavailable) is a miss:
// the combination's reach changed.
Row check_stop(const Model& base, const nlohmann::json& result, const ExpectedStop& stop,
               const Settings& settings) {
    Row row{base.name, stop.id, "stop", settings_label(settings), "", "-", "-", "-", ""};
    row.published = stop.status + " in [" + (stop.reaches ? number(*stop.reaches) : "0") + ", " +
                    number(stop.stops_before) + ")";
    const std::string status = result.value("status", "error");
    const double last = last_converged(result);
    row.computed = status + " after " + number(last);
    if (status != "converged") row.computed += ": " + result.value("message", "");
    const bool reached = !stop.reaches || last > *stop.reaches || same_factor(last, *stop.reaches);
    const bool stopped = last < stop.stops_before && !same_factor(last, stop.stops_before);
    row.verdict = status == stop.status && reached && stopped ? "pass" : "FAIL";
    return row;
}

}  // namespace

std::vector<Row> verify_rows(const std::vector<std::string>& cases) {
    std::vector<Row> rows;
    for (const std::string& c : cases) {
        const std::string path = resolve_case_path(c);
        const Model base = load_case(path, {});
        GateRuns runs(path);
        for (const ReferenceValue& ref : base.references) {
            std::vector<std::pair<Settings, double>> checks;
            for (const Settings& s : selected_runs(ref.applies_to))
                checks.push_back({s, ref.tolerance});
            for (const ReferenceValue::Check& also : ref.also) {
                for (const Settings& s : selected_runs(also.applies_to))
                    checks.push_back({s, also.tolerance});
            }
            if (checks.empty()) {  // the loader refuses applies_to that select nothing
                rows.push_back({base.name, ref.id, ref.quantity, "-", format_vector(ref.value),
                                "applies_to selects no combination", "-", "-", "FAIL"});
            }
            for (const auto& [settings, tolerance] : checks) {
                const Model* model = runs.model(settings);
                if (const ExpectedStop* stop = stop_before(base, model, ref)) {
                    Row row{base.name,
                            ref.id,
                            ref.quantity,
                            settings_label(settings),
                            format_vector(ref.value),
                            "stops first (expected stop " + stop->id + ")",
                            "-",
                            "-",
                            "not reached"};
                    rows.push_back(row);
                    continue;
                }
                rows.push_back(compare(model ? *model : base, runs.result(settings), ref, settings,
                                       tolerance));
            }
        }
        for (const ExpectedStop& stop : base.expected_stops) {
            const std::vector<Settings> selected = selected_runs(stop.applies_to);
            if (selected.empty()) {
                rows.push_back({base.name, stop.id, "stop", "-", stop.status,
                                "applies_to selects no combination", "-", "-", "FAIL"});
            }
            for (const Settings& s : selected)
                rows.push_back(check_stop(base, runs.result(s), stop, s));
        }
    }
    return rows;
}

nlohmann::json row_json(const Row& r) {
    return {{"case", r.case_name},          {"reference", r.id},        {"quantity", r.quantity},
            {"combination", r.combination}, {"published", r.published}, {"computed", r.computed},
            {"difference", r.difference},   {"tolerance", r.tolerance}, {"result", r.verdict}};
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

PublishedReferences published_references(const std::vector<std::string>& cases) {
    const std::vector<Row> rows = verify_rows(cases);
    nlohmann::json checks = nlohmann::json::array();
    for (const Row& r : rows) checks.push_back(row_json(r));
    if (rows.empty()) return {{}, checks};
    std::ostringstream md;
    md << "## Published numbers\n\nEvery published reference of the cases run (the case files' "
          "`references`: Table I, Table II and the other 45° bend values, Table III), computed "
          "with every combination its applies_to selects, and every expected stop, as `rotbeam "
          "verify` does. `recorded` entries are published values that are not converged solutions "
          "(docs/benchmarks.md §1); `not reached` pairs end at an expected stop first.\n\n"
          "| case | reference | combination | published | computed | difference | tolerance | "
          "result |\n|---|---|---|---|---|---|---|---|\n";
    for (const Row& r : rows) {
        md << "| " << r.case_name << " | " << r.id << " | "
           << (r.combination.empty() ? "the case's own" : r.combination) << " | " << r.published
           << " | " << r.computed << " | " << r.difference << " | " << r.tolerance << " | "
           << r.verdict << " |\n";
    }
    return {md.str() + "\n", checks};
}

}  // namespace rotbeam::cli
