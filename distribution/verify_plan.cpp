#include "distribution/verify_plan.hpp"

#include "cases/loader/case_loader.hpp"
#include "combinations/registry.hpp"
#include "core/errors.hpp"
#include "parameterizations/registry.hpp"
#include "runs/run_case.hpp"

namespace rotbeam::cli {

namespace {

// The keys that choose a combination; the others only set the discretization.
const std::vector<std::string> kCombinationKeys = {"formulation", "rotation", "interpolation",
                                                   "wm_map"};

bool is_combination_key(const std::string& key) {
    return std::find(kCombinationKeys.begin(), kCombinationKeys.end(), key) !=
           kCombinationKeys.end();
}

// A model's value of one applies_to key, as the loader writes it; "" where the key does not apply
// (interpolation outside the displacement formulation, wm_map outside the mixed WM, elements
// that differ between members).
std::string model_setting(const Model& model, const std::string& key) {
    const Discretization& d = model.discretization;
    if (key == "formulation") return std::string(choice_name(d.formulation));
    if (key == "rotation") return std::string(param::name_of(d.rotation));
    if (key == "interpolation") {
        return comb::traits(d.formulation).interpolations.empty()
                   ? ""
                   : std::string(choice_name(d.displacement.interpolation));
    }
    if (key == "wm_map") {
        return comb::has_wm_map(d.formulation, d.rotation)
                   ? std::string(choice_name(d.mixed.wm_map))
                   : "";
    }
    if (key == "order") return std::to_string(d.order);
    if (key == "quadrature_points") return std::to_string(d.quadrature_points);
    if (key == "refine") return std::to_string(d.refine);
    if (key == "update") return std::string(choice_name(d.displacement.update));
    if (key == "mass_rule") return std::string(choice_name(d.mass_rule()));
    if (key == "rescale") return d.displacement.rescale ? "true" : "false";
    if (key == "quadrature") {
        static const char* names[] = {"automatic", "reduced", "full", "gll",
                                      "trapezoidal"};  // enum order
        return names[static_cast<int>(d.quadrature)];
    }
    if (key == "elements") {
        std::string n;
        for (const Member& m : model.members) {
            const std::string e = std::to_string(m.elements);
            if (!n.empty() && n != e) return "";
            n = e;
        }
        return n;
    }
    return "";
}

}  // namespace

std::vector<Settings> gate_combinations() {
    std::vector<Settings> list;
    for (const comb::Combination& c : comb::all_combinations(true, true)) {
        Settings s = {{"formulation", std::string(choice_name(c.formulation))},
                      {"rotation", std::string(param::name_of(c.rotation))}};
        if (c.interpolation) s["interpolation"] = std::string(choice_name(*c.interpolation));
        if (c.wm_map) s["wm_map"] = std::string(choice_name(*c.wm_map));
        list.push_back(s);
    }
    return list;
}

std::vector<Settings> selected_runs(const Settings& applies_to) {
    std::vector<Settings> out;
    for (Settings c : gate_combinations()) {
        bool selected = true;
        for (const auto& [key, value] : applies_to) {
            if (!is_combination_key(key)) continue;
            const auto it = c.find(key);
            if (it == c.end() || it->second != value) selected = false;
        }
        if (!selected) continue;
        for (const auto& [key, value] : applies_to) {
            if (!is_combination_key(key)) c[key] = value;
        }
        out.push_back(c);
    }
    return out;
}

bool model_has(const Model& model, const Settings& pattern) {
    for (const auto& [key, value] : pattern) {
        if (model_setting(model, key) != value) return false;
    }
    return true;
}

std::string settings_label(const Settings& s) {
    std::string label;
    for (const std::string& key : kCombinationKeys) {
        const auto it = s.find(key);
        if (it != s.end()) label += (label.empty() ? "" : "/") + it->second;
    }
    for (const auto& [key, value] : s) {
        if (!is_combination_key(key)) label += " " + key + "=" + value;
    }
    return label;
}

std::vector<std::string> discretization_overrides(const Settings& s) {
    std::vector<std::string> overrides;
    for (const auto& [key, value] : s) {
        if (key != "elements") overrides.push_back("discretization." + key + "=" + value);
    }
    return overrides;
}

GateRuns::GateRuns(std::string case_path)
    : path_(std::move(case_path)), base_(load_case(path_, {}, CaseParts::case_file)) {}

GateRuns::Entry& GateRuns::entry(const Settings& wanted) {
    Settings s;
    for (const auto& [key, value] : wanted) {
        if (model_setting(base_, key) != value) s[key] = value;
    }
    Entry& e = entries_[s];
    if (e.loaded) return e;
    e.loaded = true;
    try {
        Model m = load_case(path_, discretization_overrides(s), CaseParts::case_file);
        const auto elements = s.find("elements");
        if (elements != s.end()) {
            for (Member& member : m.members) member.elements = std::stoi(elements->second);
        }
        e.model = std::move(m);
    } catch (const InputError& error) {
        e.refusal = error.what();
    }
    return e;
}

const Model* GateRuns::model(const Settings& s) {
    const Entry& e = entry(s);
    return e.model ? &*e.model : nullptr;
}

const nlohmann::json& GateRuns::result(const Settings& s) {
    Entry& e = entry(s);
    if (e.ran) return e.result;
    e.ran = true;
    if (e.model) {
        try {
            e.result = run_case(RunRequest{path_, *e.model});
            return e.result;
        } catch (const InputError& error) {
            e.refusal = error.what();
        }
    }
    e.result = {{"status", "unavailable"},
                {"available", false},
                {"message", e.refusal},
                {"steps", nlohmann::json::array()}};
    return e.result;
}

}  // namespace rotbeam::cli
