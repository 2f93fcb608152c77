#include "report_summary.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <iomanip>
#include <map>
#include <optional>
#include <sstream>

#include "cases/loader/case_loader.hpp"
#include "cases/loader/deck_case.hpp"
#include "core/choices.hpp"
#include "core/continuum/continuum.hpp"
#include "core/oracles/rollup.hpp"
#include "core/static_driver.hpp"
#include "core/static_stability.hpp"
#include "estimates/accuracy_scale.hpp"
#include "parameterizations/registry.hpp"
#include "runs/catalog.hpp"
#include "studies/study_common.hpp"

namespace rotbeam::cli {

namespace {

// Whether a verify row was computed with the run's own combination and discretization. Its
// `combination` label is "formulation/rotation[/interpolation or wm_map][ key=value ...]"
// (verify_plan.hpp, settings_label): every part must be the run's (the key=value settings compared
// with the run's `order`, `elements_per_member` or `options`).
bool row_is(const nlohmann::json& row, const nlohmann::json& run) {
    if (row.value("case", "") != run.value("case", "")) return false;
    std::istringstream label(row.value("combination", ""));
    std::string head;
    label >> head;
    std::vector<std::string> parts;
    for (size_t start = 0, slash = 0; slash != std::string::npos; start = slash + 1) {
        slash = head.find('/', start);
        parts.push_back(head.substr(start, slash == std::string::npos ? slash : slash - start));
    }
    if (parts.size() < 2 || parts[0] != run.value("formulation", "") ||
        parts[1] != run.value("rotation", "")) {
        return false;
    }
    const nlohmann::json& options = run.value("options", nlohmann::json::object());
    const auto option = [&](const std::string& key) -> std::string {
        if (!options.contains(key)) return {};
        const nlohmann::json& v = options[key];
        return v.is_string() ? v.get<std::string>() : v.dump();
    };
    if (parts.size() > 2 && parts[2] != option("interpolation") && parts[2] != option("wm_map"))
        return false;
    for (std::string setting; label >> setting;) {
        const size_t eq = setting.find('=');
        const std::string key = setting.substr(0, eq), value = setting.substr(eq + 1);
        if (key == "order") {
            if (std::to_string(run.value("order", 0)) != value) return false;
        } else if (key == "elements") {
            const nlohmann::json per_member =
                run.value("elements_per_member", nlohmann::json::object());
            for (const auto& [member, n] : per_member.items()) {
                if (n.dump() != value) return false;
            }
        } else if (option(key) != value) {
            return false;
        }
    }
    return true;
}

std::string scientific(double v, int digits = 1) {
    std::ostringstream s;
    s << std::scientific << std::setprecision(digits) << v;
    return s.str();
}

// The model of a run's case, loaded once per case (nullptr when the case no longer loads).
const Model* model_of(const std::string& case_name) {
    static std::map<std::string, std::optional<Model>> models;
    auto it = models.find(case_name);
    if (it == models.end()) {
        std::optional<Model> m;
        try {
            m = load_case(resolve_case_path(case_name), {});
        } catch (const std::exception&) {
        }
        it = models.emplace(case_name, std::move(m)).first;
    }
    return it->second ? &*it->second : nullptr;
}

// The refusals a catalog case states (cases/loader/deck_case.hpp), read once per case.
const std::map<Formulation, std::string>& stated_refusals_of(const std::string& case_name) {
    static std::map<std::string, std::map<Formulation, std::string>> refusals;
    auto it = refusals.find(case_name);
    if (it == refusals.end()) {
        std::map<Formulation, std::string> r;
        try {
            r = cases::stated_refusals(resolve_case_path(case_name));
        } catch (const std::exception&) {
        }
        it = refusals.emplace(case_name, std::move(r)).first;
    }
    return it->second;
}

struct Verdict {
    // met, unchecked, stopped, unstable, inaccurate, refused as stated, not run
    std::string kind;
    std::string text;   // the cell's words
    std::string why{};  // refused as stated: the stated words of the refusal
};

Verdict verdict(const nlohmann::json* run, const std::string& case_name,
                const nlohmann::json& checks) {
    if (!run) return {"not run", "not run"};
    const std::string status = run->value("status", "error");
    if (status == "error") {
        // A formulation the case states it refuses, refused in those words: not a hole.
        const std::map<Formulation, std::string> refusals = stated_refusals_of(case_name);
        const std::optional<Formulation> f =
            parse_choice<Formulation>(run->value("formulation", ""));
        if (f) {
            const auto stated = refusals.find(*f);
            if (stated != refusals.end() &&
                run->value("message", "").find(stated->second) != std::string::npos) {
                return {"refused as stated", "refused as stated", stated->second};
            }
        }
        return {"not run", "not run"};
    }
    if (status == "inaccurate") return {"inaccurate", "inaccurate: its estimate"};
    if (status == kUnstableEquilibrium) return {"unstable", "unstable equilibrium"};
    int passed = 0, failed = 0;
    bool expected_stop = false;
    std::string missed;
    for (const nlohmann::json& row : checks) {
        if (!row_is(row, *run)) continue;
        const std::string result = row.value("result", "");
        if (row.value("quantity", "") == "stop") {
            expected_stop = expected_stop || result == "pass";
        } else if (result == "pass") {
            ++passed;
        } else if (result == "FAIL") {
            ++failed;
            if (missed.empty()) missed = row.value("reference", "");
        }
    }
    if (!has_solution(status)) {
        return {"stopped", "stopped: " + status + (expected_stop ? ", expected" : "")};
    }
    if (failed > 0) return {"inaccurate", "inaccurate: misses " + missed};
    const Model* model = model_of(case_name);
    const nlohmann::json& estimate = run->value("estimate", nlohmann::json::object());
    const std::string estimated = estimate.value("status", "");
    if (model && (estimated == "estimated" || estimated == "partial")) {
        const std::map<Formulation, double>& accuracy = model->discretization.stated_accuracy;
        const std::optional<Formulation> f =
            parse_choice<Formulation>(run->value("formulation", ""));
        const auto stated = f ? accuracy.find(*f) : accuracy.end();
        if (stated != accuracy.end()) {
            const double target = stated->second / 2;
            // Every point at every load step, every frequency, every history of a dynamic run
            // relative to its amplitude (estimates/accuracy_scale.hpp).
            const estimate::AccuracyMeasure m = estimate::measure_accuracy(*model, *run, target);
            if (m.quantities > 0) {
                if (!estimate::meets(m, target)) return {"inaccurate", "inaccurate: estimate"};
                return {"met", "met (estimate)"};
            }
        }
    }
    if (passed > 0) return {"met", "met (" + std::to_string(passed) + ")"};
    // No accuracy stated for the formulation: the estimate still shows, so that a large
    // estimated error does not stand behind a bare "unchecked".
    if (model && (estimated == "estimated" || estimated == "partial")) {
        const estimate::AccuracyMeasure m = estimate::measure_accuracy(*model, *run, 1.0);
        if (m.quantities > 0)
            return {"unchecked", "unchecked: none stated, estimate " + scientific(m.worst)};
    }
    return {"unchecked", "unchecked"};
}

}  // namespace

std::string combination(const nlohmann::json& run) {
    return run.value("formulation", "") + "/" + run.value("rotation", "");
}

std::string run_row_id(size_t index) { return "run-" + std::to_string(index + 1); }

std::string summary_section(const std::vector<nlohmann::json>& runs,
                            const nlohmann::json& published_checks) {
    // Cases and combinations in the order of the runs (the suite plans them in registry order);
    // each cell the case's first run of that combination (later ones are the modal variants).
    std::vector<std::string> cases, combos;
    std::map<std::pair<std::string, std::string>, size_t> first;
    for (size_t i = 0; i < runs.size(); ++i) {
        const std::string c = runs[i].value("case", ""), k = combination(runs[i]);
        if (std::find(cases.begin(), cases.end(), c) == cases.end()) cases.push_back(c);
        if (std::find(combos.begin(), combos.end(), k) == combos.end()) combos.push_back(k);
        first.emplace(std::make_pair(c, k), i);
    }
    // Every cell's verdict, then a sentence per case.
    std::map<std::pair<std::string, std::string>, Verdict> cells;
    std::ostringstream sentences;
    for (const std::string& c : cases) {
        std::map<std::string, std::vector<std::string>> by_kind, refused_by_why;
        for (const std::string& k : combos) {
            const auto it = first.find({c, k});
            const Verdict v =
                verdict(it == first.end() ? nullptr : &runs[it->second], c, published_checks);
            by_kind[v.kind].push_back(k);
            if (!v.why.empty()) refused_by_why[v.why].push_back(k);
            cells[{c, k}] = v;
        }
        const size_t n = combos.size(), met = by_kind["met"].size();
        sentences << "- **" << c << "**: ";
        if (met == n) {
            sentences << "every combination met its accuracy.";
        } else {
            sentences << met << " of " << n << " combinations met their accuracy";
            const auto combinations = [&](const std::vector<std::string>& list) {
                for (size_t i = 0; i < list.size(); ++i) sentences << (i ? ", " : "") << list[i];
            };
            for (const char* kind : {"unchecked", "stopped", "unstable", "inaccurate"}) {
                const auto& list = by_kind[kind];
                if (list.empty()) continue;
                sentences << "; " << kind << ": ";
                combinations(list);
            }
            for (const auto& [why, list] : refused_by_why) {
                sentences << "; refused as stated (" << why << "): ";
                combinations(list);
            }
            if (!by_kind["not run"].empty()) {
                sentences << "; not run: ";
                combinations(by_kind["not run"]);
            }
            sentences << ".";
        }
        sentences << "\n";
    }
    // One matrix per formulation (a page's width holds five parameterizations, not ten).
    std::vector<std::string> formulations;
    for (const std::string& k : combos) {
        const std::string f = k.substr(0, k.find('/'));
        if (std::find(formulations.begin(), formulations.end(), f) == formulations.end())
            formulations.push_back(f);
    }
    std::ostringstream matrix;
    for (const std::string& f : formulations) {
        std::vector<std::string> mine;
        for (const std::string& k : combos) {
            if (k.substr(0, k.find('/')) == f) mine.push_back(k);
        }
        matrix << "| " << f << " formulation |";
        for (const std::string& k : mine) matrix << " " << k.substr(k.find('/') + 1) << " |";
        matrix << "\n|---|";
        for (size_t i = 0; i < mine.size(); ++i) matrix << "---|";
        matrix << "\n";
        for (const std::string& c : cases) {
            matrix << "| " << c << " |";
            for (const std::string& k : mine) {
                const auto it = first.find({c, k});
                const std::string text = markdown_cell(cells[{c, k}].text);
                if (it == first.end()) {
                    matrix << " " << text << " |";
                } else {
                    matrix << " [" << text << "](#" << run_row_id(it->second) << ") |";
                }
            }
            matrix << "\n";
        }
        matrix << "\n";
    }
    std::ostringstream md;
    md << "## Summary\n\nWhether each case's combinations met their accuracy, case by case, then "
          "combination by combination. *met (n)*: solved, and all n published checks that "
          "`verify` makes with the combination at the case's own discretization passed; *met "
          "(estimate)*: solved, and every error estimate of the run within half the case's stated "
          "accuracy; *unchecked*: solved, with neither a published check nor an estimate held "
          "against a stated accuracy (`--estimate off`, or the case states none for the "
          "formulation); *stopped*: the solve stopped (*expected* when the case file "
          "says it must); *unstable*: solved, but an equilibrium is unstable (its tangent has "
          "negative eigenvalues: status `unstable-equilibrium`); *inaccurate*: a published check "
          "missed, or an estimate above the stated "
          "accuracy; *refused as stated*: the case states that the formulation refuses it, and why "
          "(a BeamDyn deck with a key the formulation does not model), and the run was refused in "
          "those "
          "words; *not run*: the combination does not exist for the case. Each cell links to "
          "its run in the runs table.\n\n"
       << sentences.str() << "\n"
       << matrix.str();
    return md.str();
}

std::string estimate_cell(const nlohmann::json& run) {
    const nlohmann::json& estimate = run.value("estimate", nlohmann::json::object());
    const std::string status = estimate.value("status", "");
    if (status != "estimated" && status != "partial") return "not estimated";
    const Model* model = model_of(run.value("case", ""));
    if (!model) return "not estimated";
    const estimate::AccuracyMeasure m = estimate::measure_accuracy(*model, run, 1.0);
    if (m.quantities == 0) return "not estimated";
    return scientific(m.worst) + " (" + m.worst_what + ")";
}

namespace {

// The continuum reference (core/continuum) of a static case, solved once per case; nullptr when
// the case is not static, does not load, or lies outside what the continuum solver covers.
const ContinuumOutcome* continuum_of(const std::string& case_name) {
    static std::map<std::string, std::optional<ContinuumOutcome>> references;
    auto it = references.find(case_name);
    if (it == references.end()) {
        std::optional<ContinuumOutcome> c;
        const Model* model = model_of(case_name);
        if (model && model->analysis.kind == AnalysisKind::static_) {
            ContinuumOutcome outcome = solve_continuum(*model);
            if (outcome.status == "converged") c = std::move(outcome);
        }
        it = references.emplace(case_name, std::move(c)).first;
    }
    return it->second ? &*it->second : nullptr;
}

// The largest ‖u − u_ref‖/L over the run's load steps with a reference displacement at a named
// point (`reference(point index, load factor)`, nullopt where there is none), L the estimate's
// reference length; nullopt when no step has one.
std::optional<double> largest_difference(
    const nlohmann::json& run, const Model& model,
    const std::function<std::optional<Vec3>(size_t, double)>& reference) {
    std::optional<double> largest;
    const double length = estimate::reference_length(model);
    for (const nlohmann::json& step : run.value("steps", nlohmann::json::array())) {
        if (!step.contains("load_factor") || !step.contains("points")) continue;
        for (size_t i = 0; i < model.points.size(); ++i) {
            const std::string& name = model.points[i].name;
            if (!step["points"].contains(name)) continue;
            const std::optional<Vec3> exact = reference(i, step["load_factor"].get<double>());
            if (!exact) continue;
            const auto& u = step["points"][name]["displacement"];
            const Vec3 v(u[0].get<double>(), u[1].get<double>(), u[2].get<double>());
            largest = std::max(largest.value_or(0.0), (v - *exact).norm() / length);
        }
    }
    return largest;
}

}  // namespace

std::optional<PointReference> point_reference(const std::string& case_name) {
    const Model* model = model_of(case_name);
    if (!model) return std::nullopt;
    if (case_name == "cantilever-moment") {
        // The exact roll-up (core/oracles/rollup.hpp) at the tip, every load factor.
        const double l = (model->points[1].position - model->points[0].position).norm();
        return PointReference{"exact", model,
                              [l](size_t i, double lambda) -> std::optional<PointState> {
                                  if (i != 1) return std::nullopt;
                                  const oracle::RollupState s = oracle::rollup_tip(l, lambda);
                                  return PointState{s.displacement, s.rotation};
                              }};
    }
    const ContinuumOutcome* c = continuum_of(case_name);
    if (!c) return std::nullopt;
    // The continuum reference at every named point of every load step it reports.
    return PointReference{
        "continuum", model, [c](size_t i, double lambda) -> std::optional<PointState> {
            for (const ContinuumStep& step : c->steps) {
                if (std::abs(step.load_factor - lambda) <= 1e-12 * std::abs(lambda))
                    return step.points[i];
            }
            return std::nullopt;
        }};
}

std::string true_error_cell(const nlohmann::json& run, const nlohmann::json& published_checks) {
    if (const std::optional<PointReference> ref = point_reference(run.value("case", ""))) {
        const auto displacement = [&](size_t i, double lambda) -> std::optional<Vec3> {
            const std::optional<PointState> s = ref->state(i, lambda);
            if (!s) return std::nullopt;
            return s->displacement;
        };
        if (const std::optional<double> d = largest_difference(run, *ref->model, displacement))
            return scientific(*d) + " (" + ref->name + ", ‖Δu‖/L)";
    }
    std::string worst;
    double largest = -1.0;
    int count = 0;
    for (const nlohmann::json& row : published_checks) {
        if (!row_is(row, run) || row.value("quantity", "") == "stop") continue;
        const std::string difference = row.value("difference", "-");
        double d = 0.0;
        try {
            d = std::stod(difference);
        } catch (const std::exception&) {
            continue;  // no computed value ("-")
        }
        ++count;
        if (d > largest) {
            largest = d;
            worst = difference + " (" + row.value("reference", "") + ")";
        }
    }
    if (count == 0) return "—";
    return markdown_cell(worst) + ", worst of " + std::to_string(count) + " published";
}

}  // namespace rotbeam::cli
