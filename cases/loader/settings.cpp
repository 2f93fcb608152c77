// Case loader: analysis, discretization and solver (docs/case-format.md).
#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

#include "cases/loader/limits.hpp"
#include "cases/loader/model_builder.hpp"
#include "combinations/registry.hpp"
#include "parameterizations/registry.hpp"

namespace rotbeam::cases {

const std::vector<std::string> kQuadratures = {"automatic", "reduced", "full", "gll",
                                               "trapezoidal"};

ParameterizationId read_rotation(const YamlReader& r, const YAML::Node& node,
                                 const std::string& key) {
    return *param::parse_parameterization(r.choice(node, key, param::parameterization_names()));
}

namespace {

// Keys of `analysis` and the analysis types each belongs to.
const std::vector<std::pair<const char*, std::vector<std::string>>> kAnalysisKeys = {
    {"load_factors", {"static", "modal"}},
    {"substeps", {"static", "modal"}},
    {"max_step_cuts", {"static", "modal", "dynamic"}},
    {"time_step", {"dynamic"}},
    {"end_time", {"dynamic"}},
    {"output_interval", {"dynamic"}},
    {"rho_infinity", {"dynamic"}},
    {"integrator", {"dynamic"}},
    {"initial_velocity", {"dynamic"}},
    {"initial_state", {"dynamic"}},
    {"relative_tolerance", {"dynamic"}},
    {"absolute_tolerance", {"dynamic"}},
    {"time_tolerance", {"dynamic"}},
    {"modes", {"modal"}},
    {"about_static_state", {"modal"}},
    {"estimate", {"static", "dynamic", "modal"}},
    {"estimate_companions", {"static", "dynamic", "modal"}},
    {"accuracy", {"static", "modal", "dynamic"}}};

void read_static(const YamlReader& r, const YAML::Node& n, StaticSettings& s, bool required) {
    if (n["load_factors"] || required) {
        s.load_factors =
            r.numbers(r.required(n, "analysis", "load_factors"), "analysis.load_factors");
        if (s.load_factors.empty())
            r.fail(n["load_factors"], "analysis.load_factors", "must not be empty");
        if (s.load_factors.size() > static_cast<size_t>(kMaxLoadFactors)) {
            r.fail(n["load_factors"], "analysis.load_factors",
                   "has " + std::to_string(s.load_factors.size()) + " entries, more than " +
                       std::to_string(kMaxLoadFactors) + " (a limit of the case format)");
        }
    }
    if (n["substeps"])
        s.substeps = r.positive_integer(n["substeps"], "analysis.substeps", kMaxSubsteps);
    const long total = static_cast<long>(s.load_factors.size()) * s.substeps;
    if (total > kMaxStaticSubsteps) {
        r.fail(n["substeps"], "analysis.substeps",
               std::to_string(s.substeps) + " sub-steps per load factor × " +
                   std::to_string(s.load_factors.size()) +
                   " load factors = " + std::to_string(total) + " sub-steps, more than " +
                   std::to_string(kMaxStaticSubsteps) + " (a limit of the case format)");
    }
    if (n["max_step_cuts"]) {
        s.max_step_cuts = r.integer(n["max_step_cuts"], "analysis.max_step_cuts");
        if (s.max_step_cuts < 0)
            r.fail(n["max_step_cuts"], "analysis.max_step_cuts", "must not be negative");
        if (s.max_step_cuts > kMaxStepCuts) {
            r.fail(n["max_step_cuts"], "analysis.max_step_cuts",
                   "must be at most " + std::to_string(kMaxStepCuts) +
                       " (a limit of the case format: a sub-step cut that often is round-off)");
        }
    }
}

void read_dynamic(const YamlReader& r, const YAML::Node& n, DynamicSettings& d) {
    d.time_step = r.positive(r.required(n, "analysis", "time_step"), "analysis.time_step");
    d.end_time = r.positive(r.required(n, "analysis", "end_time"), "analysis.end_time");
    if (d.end_time < d.time_step)
        r.fail(n["end_time"], "analysis.end_time", "is shorter than time_step");
    if (d.end_time / d.time_step > kMaxTimeSteps) {
        std::ostringstream m;
        m << "end_time / time_step = " << d.end_time / d.time_step << " time steps, more than "
          << kMaxTimeSteps << " (a limit of the case format)";
        r.fail(n["time_step"], "analysis.time_step", m.str());
    }
    if (n["output_interval"]) {
        d.output_interval = r.non_negative(n["output_interval"], "analysis.output_interval");
    }
    if (n["rho_infinity"]) {
        d.rho_infinity = r.number(n["rho_infinity"], "analysis.rho_infinity");
        if (d.rho_infinity < 0.0 || d.rho_infinity > 1.0) {
            r.fail(n["rho_infinity"], "analysis.rho_infinity", "must lie in [0, 1]");
        }
    }
    if (n["integrator"]) {
        // Any formulation's name here; case_loader.cpp checks it against the case's formulation.
        const std::string name = r.string(n["integrator"], "analysis.integrator");
        const std::optional<Integrator> integrator = parse_choice<Integrator>(name);
        if (!integrator) {
            std::string valid;
            for (const comb::FormulationTraits& f : comb::kFormulations) {
                valid += (valid.empty() ? "" : "; ") + std::string(choice_name(f.id)) + ": " +
                         comb::integrator_names(f.id);
            }
            r.fail(n["integrator"], "analysis.integrator",
                   "unknown integrator '" + name + "' (" + valid + ")");
        }
        d.integrator = *integrator;
    }
    if (n["initial_state"]) {
        d.initial_state =
            read_choice<InitialState>(r, n["initial_state"], "analysis.initial_state");
    }
    if (n["initial_velocity"])
        d.initial_velocity = r.vec3(n["initial_velocity"], "analysis.initial_velocity");
    if (n["time_tolerance"]) {
        // Adaptive time steps (core/step_size_control.hpp): a relative global error, in the
        // range of analysis.accuracy.
        d.time_tolerance = r.positive(n["time_tolerance"], "analysis.time_tolerance");
        if (d.time_tolerance < kMinAccuracy || d.time_tolerance >= kMaxAccuracy) {
            std::ostringstream m;
            m << "must lie in [" << kMinAccuracy << ", " << kMaxAccuracy << ")";
            r.fail(n["time_tolerance"], "analysis.time_tolerance", m.str());
        }
    }
    if (n["max_step_cuts"]) {
        d.max_step_cuts = r.integer(n["max_step_cuts"], "analysis.max_step_cuts");
        if (d.max_step_cuts < 0 || d.max_step_cuts > kMaxStepCuts) {
            r.fail(n["max_step_cuts"], "analysis.max_step_cuts",
                   "must lie in [0, " + std::to_string(kMaxStepCuts) + "]");
        }
    }
    // IDA's tolerances (the mixed formulation's `ida` integrator): refused for any other
    // integrator, which would ignore them, and outside [1e-14, 1): a weighted error below ~50 ε
    // cannot be met in double precision (IDA fails with IDA_TOO_MUCH_ACC), and 1 asks for nothing.
    for (const char* name : {"relative_tolerance", "absolute_tolerance"}) {
        if (!n[name]) continue;
        const std::string key = std::string("analysis.") + name;
        const double v = r.positive(n[name], key);
        if (v < 1e-14 || v >= 1.0) r.fail(n[name], key, "must lie in [1e-14, 1)");
        if (d.integrator != Integrator::ida) {
            r.fail(n[name], key, "used only by analysis.integrator: ida (the tolerances of IDA)");
        }
        (std::string(name) == "relative_tolerance" ? d.relative_tolerance : d.absolute_tolerance) =
            v;
    }
}

// discretization.accuracy: {FORMULATION: TOL}, each TOL in the range of analysis.accuracy.
void read_stated_accuracy(const YamlReader& r, const YAML::Node& n, Discretization& d) {
    const std::string k = "discretization.accuracy";
    if (!n.IsMap()) r.fail(n, k, "expected a mapping of formulation: accuracy");
    r.expect_unique_keys(n, k);
    for (const auto& item : n) {
        const std::string name = item.first.Scalar();
        const std::optional<Formulation> f = parse_choice<Formulation>(name);
        if (!f) r.fail(item.first, k + "." + name, "unknown formulation");
        const double tol = r.positive(item.second, k + "." + name);
        if (tol < kMinAccuracy || tol >= kMaxAccuracy) {
            std::ostringstream m;
            m << "must lie in [" << kMinAccuracy << ", " << kMaxAccuracy << ")";
            r.fail(item.second, k + "." + name, m.str());
        }
        d.stated_accuracy[*f] = tol;
    }
}

}  // namespace

void read_analysis(const YamlReader& r, const YAML::Node& root, Model& model) {
    const YAML::Node n = r.required(root, "", "analysis");
    std::vector<const char*> allowed = {"type"};
    for (const auto& [k, kinds] : kAnalysisKeys) allowed.push_back(k);
    if (!n.IsMap()) r.fail(n, "analysis", "expected a mapping");
    r.expect_unique_keys(n, "analysis");
    const std::string type = r.choice(r.required(n, "analysis", "type"), "analysis.type",
                                      {"static", "dynamic", "modal"});
    for (const auto& item : n) {
        const std::string k = item.first.Scalar();
        const auto it = std::find_if(kAnalysisKeys.begin(), kAnalysisKeys.end(),
                                     [&](const auto& e) { return k == e.first; });
        if (k == "type") continue;
        if (it == kAnalysisKeys.end()) {
            std::vector<std::string> names(allowed.begin(), allowed.end());
            const std::string s = closest_match(k, names);
            r.fail(item.first, "analysis." + k,
                   "unknown key" + (s.empty() ? "" : "; did you mean '" + s + "'?"));
        }
        if (std::find(it->second.begin(), it->second.end(), type) == it->second.end()) {
            r.fail(item.first, "analysis." + k, "not used by a " + type + " analysis");
        }
    }
    Analysis& a = model.analysis;
    if (n["estimate"]) a.estimate = r.boolean(n["estimate"], "analysis.estimate");
    if (n["estimate_companions"]) {
        a.estimate_companions =
            read_choice<CompanionSide>(r, n["estimate_companions"], "analysis.estimate_companions");
    }
    if (n["accuracy"]) {
        // The target of accuracy control (docs/accuracy-control.md): refines until the estimates
        // meet it, so it needs them.
        a.accuracy = r.positive(n["accuracy"], "analysis.accuracy");
        if (a.accuracy < kMinAccuracy || a.accuracy >= kMaxAccuracy) {
            std::ostringstream m;
            m << "must lie in [" << kMinAccuracy << ", " << kMaxAccuracy
              << ") (a relative accuracy; docs/accuracy-control.md)";
            r.fail(n["accuracy"], "analysis.accuracy", m.str());
        }
        if (!a.estimate) {
            r.fail(n["accuracy"], "analysis.accuracy",
                   "needs the error estimate, which analysis.estimate: false switches off");
        }
    }
    if (type == "static") {
        a.kind = AnalysisKind::static_;
        read_static(r, n, a.statics, true);
    } else if (type == "dynamic") {
        a.kind = AnalysisKind::dynamic;
        read_dynamic(r, n, a.dynamics);
        if (a.accuracy > 0.0) {
            // Accuracy control of a dynamic run (docs/accuracy-control.md, Dynamics): the target
            // accuracy/2 split between the mesh and the time step, so the adaptive steps start
            // with accuracy/4 as their global tolerance, which the control tightens when the
            // estimate's time part asks for it.
            if (n["time_tolerance"]) {
                r.fail(n["accuracy"], "analysis.accuracy",
                       "sets the time tolerance of a dynamic analysis (accuracy/4); give one of "
                       "analysis.accuracy and analysis.time_tolerance");
            }
            a.dynamics.time_tolerance = 0.25 * a.accuracy;
        }
    } else {
        a.kind = AnalysisKind::modal;
        read_static(r, n, a.statics, false);
        if (n["modes"]) a.modal.modes = r.positive_integer(n["modes"], "analysis.modes", kMaxModes);
        if (n["about_static_state"]) {
            a.modal.about_static_state =
                r.boolean(n["about_static_state"], "analysis.about_static_state");
        }
    }
}

namespace {

// The discretization keys that belong to one formulation's options (core/model.hpp); the others
// are shared. A case that gives a key of a formulation it does not run in is refused.
const std::vector<std::pair<const char*, std::vector<Formulation>>> kFormulationKeys = {
    {"interpolation", {Formulation::displacement}},
    {"update", {Formulation::displacement}},
    {"rescale", {Formulation::displacement}},
    {"mass_rule", {Formulation::displacement, Formulation::mixed}},
    {"wm_map", {Formulation::mixed}}};

void refuse_other_formulations_keys(const YamlReader& r, const YAML::Node& n, Formulation f) {
    for (const auto& [key, formulations] : kFormulationKeys) {
        if (!n[key] || std::find(formulations.begin(), formulations.end(), f) != formulations.end())
            continue;
        std::string owners;
        for (const Formulation o : formulations) {
            owners += (owners.empty() ? "" : ", ") + std::string(choice_name(o));
        }
        r.fail(n[key], "discretization." + std::string(key),
               "not an option of the " + std::string(choice_name(f)) +
                   " formulation (an option of the " + owners + " formulation)");
    }
}

void read_displacement_options(const YamlReader& r, const YAML::Node& n, DisplacementOptions& o) {
    const std::string k = "discretization";
    if (n["interpolation"])
        o.interpolation = read_choice<Interpolation>(r, n["interpolation"], k + ".interpolation");
    if (n["update"]) o.update = read_choice<Update>(r, n["update"], k + ".update");
    if (n["rescale"]) o.rescale = r.boolean(n["rescale"], k + ".rescale");
    if (n["mass_rule"]) o.mass_rule = read_choice<MassRule>(r, n["mass_rule"], k + ".mass_rule");
}

void read_mixed_options(const YamlReader& r, const YAML::Node& n, ParameterizationId rotation,
                        MixedOptions& o) {
    const std::string k = "discretization";
    if (n["mass_rule"]) {
        o.mass_rule = read_choice<MassRule>(r, n["mass_rule"], k + ".mass_rule");
        // The mixed element's momenta are element unknowns: nothing to lump
        // (docs/mixed-dynamics.md).
        if (o.mass_rule == MassRule::lumped) {
            r.fail(n["mass_rule"], k + ".mass_rule",
                   std::string(comb::traits(Formulation::mixed).no_lumped_mass_reason));
        }
    }
    if (n["wm_map"]) {
        // Only the rotations the combination registry gives a WM map (comb::has_wm_map) take
        // it; with another one it would be ignored.
        if (!comb::has_wm_map(Formulation::mixed, rotation)) {
            std::string takers;
            for (const ParameterizationId p : param::parameterization_ids()) {
                if (!comb::has_wm_map(Formulation::mixed, p)) continue;
                takers += (takers.empty() ? "" : " | ") + std::string(param::name_of(p));
            }
            r.fail(n["wm_map"], k + ".wm_map",
                   "not an option of rotation '" + std::string(param::name_of(rotation)) +
                       "' (an option of rotation " + takers + ")");
        }
        o.wm_map = read_choice<WmMap>(r, n["wm_map"], k + ".wm_map");
    }
}

}  // namespace

void read_discretization(const YamlReader& r, const YAML::Node& root, Model& model) {
    const YAML::Node n = root["discretization"];
    if (!n) return;
    const std::string k = "discretization";
    r.expect_map(n, k,
                 {"formulation", "rotation", "order", "quadrature", "quadrature_points", "refine",
                  "interpolation", "update", "rescale", "mass_rule", "wm_map", "accuracy"});
    Discretization& d = model.discretization;
    if (n["formulation"])
        d.formulation = read_choice<Formulation>(r, n["formulation"], k + ".formulation");
    if (n["rotation"]) d.rotation = read_rotation(r, n["rotation"], k + ".rotation");
    if (n["order"]) d.order = r.positive_integer(n["order"], k + ".order", kMaxOrder);
    if (n["quadrature"]) {
        const std::string q = r.choice(n["quadrature"], k + ".quadrature", kQuadratures);
        const auto at =
            std::find(kQuadratures.begin(), kQuadratures.end(), q) - kQuadratures.begin();
        d.quadrature = static_cast<Quadrature>(at);  // kQuadratures lists the enum in order
    }
    if (n["quadrature_points"])
        d.quadrature_points = r.positive_integer(n["quadrature_points"], k + ".quadrature_points",
                                                 kMaxQuadraturePoints);
    // The trapezoidal rule's points are the section stations and their divisions: it has no
    // point count, and `refine` belongs to it alone.
    const bool trapezoidal = d.quadrature == Quadrature::trapezoidal;
    if (trapezoidal && n["quadrature_points"]) {
        r.fail(n["quadrature_points"], k + ".quadrature_points",
               "not an option of quadrature trapezoidal (its points are the section stations, "
               "divided by refine)");
    }
    if (n["refine"]) {
        if (!trapezoidal) {
            r.fail(n["refine"], k + ".refine", "an option of quadrature trapezoidal only");
        }
        d.refine = r.positive_integer(n["refine"], k + ".refine", kMaxRefine);
    }
    refuse_other_formulations_keys(r, n, d.formulation);
    switch (d.formulation) {
        case Formulation::displacement:
            read_displacement_options(r, n, d.displacement);
            break;
        case Formulation::mixed:
            read_mixed_options(r, n, d.rotation, d.mixed);
            break;
    }
    if (n["accuracy"]) read_stated_accuracy(r, n["accuracy"], d);
}

void read_solver(const YamlReader& r, const YAML::Node& root, Model& model) {
    const YAML::Node n = root["solver"];
    if (!n) return;
    const std::string k = "solver";
    r.expect_map(
        n, k,
        {"residual_tolerance", "increment_tolerance", "max_iterations", "line_search", "mip",
         "linear_solver", "driver", "force_scale", "length_scale", "assemble_all_terms"});
    SolverSettings& s = model.solver;
    if (n["residual_tolerance"])
        s.residual_tolerance = r.positive(n["residual_tolerance"], k + ".residual_tolerance");
    if (n["increment_tolerance"])
        s.increment_tolerance = r.positive(n["increment_tolerance"], k + ".increment_tolerance");
    if (n["max_iterations"])
        s.max_iterations =
            r.positive_integer(n["max_iterations"], k + ".max_iterations", kMaxNewtonIterations);
    if (n["line_search"]) s.line_search = r.boolean(n["line_search"], k + ".line_search");
    if (n["mip"]) {
        // An option of the displacement formulation (DisplacementOptions), kept under `solver`.
        const Formulation f = model.discretization.formulation;
        if (!comb::traits(f).mip)
            r.fail(n["mip"], k + ".mip", std::string(comb::traits(f).no_mip_reason));
        model.discretization.displacement.mip = r.boolean(n["mip"], k + ".mip");
    }
    if (n["linear_solver"]) {
        s.linear_solver = read_choice<LinearSolver>(r, n["linear_solver"], k + ".linear_solver");
    }
    if (n["driver"]) s.driver = read_choice<Driver>(r, n["driver"], k + ".driver");
    if (n["force_scale"]) s.force_scale = r.non_negative(n["force_scale"], k + ".force_scale");
    if (n["length_scale"]) s.length_scale = r.non_negative(n["length_scale"], k + ".length_scale");
    if (n["assemble_all_terms"])
        s.assemble_all_terms = r.boolean(n["assemble_all_terms"], k + ".assemble_all_terms");
}

}  // namespace rotbeam::cases
