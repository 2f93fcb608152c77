// What `rotbeam verify` runs (docs/case-format.md, "references"): the combinations a reference or
// an expected stop is checked with, the discretization each run gets, and one cached run per
// distinct discretization of a case.
#pragma once

#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/model.hpp"

namespace rotbeam::cli {

// applies_to-style settings: formulation, rotation, interpolation, wm_map (the combination),
// elements, order, quadrature, mass_rule, rescale, ... (the discretization).
using Settings = std::map<std::string, std::string>;

// Every combination the gate knows: formulation × parameterization, the displacement formulation
// with both interpolation strategies, the mixed Wiener–Milenković with both maps.
std::vector<Settings> gate_combinations();

// The combinations an applies_to selects (those agreeing with every combination key it names),
// each completed by its discretization keys.
std::vector<Settings> selected_runs(const Settings& applies_to);

// Whether a loaded model has every setting of `pattern` (an expected stop's applies_to).
bool model_has(const Model& model, const Settings& pattern);

// "displacement/quaternion/relative order=4", for the table.
std::string settings_label(const Settings& s);

// The --set overrides of the discretization keys (elements is set on the members, not here).
std::vector<std::string> discretization_overrides(const Settings& s);

// One case's runs, each discretization run once (settings that the case already has do not make
// another run). A discretization the program refuses (InputError) comes back as
// {"status": "unavailable", "available": false, "message": ...}.
class GateRuns {
  public:
    explicit GateRuns(std::string case_path);
    // The model of that discretization; nullptr when the program refuses it.
    const Model* model(const Settings& s);
    const nlohmann::json& result(const Settings& s);

  private:
    // bugprone-exception-escape: Entry's implicit special members may throw through Model's;
    // entries live in a std::map and are never moved, so nothing relies on them not throwing.
    struct Entry {  // NOLINT(bugprone-exception-escape)
        std::optional<Model> model;
        std::string refusal;  // the InputError's message when there is no model
        nlohmann::json result;
        bool loaded = false, ran = false;
    };
    Entry& entry(const Settings& s);
    std::string path_;
    Model base_;  // the case as written: settings equal to its own are dropped from a run's key
    std::map<Settings, Entry> entries_;
};

}  // namespace rotbeam::cli
