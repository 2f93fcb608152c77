#include "cases/loader/case_loader.hpp"

#include <yaml-cpp/depthguard.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string_view>

#include "cases/loader/beamdyn_import.hpp"
#include "cases/loader/deck_case.hpp"
#include "cases/loader/file_name_part.hpp"
#include "cases/loader/limits.hpp"
#include "cases/loader/model_builder.hpp"
#include "cases/loader/yaml_file.hpp"
#include "combinations/registry.hpp"
#include "core/errors.hpp"

namespace rotbeam {

namespace {

using cases::YamlReader;

[[noreturn]] void override_error(const std::string& file, const std::string& path,
                                 const std::string& problem) {
    throw InputError(
        cases::one_line(file + ":--set: " + (path.empty() ? "(set)" : path) + ": " + problem));
}

// The child of `node` named by one path segment: a key of a mapping (created when missing) or
// an index into a list.
YAML::Node descend(YAML::Node& node, const std::string& segment, const std::string& reached,
                   const std::string& file) {
    YAML::Node next;
    if (node.IsSequence()) {
        size_t index = 0;
        try {
            index = std::stoul(segment);
        } catch (const std::exception&) {
            override_error(file, reached, "indexes a list: use a number");
        }
        if (index >= node.size()) override_error(file, reached, "is past the end of the list");
        next.reset(node[index]);
    } else if (node.IsMap() || node.IsNull()) {
        next.reset(node[segment]);
    } else {
        override_error(file, reached, "cannot set a key inside a value");
    }
    return next;
}

// The value of an override, parsed as YAML after the checks a file gets (text, shape).
YAML::Node override_value(const std::string& value_text, const std::string& path,
                          const std::string& file) {
    if (const size_t at = cases::first_non_text_byte(value_text); at != std::string::npos) {
        override_error(file, path,
                       "the value holds a control character or a byte that is not UTF-8 (byte " +
                           std::to_string(at) + ")");
    }
    try {
        cases::check_yaml_shape(value_text, "");
        const YAML::Node value = YAML::Load(value_text);
        cases::check_one_document(value_text, value, "", "--set value");
        return value;
    } catch (const YAML::Exception& e) {
        override_error(file, path, "the value is not valid YAML (" + e.msg + ")");
    } catch (const InputError& e) {
        // `:LINE: (file|yaml): problem` of a one-line value: the problem alone.
        const std::string m = e.what();
        override_error(file, path, "the value: " + m.substr(m.find("): ") + 3));
    }
}

// Applies `key.path=value` to the tree: map segments are created when missing, list segments
// are indices, and a `*` segment stands for every key of a mapping that exists
// (`members.*.elements=8`). The value is YAML (`[0.4, 2]` is a list). Returns the key paths set.
std::vector<std::string> apply_override(YAML::Node& root, const std::string& text,
                                        const std::string& file) {
    const size_t eq = text.find('=');
    const std::string path = eq == std::string::npos ? text : text.substr(0, eq);
    if (eq == std::string::npos || path.empty()) {
        override_error(file, path, "expected key.path=value, got '" + text + "'");
    }
    std::vector<std::string> segments;
    std::stringstream ss(path);
    for (std::string s; std::getline(ss, s, '.');) {
        if (s.empty()) override_error(file, path, "empty segment in the key path");
        segments.push_back(s);
    }
    if (path.back() == '.') override_error(file, path, "empty segment in the key path");
    const YAML::Node value = override_value(text.substr(eq + 1), path, file);
    if (value.IsNull()) override_error(file, path, "missing value after '='");
    YAML::Node node = root;
    std::string reached;
    for (size_t i = 0; i + 1 < segments.size(); ++i) {
        if (segments[i] == "*") {
            if (!node.IsMap() || node.size() == 0) {
                override_error(file, path, "'*' must stand for the keys of an existing mapping");
            }
            std::vector<std::string> keys, set;
            for (const auto& item : node) keys.push_back(item.first.Scalar());
            for (const std::string& key : keys) {
                std::string concrete = reached.empty() ? "" : reached + ".";
                concrete += key;
                for (size_t j = i + 1; j < segments.size(); ++j) concrete += "." + segments[j];
                for (const std::string& p : apply_override(root, concrete + text.substr(eq), file))
                    set.push_back(p);
            }
            return set;
        }
        node.reset(descend(node, segments[i], reached, file));
        reached = cases::child_key(reached, segments[i]);
    }
    if (segments.back() == "*") override_error(file, path, "'*' cannot be the last segment");
    if (node.IsScalar()) override_error(file, path, "cannot set a key inside a value");
    if (node.IsSequence()) {
        YAML::Node item = descend(node, segments.back(), path, file);
        item = value;
    } else {
        node[segments.back()] = value;
    }
    return {path};
}

// Every connected part of the structure (members joined at shared points) holds a constrained
// point. A part that holds none moves as a rigid body: its static tangent is singular, and a modal
// analysis would report its rigid-body modes, whose ω² is round-off, as frequencies of 1e-5 Hz.
// (A dynamic analysis may let a part fly free: its inertia keeps the step's matrix regular.)
void check_every_part_held(const YamlReader& r, const YAML::Node& root, const Model& model) {
    std::vector<int> part(model.points.size());
    for (size_t i = 0; i < part.size(); ++i) part[i] = static_cast<int>(i);
    const auto find = [&](int p) {
        while (part[static_cast<size_t>(p)] != p) p = part[static_cast<size_t>(p)];
        return p;
    };
    for (const Member& m : model.members)
        part[static_cast<size_t>(find(m.start_point))] = find(m.end_point);
    std::vector<bool> held(part.size(), false);
    for (const Constraint& c : model.constraints) held[static_cast<size_t>(find(c.point))] = true;
    for (const Member& m : model.members) {
        if (held[static_cast<size_t>(find(m.start_point))]) continue;
        r.fail(root["members"], "members." + m.name,
               "is not joined to any constrained point: its part of the structure moves as a rigid "
               "body (singular in a static analysis; zero-frequency modes in a modal one)");
    }
}

// Every point is an end of some member (a point nothing attaches to cannot carry a load or a
// constraint), and a static analysis needs a constraint (else rigid-body motion is singular).
void check_topology(const YamlReader& r, const YAML::Node& root, const Model& model) {
    for (size_t i = 0; i < model.points.size(); ++i) {
        const bool used =
            std::any_of(model.members.begin(), model.members.end(), [&](const Member& m) {
                return m.start_point == static_cast<int>(i) || m.end_point == static_cast<int>(i);
            });
        if (!used) {
            r.fail(root["points"], "points." + model.points[i].name, "is not an end of any member");
        }
    }
    if (model.analysis.kind == AnalysisKind::static_ && model.constraints.empty()) {
        r.fail(root["analysis"], "constraints",
               "missing: a static analysis needs at least one constraint (rigid-body motion)");
    }
    if (model.analysis.kind != AnalysisKind::dynamic) check_every_part_held(r, root, model);
}

// The memory the run would need (limits.hpp), against the machine's: the member with the most
// elements is named, as the usual cause.
void check_memory(const YamlReader& r, const YAML::Node& root, const Model& model) {
    const cases::MemoryEstimate e = cases::estimate_memory(model);
    const double available = cases::physical_memory_bytes();
    if (available <= 0.0 || e.bytes <= available) return;
    const auto largest =
        std::max_element(model.members.begin(), model.members.end(),
                         [](const Member& a, const Member& b) { return a.elements < b.elements; });
    r.fail(root, "members." + largest->name + ".elements",
           "the run would need an estimated " + cases::memory_text(e.bytes) + " of memory (" +
               std::to_string(e.unknowns) + " unknowns; mostly " + e.dominant +
               "), more than this machine's " + cases::memory_text(available) +
               "; use fewer elements or a lower order");
}

// The integrator a dynamic case names must be one its formulation takes
// (combinations/registry.hpp).
void check_integrator(const YamlReader& r, const YAML::Node& root, const Model& model) {
    const Formulation f = model.discretization.formulation;
    const Integrator asked = model.analysis.dynamics.integrator;
    if (model.analysis.kind != AnalysisKind::dynamic) return;
    if (!comb::takes_integrator(f, asked)) {
        r.fail(root["analysis"]["integrator"], "analysis.integrator",
               "the " + std::string(choice_name(f)) + " formulation integrates with " +
                   comb::integrator_names(f) + ", not '" + std::string(choice_name(asked)) + "'");
    }
}

// The displacement formulation's `midpoint` mass rule samples the inertia at one point per
// element: its element mass has rank 6 while an element of order p couples 6(p + 1) unknowns, so
// for p ≥ 2 the assembled mass is singular (an infinite eigenvalue per missing rank; the dense
// Cholesky-based solver then turns round-off into frequencies of any size). Refused here rather
// than replaced: the mass rule changes the frequencies at the level of the discretization error,
// and the user asked for this one (docs/displacement-modal.md, "Mass rule").
void check_mass_rule(const YamlReader& r, const YAML::Node& root, const Model& model) {
    const Discretization& d = model.discretization;
    if (!model.needs_inertia() || d.formulation != Formulation::displacement ||
        d.displacement.mass_rule != MassRule::midpoint || d.order < 2) {
        return;
    }
    r.fail(root["discretization"]["mass_rule"], "discretization.mass_rule",
           "'midpoint' (one mass point per element) gives a singular mass matrix for order " +
               std::to_string(d.order) +
               " elements (order 1 only); use consistent | lumped "
               "(e.g. --set discretization.mass_rule=consistent)");
}

// rotating_frame: {angular_velocity: [Ωx, Ωy, Ωz], center: [x, y, z]} (core/model.hpp,
// docs/rotating-frame.md). The rotation is
// modelled in statics and dynamics (turning supports) of both formulations and in the displacement
// formulation's modal analysis; the mixed modal analysis refuses it here.
void read_rotating_frame(const YamlReader& r, const YAML::Node& root, Model& model) {
    const YAML::Node n = root["rotating_frame"];
    if (!n) return;
    r.expect_map(n, "rotating_frame", {"angular_velocity", "center"});
    if (!n["angular_velocity"])
        r.fail(n, "rotating_frame.angular_velocity", "missing required key");
    RotatingFrame& f = model.rotating_frame;
    f.angular_velocity = r.vec3(n["angular_velocity"], "rotating_frame.angular_velocity");
    if (n["center"]) f.center = r.vec3(n["center"], "rotating_frame.center");
    if (!f.active()) return;
}

// The case's name (else its file's stem) names the run's output files (file_name_part.hpp).
void read_case_name(const YamlReader& r, const YAML::Node& root, const std::string& file,
                    Model& model) {
    if (const YAML::Node n = root["name"]) {
        model.name = r.string(n, "name");
        const std::string problem = cases::file_name_part_problem(model.name);
        if (!problem.empty()) r.fail(n, "name", problem + "; the case name names its output files");
        return;
    }
    model.name = std::filesystem::path(file).stem().string();
    const std::string problem = cases::file_name_part_problem(model.name);
    if (!problem.empty()) {
        r.fail(root, "name",
               "missing, so the case is named after its file, but " + problem +
                   "; the case name names its output files: give one (name: ...)");
    }
}

Model build(const YamlReader& r, const YAML::Node& root, const std::string& file) {
    r.expect_map(root, "",
                 {"name", "description", "units", "points", "sections", "members", "constraints",
                  "loads", "gravity", "rotating_frame", "analysis", "discretization", "solver",
                  "references", "expected_stops"});
    Model model;
    read_case_name(r, root, file, model);
    if (root["description"]) model.description = r.string(root["description"], "description");
    if (root["units"]) model.units = r.string(root["units"], "units");
    cases::read_points(r, root, model);
    const cases::SectionTable sections = cases::read_sections(r, root);
    cases::read_members(r, root, sections, model);
    cases::check_distinct_points(r, root, model);
    cases::read_constraints(r, root, model);
    cases::read_loads(r, root, model);
    if (root["gravity"]) model.gravity = r.vec3(root["gravity"], "gravity");
    cases::read_analysis(r, root, model);
    cases::read_discretization(r, root, model);
    read_rotating_frame(r, root, model);
    cases::read_solver(r, root, model);
    cases::read_references(r, root, model);
    check_topology(r, root, model);
    check_mass_rule(r, root, model);
    check_integrator(r, root, model);
    // Inertia is needed by dynamics, modal analysis and gravity: every section must have mass.
    if (model.needs_inertia() || model.gravity.norm() > 0.0 || model.rotating_frame.active()) {
        for (const Member& m : model.members) {
            for (const SectionStation& st : m.sections) {
                if (st.section.mass) continue;
                for (const auto& item : root["sections"]) {  // report the line of the name
                    if (item.first.Scalar() != st.section.name) continue;
                    r.fail(item.first, "sections." + st.section.name,
                           "needs mass or density (the analysis, gravity or the rotating frame "
                           "uses inertia)");
                }
            }
        }
    }
    check_memory(r, root, model);
    return model;
}

}  // namespace

Model load_case_text(const std::string& text, const std::string& file_name,
                     const std::vector<std::string>& overrides) {
    YAML::Node root = cases::parse_yaml_file(text, file_name, cases::kCaseFile);
    std::set<std::string> overridden;
    for (const std::string& o : overrides) {
        for (const std::string& p : apply_override(root, o, file_name)) overridden.insert(p);
    }
    YamlReader reader(file_name, overridden);
    reader.index_lines(root);
    try {
        return build(reader, root, file_name);
    } catch (const YAML::Exception& e) {
        // Defensive: every access is type-checked, but yaml-cpp must never escape as a crash.
        throw InputError(file_name + ":" + std::to_string(e.mark.line + 1) +
                         ": (yaml): " + cases::one_line(e.msg));
    }
}

std::filesystem::path published_references_path(const std::string& case_path) {
    const std::filesystem::path p(case_path);
    return p.parent_path() / "references" / (p.stem().string() + ".yaml");
}

namespace {

std::string read_text_file(const std::string& path, const char* what) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) {
        throw InputError(path + ": (file): is a directory, not a " + what);
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path + ": (file): cannot open the " + std::string(what));
    // Read in chunks, stopping one chunk past the limit (a device or a pipe has no size to ask
    // for, and a case file is a few kB: no megabyte buffer for each).
    std::string text;
    char chunk[16384];
    while (text.size() <= cases::kMaxFileBytes && in.read(chunk, sizeof chunk).gcount() > 0) {
        text.append(chunk, static_cast<size_t>(in.gcount()));
    }
    if (text.size() > cases::kMaxFileBytes) {
        throw InputError(path + ":1: (file): larger than " + std::to_string(cases::kMaxFileBytes) +
                         " bytes (a limit of the case format)");
    }
    return text;
}

bool sets_references(const std::string& override_text) {
    for (const char* block : {"references", "expected_stops"}) {
        const std::string b(block);
        if (override_text.rfind(b + ".", 0) == 0 || override_text.rfind(b + "=", 0) == 0)
            return true;
    }
    return false;
}

// The published references file (a mapping with the one key `references`, the same block a case
// may hold) read into `model`, whose analysis its entries are checked against; `--set
// references...` overrides apply to it. A case with a block of its own and such a file is refused:
// one place for the numbers.
void read_published_references(const std::string& file, const std::vector<std::string>& overrides,
                               const std::string& case_file, Model& model) {
    YAML::Node root =
        cases::parse_yaml_file(read_text_file(file, "references file"), file, cases::kCaseFile);
    // Every overridden key counts, the case's too: an entry's load factor need not be one of
    // `analysis.load_factors` once --set replaced them (settings.cpp, read_reference).
    std::set<std::string> overridden;
    for (const std::string& o : overrides) {
        if (sets_references(o)) {
            for (const std::string& p : apply_override(root, o, case_file)) overridden.insert(p);
        } else {
            overridden.insert(o.substr(0, o.find('=')));
        }
    }
    YamlReader reader(file, overridden);
    reader.index_lines(root);
    reader.expect_map(root, "", {"references", "expected_stops"});
    if (!model.references.empty() || !model.expected_stops.empty()) {
        const char* block = root["references"] ? "references" : "expected_stops";
        reader.fail(root[block], block,
                    "the case " + case_file + " has a references block of its own; keep one");
    }
    try {
        cases::read_references(reader, root, model);
    } catch (const YAML::Exception& e) {
        throw InputError(file + ":" + std::to_string(e.mark.line + 1) +
                         ": (yaml): " + cases::one_line(e.msg));
    }
}

}  // namespace

Model load_case(const std::string& path, const std::vector<std::string>& overrides,
                CaseParts parts) {
    // A BeamDyn driver file is imported into the case text it stands for (docs/beamdyn-import.md).
    if (cases::is_beamdyn_driver_path(path)) {
        return load_case_text(cases::import_beamdyn(path), path + " (imported)", overrides);
    }
    std::string text = read_text_file(path, "case file");
    std::string file_name = path;
    std::vector<std::string> all = overrides;
    // A catalog entry that is a BeamDyn deck: the import, then the entry's overrides and the
    // user's (cases/loader/deck_case.hpp); its published references beside it like any case's.
    if (const std::optional<cases::DeckCase> deck = cases::read_deck_case(text, path)) {
        text = cases::import_beamdyn(deck->driver);
        file_name = path + " (" + deck->driver + ", imported)";
        all = deck->overrides;
        all.insert(all.end(), overrides.begin(), overrides.end());
    }
    const std::filesystem::path published = published_references_path(path);
    std::vector<std::string> case_overrides;
    bool sets_a_reference = false;
    for (const std::string& o : all) {
        if (sets_references(o)) {
            sets_a_reference = true;
        } else {
            case_overrides.push_back(o);
        }
    }
    // An override of a published reference reads that file even for `case_file`, so that it is
    // validated where it applies instead of creating a partial block in the case.
    std::error_code ec;
    if ((parts == CaseParts::case_file && !sets_a_reference) ||
        !std::filesystem::is_regular_file(published, ec)) {
        return load_case_text(text, file_name, all);
    }
    Model model = load_case_text(text, file_name, case_overrides);
    read_published_references(published.string(), all, path, model);
    return model;
}

}  // namespace rotbeam
