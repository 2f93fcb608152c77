// Case loader: the published references and the expected stops, what `rotbeam verify` gates
// (docs/case-format.md, "references" and "Expected stops").
#include <algorithm>
#include <cmath>

#include "cases/loader/limits.hpp"
#include "cases/loader/model_builder.hpp"
#include "combinations/registry.hpp"
#include "parameterizations/registry.hpp"

namespace rotbeam::cases {

namespace {

// The keys of applies_to that choose a combination (every one the gate runs when unnamed), and
// those that only set the discretization.
const std::vector<std::string> kCombinationKeys = {"formulation", "rotation", "interpolation",
                                                   "wm_map"};

std::string applies_value(const YamlReader& r, const YAML::Node& v, const std::string& key,
                          const std::string& name) {
    if (name == "formulation") return r.choice(v, key, choice_names<Formulation>());
    if (name == "rotation") return r.choice(v, key, param::parameterization_names());
    if (name == "quadrature") return r.choice(v, key, kQuadratures);
    if (name == "interpolation") return r.choice(v, key, choice_names<Interpolation>());
    if (name == "update") return r.choice(v, key, choice_names<Update>());
    if (name == "mass_rule") return r.choice(v, key, choice_names<MassRule>());
    if (name == "wm_map") return r.choice(v, key, choice_names<WmMap>());
    if (name == "rescale") return r.boolean(v, key) ? "true" : "false";
    if (name == "elements")
        return std::to_string(r.positive_integer(v, key, kMaxElementsPerMember));
    if (name == "order") return std::to_string(r.positive_integer(v, key, kMaxOrder));
    if (name == "refine") return std::to_string(r.positive_integer(v, key, kMaxRefine));
    return std::to_string(r.positive_integer(v, key, kMaxQuadraturePoints));
}

// `applies_to` of a reference, an `also` entry or an expected stop; `scope` (why the named
// combination keys leave the other combinations out) is required when it names one.
std::map<std::string, std::string> read_applies_to(const YamlReader& r, const YAML::Node& n,
                                                   const std::string& key, std::string& scope) {
    std::map<std::string, std::string> out;
    const YAML::Node at = n["applies_to"];
    if (at) {
        const std::string ak = key + ".applies_to";
        r.expect_map(
            at, ak,
            {"formulation", "rotation", "elements", "order", "quadrature", "quadrature_points",
             "refine", "interpolation", "update", "mass_rule", "wm_map", "rescale"});
        for (const auto& item : at) {
            const std::string name = item.first.Scalar();
            out[name] = applies_value(r, item.second, ak + "." + name, name);
        }
    }
    // Keys that no combination has would select nothing (verify_plan.cpp: gate_combinations).
    // The values were checked above: they parse.
    std::optional<Formulation> formulation;
    if (out.count("formulation")) formulation = parse_choice<Formulation>(out["formulation"]);
    bool any_wm_map = false;  // a combination the named keys allow takes wm_map
    for (const Formulation f : comb::formulations()) {
        if (formulation && f != *formulation) continue;
        for (const ParameterizationId p : param::parameterization_ids()) {
            if (out.count("rotation") && p != param::parse_parameterization(out["rotation"]))
                continue;
            any_wm_map = any_wm_map || comb::has_wm_map(f, p);
        }
    }
    if (out.count("interpolation") && formulation &&
        comb::traits(*formulation).interpolations.empty()) {
        r.fail(at["interpolation"], key + ".applies_to.interpolation",
               "the " + out["formulation"] +
                   " formulation has no interpolation strategy: no combination is selected");
    }
    if (out.count("wm_map") && !any_wm_map) {
        r.fail(at["wm_map"], key + ".applies_to.wm_map",
               "only the mixed formulation with wiener-milenkovic has a map: no combination is "
               "selected");
    }
    if (n["scope"]) scope = r.string(n["scope"], key + ".scope");
    const bool narrows = std::any_of(kCombinationKeys.begin(), kCombinationKeys.end(),
                                     [&](const std::string& k) { return out.count(k) > 0; });
    if (narrows && scope.empty()) {
        r.fail(at, key + ".applies_to",
               "names a combination (formulation, rotation, interpolation or wm_map) but no "
               "`scope` says why the other combinations are not checked");
    }
    return out;
}

bool listed(const std::vector<double>& list, double x) {
    return std::any_of(list.begin(), list.end(), [x](double v) {
        return std::abs(v - x) <= 1e-9 * std::max(1.0, std::abs(x));
    });
}

// A load factor that must be a reported step (unless --set replaced the steps: a quick run at
// other load factors is legitimate; verify then reports the entry unavailable).
double reported_load_factor(const YamlReader& r, const YAML::Node& node, const std::string& key,
                            const Model& model) {
    const double x = r.number(node, key);
    if (!r.overridden("analysis.load_factors") && !listed(model.analysis.statics.load_factors, x)) {
        r.fail(node, key, "is not one of analysis.load_factors");
    }
    return x;
}

void read_reference_where(const YamlReader& r, const YAML::Node& n, const std::string& key,
                          const Model& model, ReferenceValue& ref) {
    const Analysis& a = model.analysis;
    if (ref.quantity == "frequency") {
        if (a.kind != AnalysisKind::modal)
            r.fail(n["quantity"], key + ".quantity", "frequency needs a modal analysis");
        ref.mode = r.positive_integer(r.required(n, key, "mode"), key + ".mode");
        if (ref.mode > a.modal.modes) r.fail(n["mode"], key + ".mode", "exceeds analysis.modes");
        return;
    }
    std::vector<std::string> points;
    for (const Point& p : model.points) points.push_back(p.name);
    ref.point = r.name_in(r.required(n, key, "point"), key + ".point", points, "point");
    if (a.kind == AnalysisKind::dynamic) {
        ref.time = r.non_negative(r.required(n, key, "time"), key + ".time");
        if (*ref.time > a.dynamics.end_time)
            r.fail(n["time"], key + ".time", "is after analysis.end_time");
    } else {
        ref.load_factor =
            reported_load_factor(r, r.required(n, key, "load_factor"), key + ".load_factor", model);
    }
}

// The `also` entries: {applies_to, scope, tolerance, justification} each.
void read_also(const YamlReader& r, const YAML::Node& n, const std::string& key,
               ReferenceValue& ref) {
    if (!n.IsSequence())
        r.fail(n, key, "expected a list of {applies_to, tolerance, justification}");
    for (size_t i = 0; i < n.size(); ++i) {
        const YAML::Node item = n[i];
        const std::string k = key + "." + std::to_string(i);
        r.expect_map(item, k, {"applies_to", "scope", "tolerance", "justification"});
        ReferenceValue::Check c;
        c.applies_to = read_applies_to(r, item, k, c.scope);
        c.tolerance = r.positive(r.required(item, k, "tolerance"), k + ".tolerance");
        c.justification = r.string(r.required(item, k, "justification"), k + ".justification");
        ref.also.push_back(c);
    }
}

ReferenceValue read_reference(const YamlReader& r, const YAML::Node& n, const std::string& key,
                              const Model& model) {
    r.expect_map(n, key,
                 {"quantity", "point", "load_factor", "time", "mode", "value", "components",
                  "tolerance", "relative", "gated", "justification", "source", "applies_to",
                  "scope", "also", "iterations"});
    ReferenceValue ref;
    ref.quantity = r.choice(r.required(n, key, "quantity"), key + ".quantity",
                            {"displacement", "position", "rotation_angle", "frequency"});
    for (const char* k : {"point", "load_factor", "time", "mode"}) {
        if (!n[k]) continue;
        const bool ok =
            ref.quantity == "frequency" ? std::string(k) == "mode" : std::string(k) != "mode";
        if (!ok) r.fail(n[k], child_key(key, k), "not used with quantity " + ref.quantity);
    }
    read_reference_where(r, n, key, model, ref);
    ref.value = r.numbers(r.required(n, key, "value"), key + ".value");
    const bool vector = ref.quantity == "displacement" || ref.quantity == "position";
    if (n["components"]) {
        if (!vector) r.fail(n["components"], key + ".components", "only for vector quantities");
        for (double c : r.numbers(n["components"], key + ".components")) {
            if (c != 0.0 && c != 1.0 && c != 2.0)
                r.fail(n["components"], key + ".components", "components are 0, 1, 2 (x, y, z)");
            ref.components.push_back(static_cast<int>(c));
        }
    }
    const size_t expected = !vector ? 1 : ref.components.empty() ? 3 : ref.components.size();
    if (ref.value.size() != expected) {
        r.fail(n["value"], key + ".value",
               "expected " + std::to_string(expected) + " number(s), got " +
                   std::to_string(ref.value.size()));
    }
    ref.tolerance = r.positive(r.required(n, key, "tolerance"), key + ".tolerance");
    if (n["relative"]) ref.relative = r.boolean(n["relative"], key + ".relative");
    if (n["gated"]) ref.gated = r.boolean(n["gated"], key + ".gated");
    ref.justification = r.string(r.required(n, key, "justification"), key + ".justification");
    ref.source = r.string(r.required(n, key, "source"), key + ".source");
    if (n["iterations"]) {
        ref.published_iterations = r.positive_integer(n["iterations"], key + ".iterations");
    }
    ref.applies_to = read_applies_to(r, n, key, ref.scope);
    if (n["also"]) read_also(r, n["also"], key + ".also", ref);
    return ref;
}

ExpectedStop read_expected_stop(const YamlReader& r, const YAML::Node& n, const std::string& key,
                                const Model& model) {
    r.expect_map(n, key,
                 {"applies_to", "scope", "reaches", "stops_before", "status", "justification"});
    ExpectedStop stop;
    std::string scope;
    stop.applies_to = read_applies_to(r, n, key, scope);
    stop.stops_before =
        reported_load_factor(r, r.required(n, key, "stops_before"), key + ".stops_before", model);
    if (n["reaches"]) {
        stop.reaches = reported_load_factor(r, n["reaches"], key + ".reaches", model);
        if (*stop.reaches >= stop.stops_before)
            r.fail(n["reaches"], key + ".reaches", "must be below stops_before");
    }
    // Any status name: the results define them (a new one needs no change here).
    stop.status = r.string(r.required(n, key, "status"), key + ".status");
    if (stop.status.empty() || stop.status == "converged")
        r.fail(n["status"], key + ".status", "must name the status of a run that stops");
    stop.justification = r.string(r.required(n, key, "justification"), key + ".justification");
    return stop;
}

}  // namespace

void read_references(const YamlReader& r, const YAML::Node& root, Model& model) {
    if (const YAML::Node refs = root["references"]) {
        r.expect_named_map(refs, "references");
        for (const auto& item : refs) {
            const std::string key = "references." + item.first.Scalar();
            model.references.push_back(read_reference(r, item.second, key, model));
            model.references.back().id = item.first.Scalar();
        }
    }
    if (const YAML::Node stops = root["expected_stops"]) {
        r.expect_named_map(stops, "expected_stops");
        if (model.analysis.kind != AnalysisKind::static_) {
            r.fail(stops, "expected_stops", "needs a static analysis (a stop is a load factor)");
        }
        for (const auto& item : stops) {
            const std::string key = "expected_stops." + item.first.Scalar();
            model.expected_stops.push_back(read_expected_stop(r, item.second, key, model));
            model.expected_stops.back().id = item.first.Scalar();
        }
    }
}

}  // namespace rotbeam::cases
