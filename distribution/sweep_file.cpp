#include "distribution/sweep_file.hpp"

#include <yaml-cpp/depthguard.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cases/loader/case_loader.hpp"
#include "cases/loader/file_name_part.hpp"
#include "cases/loader/limits.hpp"
#include "cases/loader/yaml_file.hpp"
#include "cases/loader/yaml_reader.hpp"
#include "combinations/registry.hpp"
#include "core/errors.hpp"
#include "runs/catalog.hpp"
#include "runs/run_cost.hpp"

namespace rotbeam::cli {

namespace fs = std::filesystem;

std::vector<std::string> SweepRun::overrides(const std::vector<std::string>& keys) const {
    std::vector<std::string> o;
    if (!interpolation.empty()) o.push_back("discretization.interpolation=" + interpolation);
    if (!wm_map.empty()) o.push_back("discretization.wm_map=" + wm_map);
    for (size_t i = 0; i < keys.size(); ++i) o.push_back(keys[i] + "=" + values[i]);
    return o;
}

namespace {

constexpr cases::YamlFileKind kSweepFile{"sweep file", "keys (name, cases, ...)",
                                         "the limit of a sweep file"};

// Messages: `FILE:LINE: KEY: problem`, one line.
struct Where {
    const std::string& file;
    [[noreturn]] void fail(const YAML::Node& node, const std::string& key,
                           const std::string& problem) const {
        // A key that is absent (an invalid node) is reported at the first line.
        const YAML::Mark m = node.IsDefined() ? node.Mark() : YAML::Mark::null_mark();
        const std::string line = m.is_null() || m.line < 0 ? "1" : std::to_string(m.line + 1);
        throw InputError(cases::one_line(file + ":" + line + ": " + key + ": " + problem));
    }
};

template <class E>
std::vector<std::string> names_of() {
    std::vector<std::string> names;
    for (const std::string_view n : ChoiceNames<E>::kNames) names.emplace_back(n);
    return names;
}

void expect_keys(const Where& w, const YAML::Node& map, const std::string& key,
                 const std::vector<std::string>& allowed) {
    if (!map.IsMap()) w.fail(map, key.empty() ? "(file)" : key, "expected a mapping");
    std::vector<std::string> seen;
    for (const auto& item : map) {
        const std::string k = item.first.Scalar();
        const std::string full = key.empty() ? k : key + "." + k;
        if (std::find(seen.begin(), seen.end(), k) != seen.end())
            w.fail(item.first, full, "appears twice");
        seen.push_back(k);
        if (std::find(allowed.begin(), allowed.end(), k) == allowed.end()) {
            const std::string guess = closest_match(k, allowed);
            w.fail(item.first, full,
                   "unknown key" + (guess.empty() ? "" : "; did you mean '" + guess + "'?"));
        }
    }
}

// A value that names files or a folder (cases/loader/file_name_part.hpp).
std::string file_name_part(const Where& w, const YAML::Node& node, const std::string& key) {
    if (!node.IsScalar()) w.fail(node, key, "expected a name");
    const std::string problem = cases::file_name_part_problem(node.Scalar());
    if (!problem.empty()) w.fail(node, key, problem);
    return node.Scalar();
}

// The items of a scalar (one) or a list; anything else is refused as not `expected`.
std::vector<YAML::Node> one_or_list(const Where& w, const YAML::Node& node, const std::string& key,
                                    const std::string& expected) {
    std::vector<YAML::Node> items;
    if (node.IsScalar()) {
        items.push_back(node);
    } else if (node.IsSequence()) {
        for (const auto& n : node) items.push_back(n);
    } else {
        w.fail(node, key, "expected " + expected);
    }
    return items;
}

// A list of names, each one of `choices` (a single name is a list of one).
std::vector<std::string> name_list(const Where& w, const YAML::Node& node, const std::string& key,
                                   const std::vector<std::string>& choices) {
    const std::vector<YAML::Node> items = one_or_list(w, node, key, "a name or a list of names");
    if (items.empty()) w.fail(node, key, "empty list");
    std::vector<std::string> names;
    for (const YAML::Node& n : items) {
        if (!n.IsScalar()) w.fail(n, key, "expected a name");
        const std::string v = n.Scalar();
        if (std::find(choices.begin(), choices.end(), v) == choices.end()) {
            const std::string guess = closest_match(v, choices);
            w.fail(n, key,
                   "unknown value '" + v + "'" +
                       (guess.empty() ? "" : "; did you mean '" + guess + "'?"));
        }
        if (std::find(names.begin(), names.end(), v) != names.end())
            w.fail(n, key, "'" + v + "' listed twice");
        names.push_back(v);
    }
    return names;
}

double number(const Where& w, const YAML::Node& node, const std::string& key) {
    if (!node.IsScalar()) w.fail(node, key, "expected a number");
    try {
        const double x = node.as<double>();
        if (std::isfinite(x)) return x;
    } catch (const YAML::Exception&) {
    }
    w.fail(node, key, "expected a finite number, got '" + node.Scalar() + "'");
}

// An integer written as one (no fraction, no exponent), within ±1e15.
std::optional<long long> integer(const YAML::Node& node) {
    if (!node.IsScalar()) return std::nullopt;
    const std::string& s = node.Scalar();
    if (s.empty() || s.size() > 16) return std::nullopt;
    size_t used = 0;
    try {
        const long long n = std::stoll(s, &used);
        if (used == s.size()) return n;
    } catch (const std::exception&) {
    }
    return std::nullopt;
}

std::string number_text(double x) { return nlohmann::json(x).dump(); }

// The count of a generator: an integer in [1, kMaxSweepRuns] (0: an empty range).
long count(const Where& w, const YAML::Node& node, const std::string& key) {
    const auto n = integer(node);
    if (!n) w.fail(node, key, "the count must be an integer, got '" + node.Scalar() + "'");
    if (*n < 1) w.fail(node, key, "empty range (count " + node.Scalar() + ")");
    if (*n > kMaxSweepRuns) {
        w.fail(node, key,
               "more than " + std::to_string(kMaxSweepRuns) + " values (the limit of a sweep)");
    }
    return static_cast<long>(*n);
}

// `{linspace: [from, to, n]}`, `{logspace: [from, to, n]}` (10^from … 10^to),
// `{geometric: [first, ratio, n]}`, `{range: [from, to]}` or `{range: [from, to, step]}`
// (integers, both ends included).
std::vector<std::string> generated(const Where& w, const YAML::Node& node, const std::string& key) {
    if (node.size() != 1) {
        w.fail(node, key, "a range is one of linspace, logspace, geometric, range");
    }
    const std::string kind = node.begin()->first.Scalar();
    const YAML::Node args = node.begin()->second;
    const std::string k = key + "." + kind;
    const std::vector<std::string> kinds = {"linspace", "logspace", "geometric", "range"};
    if (std::find(kinds.begin(), kinds.end(), kind) == kinds.end()) {
        const std::string guess = closest_match(kind, kinds);
        w.fail(node.begin()->first, k,
               "unknown range (linspace | logspace | geometric | range)" +
                   (guess.empty() ? "" : "; did you mean '" + guess + "'?"));
    }
    const size_t arity = args.IsSequence() ? args.size() : 0;
    if (arity != 3 && !(kind == "range" && arity == 2)) {
        w.fail(args, k,
               kind == "range"       ? "expected [from, to] or [from, to, step]"
               : kind == "geometric" ? "expected [first, ratio, count]"
                                     : "expected [from, to, count]");
    }
    std::vector<std::string> values;
    if (kind == "range") {
        const auto from = integer(args[0]), to = integer(args[1]);
        const auto step = arity == 3 ? integer(args[2]) : std::optional<long long>(1);
        if (!from || !to || !step) w.fail(args, k, "range takes integers");
        if (*step < 1) w.fail(args[2], k, "the step must be a positive integer");
        if (*to < *from) w.fail(args, k, "empty range (to < from)");
        if ((*to - *from) / *step >= kMaxSweepRuns) {
            w.fail(args, k,
                   "more than " + std::to_string(kMaxSweepRuns) + " values (the limit of a sweep)");
        }
        for (long long v = *from; v <= *to; v += *step) values.push_back(std::to_string(v));
        return values;
    }
    const long n = count(w, args[2], k);
    if (kind == "geometric") {
        const auto first = integer(args[0]), ratio = integer(args[1]);
        const double f = number(w, args[0], k), r = number(w, args[1], k);
        if (!(r > 0.0)) w.fail(args[1], k, "the ratio must be positive");
        for (long i = 0; i < n; ++i) {
            const double v = f * std::pow(r, static_cast<double>(i));
            if (!std::isfinite(v)) w.fail(args, k, "overflows at value " + std::to_string(i + 1));
            // Integers stay integers (element counts) while they are exact in a double.
            values.push_back(first && ratio && std::fabs(v) < 9e15
                                 ? std::to_string(static_cast<long long>(std::llround(v)))
                                 : number_text(v));
        }
        return values;
    }
    const double a = number(w, args[0], k), b = number(w, args[1], k);
    const auto ia = integer(args[0]), ib = integer(args[1]);
    for (long i = 0; i < n; ++i) {
        // Weighted so that both ends are exactly the values written.
        const double x = n == 1
                             ? a
                             : (a * static_cast<double>(n - 1 - i) + b * static_cast<double>(i)) /
                                   static_cast<double>(n - 1);
        if (kind == "logspace") {
            const double v = std::pow(10.0, x);
            if (!std::isfinite(v) || v == 0.0)
                w.fail(args, k, "10^" + number_text(x) + " is not a finite non-zero number");
            values.push_back(number_text(v));
        } else if (ia && ib && n > 1 && (*ib - *ia) % (n - 1) == 0) {
            values.push_back(std::to_string(*ia + (*ib - *ia) / (n - 1) * i));
        } else {
            values.push_back(number_text(x));
        }
    }
    return values;
}

// A value as `--set` text: a scalar as written, a list or mapping in YAML flow style.
std::string value_text(const YAML::Node& node) {
    if (node.IsScalar()) return node.Scalar();
    YAML::Emitter e;
    e << YAML::Flow << node;
    return e.c_str();
}

// A swept key's values: a list, a range, or one scalar.
std::vector<std::string> values_of(const Where& w, const YAML::Node& node, const std::string& key) {
    if (node.IsNull()) w.fail(node, key, "no values");
    if (node.IsScalar()) return {node.Scalar()};
    if (node.IsMap()) return generated(w, node, key);
    if (node.size() == 0) w.fail(node, key, "empty list");
    if (node.size() > static_cast<size_t>(kMaxSweepRuns)) {
        w.fail(node, key,
               "more than " + std::to_string(kMaxSweepRuns) + " values (the limit of a sweep)");
    }
    std::vector<std::string> values;
    for (const auto& item : node) values.push_back(value_text(item));
    return values;
}

// The case loader's message without its `FILE:--set: ` prefix (the case is named anyway).
std::string loader_problem(const std::string& message) {
    const size_t at = message.find(":--set: ");
    return at == std::string::npos ? message : message.substr(at + 8);
}

struct Axis {
    std::string key;
    YAML::Node node;
    std::vector<std::string> values;
};

struct CaseEntry {
    std::string name, path;
    YAML::Node node;
};

std::vector<CaseEntry> read_cases(const Where& w, const YAML::Node& root,
                                  const std::string& base_dir) {
    if (!root["cases"]) w.fail(root, "cases", "missing required key");
    const YAML::Node node = root["cases"];
    const std::vector<YAML::Node> items =
        one_or_list(w, node, "cases", "a case or a list of cases");
    if (items.empty()) w.fail(node, "cases", "empty list");
    if (items.size() > static_cast<size_t>(kMaxSweepRuns)) {
        w.fail(node, "cases",
               "more than " + std::to_string(kMaxSweepRuns) + " cases (the limit of a sweep)");
    }
    std::vector<CaseEntry> cases;
    for (const YAML::Node& n : items) {
        if (!n.IsScalar() || n.Scalar().empty()) w.fail(n, "cases", "expected a case name or path");
        const std::string arg = n.Scalar();
        std::string path;
        const fs::path beside = fs::path(base_dir) / arg;
        try {
            path = (!base_dir.empty() && fs::path(arg).is_relative() && fs::exists(beside) &&
                    fs::is_regular_file(beside))
                       ? beside.string()
                       : resolve_case_path(arg);
            if (!fs::is_regular_file(path)) throw InputError(arg + ": not a case file");
        } catch (const InputError& e) {
            w.fail(n, "cases", e.what());
        } catch (const fs::filesystem_error& e) {
            w.fail(n, "cases", arg + ": " + e.code().message());
        }
        for (const CaseEntry& c : cases) {
            if (c.path == path) w.fail(n, "cases", "'" + arg + "' listed twice");
        }
        // The stem names the case's run files.
        const std::string name = fs::path(arg).stem().string();
        if (const std::string problem = cases::file_name_part_problem(name); !problem.empty())
            w.fail(n, "cases", "the case's file name " + problem);
        cases.push_back({name, path, n});
    }
    return cases;
}

struct Combos {
    YAML::Node node;
    std::vector<std::string> formulations, rotations, interpolations, wm_maps;
    bool explicit_pairs = false;  // formulation or rotation named: refusals are errors
};

Combos read_combinations(const Where& w, const YAML::Node& root) {
    Combos c;
    std::vector<std::string> formulations, rotations = param::parameterization_names();
    for (const Formulation f : comb::formulations()) formulations.emplace_back(choice_name(f));
    c.formulations = formulations;
    c.rotations = rotations;
    if (!root["combinations"]) return c;
    c.node = root["combinations"];
    expect_keys(w, c.node, "combinations", {"formulation", "rotation", "interpolation", "wm_map"});
    if (c.node["formulation"]) {
        c.formulations =
            name_list(w, c.node["formulation"], "combinations.formulation", formulations);
        c.explicit_pairs = true;
    }
    if (c.node["rotation"]) {
        c.rotations = name_list(w, c.node["rotation"], "combinations.rotation", rotations);
        c.explicit_pairs = true;
    }
    if (c.node["interpolation"]) {
        c.interpolations = name_list(w, c.node["interpolation"], "combinations.interpolation",
                                     names_of<Interpolation>());
    }
    if (c.node["wm_map"])
        c.wm_maps = name_list(w, c.node["wm_map"], "combinations.wm_map", names_of<WmMap>());
    return c;
}

std::vector<Axis> read_parameters(const Where& w, const YAML::Node& root) {
    std::vector<Axis> axes;
    const YAML::Node node = root["parameters"];
    if (!node) return axes;
    if (!node.IsMap()) w.fail(node, "parameters", "expected a mapping of case keys to values");
    for (const auto& item : node) {
        const std::string key = item.first.Scalar();
        const std::string full = "parameters." + key;
        for (const Axis& a : axes) {
            if (a.key == key) w.fail(item.first, full, "appears twice");
        }
        if (key == "discretization.formulation" || key == "discretization.rotation" ||
            key == "discretization.interpolation" || key == "discretization.wm_map") {
            w.fail(item.first, full,
                   "a combination, not a parameter: list it under combinations." +
                       key.substr(key.find('.') + 1));
        }
        if (key.empty() || key.find('=') != std::string::npos)
            w.fail(item.first, full, "not a case key path");
        axes.push_back({key, item.second, values_of(w, item.second, full)});
    }
    return axes;
}

// The value tuples: the product of the axes (the last varying fastest) or, zipped, the i-th
// value of every axis.
std::vector<std::vector<std::string>> tuples(const Where& w, const YAML::Node& root,
                                             const std::vector<Axis>& axes, bool zip,
                                             long per_tuple_runs) {
    std::vector<std::vector<std::string>> out;
    if (axes.empty()) return {{}};
    if (zip) {
        for (const Axis& a : axes) {
            if (a.values.size() != axes.front().values.size()) {
                w.fail(root["combine"], "combine",
                       "zip needs as many values for every key: " + axes.front().key + " has " +
                           std::to_string(axes.front().values.size()) + ", " + a.key + " has " +
                           std::to_string(a.values.size()));
            }
        }
        for (size_t i = 0; i < axes.front().values.size(); ++i) {
            out.emplace_back();
            for (const Axis& a : axes) out.back().push_back(a.values[i]);
        }
    } else {
        long total = 1;
        for (const Axis& a : axes) {
            total *= static_cast<long>(a.values.size());
            if (total * per_tuple_runs > kMaxSweepRuns) {
                w.fail(a.node, "parameters." + a.key,
                       "the sweep expands to more than " + std::to_string(kMaxSweepRuns) +
                           " runs (the limit of a sweep; docs/sweeps.md)");
            }
        }
        out.assign(1, {});
        for (const Axis& a : axes) {
            std::vector<std::vector<std::string>> next;
            for (const auto& t : out) {
                for (const std::string& v : a.values) {
                    next.push_back(t);
                    next.back().push_back(v);
                }
            }
            out = std::move(next);
        }
    }
    return out;
}

// Every value of every axis through the case loader on its own, so that a refusal names the key.
void validate_values(const Where& w, const CaseEntry& c, const std::vector<Axis>& axes) {
    for (const Axis& a : axes) {
        for (size_t i = 0; i < a.values.size(); ++i) {
            try {
                (void)load_case(c.path, {a.key + "=" + a.values[i]}, CaseParts::case_file);
            } catch (const InputError& e) {
                const YAML::Node at = a.node.IsSequence() ? a.node[i] : a.node;
                w.fail(at, "parameters." + a.key,
                       "case " + c.name + " refuses '" + a.values[i] +
                           "': " + loader_problem(e.what()));
            }
        }
    }
}

// The combinations of one case: formulation × rotation (× interpolation × wm_map where the
// formulation has them). Without a formulation or rotation list, those the case refuses are left
// out (the case does not support them); a pair that was asked for and is refused stops the sweep.
std::vector<SweepRun> combinations_of(const Where& w, const CaseEntry& c, const Combos& combos) {
    std::vector<SweepRun> runs;
    for (const std::string& f : combos.formulations) {
        const Formulation id = *parse_choice<Formulation>(f);
        const comb::FormulationTraits& t = comb::traits(id);
        for (const std::string& r : combos.rotations) {
            try {
                (void)load_case(c.path,
                                {"discretization.formulation=" + f, "discretization.rotation=" + r},
                                CaseParts::case_file);
            } catch (const InputError& e) {
                if (!combos.explicit_pairs) continue;
                w.fail(
                    combos.node, "combinations",
                    "case " + c.name + " refuses " + f + "/" + r + ": " + loader_problem(e.what()));
            }
            std::vector<std::string> interps = {""}, maps = {""};
            if (!combos.interpolations.empty() && !t.interpolations.empty())
                interps = combos.interpolations;
            if (!combos.wm_maps.empty() && comb::has_wm_map(id, *param::parse_parameterization(r)))
                maps = combos.wm_maps;
            for (const std::string& i : interps) {
                for (const std::string& m : maps) {
                    SweepRun run;
                    run.case_name = c.name;
                    run.case_path = c.path;
                    run.formulation = f;
                    run.rotation = r;
                    run.interpolation = i;
                    run.wm_map = m;
                    runs.push_back(run);
                }
            }
        }
    }
    if (runs.empty())
        w.fail(c.node, "cases", "case " + c.name + " supports none of the combinations");
    return runs;
}

std::string run_label(const SweepRun& r, const std::vector<std::string>& keys) {
    std::string s = r.case_name + " " + r.formulation + "/" + r.rotation;
    for (const std::string& o : r.overrides(keys)) s += " " + o;
    return s;
}

}  // namespace

Sweep read_sweep_text(const std::string& text, const std::string& file,
                      const std::string& base_dir) {
    const Where w{file};
    const YAML::Node root = cases::parse_yaml_file(text, file, kSweepFile);
    expect_keys(w, root, "", {"name", "cases", "combinations", "parameters", "combine", "output"});
    Sweep sweep;
    sweep.file = file;
    if (!root["name"]) w.fail(root, "name", "missing required key");
    sweep.name = file_name_part(w, root["name"], "name");
    sweep.folder = "sweep-" + sweep.name;
    if (const YAML::Node c = root["combine"]) {
        const std::vector<std::string> choices = {"product", "zip"};
        sweep.zip = name_list(w, c, "combine", choices).front() == "zip";
        if (!c.IsScalar()) w.fail(c, "combine", "expected product or zip");
    }
    if (const YAML::Node o = root["output"]) {
        expect_keys(w, o, "output", {"folder", "steps"});
        if (o["folder"]) {
            sweep.folder = file_name_part(w, o["folder"], "output.folder");
        }
        if (o["steps"]) {
            if (!o["steps"].IsScalar()) w.fail(o["steps"], "output.steps", "expected last or all");
            sweep.all_steps =
                name_list(w, o["steps"], "output.steps", {"last", "all"}).front() == "all";
        }
    }
    const std::vector<CaseEntry> cases = read_cases(w, root, base_dir);
    const Combos combos = read_combinations(w, root);
    const std::vector<Axis> axes = read_parameters(w, root);
    for (const Axis& a : axes) sweep.keys.push_back(a.key);
    // The size is checked before anything is loaded: cases × formulations × rotations ×
    // interpolations × maps bounds the combinations.
    const long per_tuple =
        static_cast<long>(cases.size() * combos.formulations.size() * combos.rotations.size() *
                          std::max<size_t>(1, combos.interpolations.size()) *
                          std::max<size_t>(1, combos.wm_maps.size()));
    const std::vector<std::vector<std::string>> values =
        tuples(w, root, axes, sweep.zip, sweep.zip ? 1 : per_tuple);
    if (static_cast<long>(values.size()) * per_tuple > kMaxSweepRuns) {
        w.fail(root, "(file)",
               "the sweep expands to more than " + std::to_string(kMaxSweepRuns) +
                   " runs (the limit of a sweep; docs/sweeps.md)");
    }
    for (const CaseEntry& c : cases) {
        validate_values(w, c, axes);
        for (const SweepRun& combination : combinations_of(w, c, combos)) {
            for (const std::vector<std::string>& v : values) {
                SweepRun run = combination;
                run.values = v;
                std::vector<std::string> overrides = {
                    "discretization.formulation=" + run.formulation,
                    "discretization.rotation=" + run.rotation};
                const std::vector<std::string> more = run.overrides(sweep.keys);
                overrides.insert(overrides.end(), more.begin(), more.end());
                try {
                    run.modelled_seconds = modelled_seconds(load_case(run.case_path, overrides));
                } catch (const InputError& e) {
                    w.fail(root["parameters"] ? root["parameters"] : root, "parameters",
                           "run " + std::to_string(sweep.runs.size() + 1) + " (" +
                               run_label(run, sweep.keys) +
                               ") is refused by its case: " + loader_problem(e.what()));
                }
                sweep.runs.push_back(std::move(run));
            }
        }
    }
    return sweep;
}

Sweep read_sweep(const std::string& path) {
    std::error_code ec;
    if (fs::is_directory(path, ec))
        throw InputError(path + ": (file): is a directory, not a sweep file");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path + ": (file): cannot open the sweep file");
    std::string text;
    char chunk[16384];
    while (text.size() <= cases::kMaxFileBytes && in.read(chunk, sizeof chunk).gcount() > 0)
        text.append(chunk, static_cast<size_t>(in.gcount()));
    return read_sweep_text(text, path, fs::path(path).parent_path().string());
}

}  // namespace rotbeam::cli
