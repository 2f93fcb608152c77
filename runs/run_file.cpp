#include "runs/run_file.hpp"

#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <vector>

#include "core/errors.hpp"
#include "core/results.hpp"

namespace rotbeam {

namespace {

using json = nlohmann::json;

// What a value at a path must be.
enum class Shape {
    object,
    array,
    text,
    boolean,
    count,
    number,
    vector3,
    matrix3,
    numbers,
    station
};

// The type of a value, by its path: object keys by name, `*` for any key not named at that place,
// `[]` for any array element. Every key a reader of the file uses (reports/, estimates/
// accuracy_scale.cpp, distribution/sweep_table.cpp, the merge), with the shape it reads it as.
struct TypeRule {
    std::string path;
    Shape shape;
};

// Keys an object at `at` must have: one of `one_of`, or, with `when`, only when it has `when`.
struct NeedRule {
    std::string at;
    const char* when;
    std::vector<const char*> one_of;
};

struct Schema {
    std::map<std::string, Shape> types;
    std::set<std::string> prefixes;  // every path of `types` and each of its ancestors
    std::vector<NeedRule> needs;
};

// An estimated quantity (estimates/estimate.hpp): its error, whether it is reliable, why not.
void add_quantity(std::vector<TypeRule>& types, std::vector<NeedRule>& needs,
                  const std::string& at) {
    types.push_back({at, Shape::object});
    types.push_back({at + ".error", Shape::number});
    types.push_back({at + ".reliable", Shape::boolean});
    types.push_back({at + ".observed_order", Shape::number});
    types.push_back({at + ".reason", Shape::text});
    needs.push_back({at, nullptr, {"error"}});
    needs.push_back({at, nullptr, {"reliable"}});
}

// A run's result (core/results.hpp, docs/json-schema.md).
std::vector<TypeRule> case_run_types(std::vector<NeedRule>& needs) {
    std::vector<TypeRule> t = {
        {"schema_version", Shape::count},
        {"version", Shape::text},
        {"input_key", Shape::text},
        {"case", Shape::text},
        {"rotation", Shape::text},
        {"formulation", Shape::text},
        {"status", Shape::text},
        {"message", Shape::text},
        {"wall_seconds", Shape::number},
        {"elements", Shape::count},
        {"order", Shape::count},
        {"dofs", Shape::count},
        {"elements_per_member", Shape::object},
        {"elements_per_member.*", Shape::count},
        {"options", Shape::object},
        {"options.quadrature", Shape::text},
        {"options.mass_rule", Shape::text},
        {"options.interpolation", Shape::text},
        {"options.wm_map", Shape::text},
        {"frequencies_hz", Shape::numbers},
        {"modes", Shape::array},
        {"modes[]", Shape::object},
        {"modes[].frequency_hz", Shape::number},
        {"modes[].estimate", Shape::object},
        {"estimate", Shape::object},
        {"estimate.status", Shape::text},
        {"estimate.history", Shape::object},
        {"estimate.history.*", Shape::object},
        {"estimate.history.*.*", Shape::object},
        {"estimate.history.*.*.relative", Shape::number},
        {"steps", Shape::array},
        {"steps[]", Shape::object},
        {"steps[].load_factor", Shape::number},
        {"steps[].time", Shape::number},
        {"steps[].newton_iterations", Shape::count},
        {"steps[].points", Shape::object},
        {"steps[].points.*", Shape::object},
        {"steps[].points.*.displacement", Shape::vector3},
        {"steps[].points.*.rotation_vector", Shape::vector3},
        {"steps[].points.*.rotation_matrix", Shape::matrix3},
        {"steps[].points.*.rotation_angle", Shape::number},
        {"steps[].points.*.reaction_force", Shape::vector3},
        {"steps[].points.*.reaction_moment", Shape::vector3},
        {"steps[].reactions", Shape::object},
        {"steps[].reactions.*", Shape::object},
        {"steps[].reactions.*.force", Shape::vector3},
        {"steps[].reactions.*.moment", Shape::vector3},
        {"steps[].centerline", Shape::array},
        {"steps[].centerline[]", Shape::station},
        {"steps[].estimate", Shape::object},
        {"steps[].estimate.status", Shape::text},
        {"steps[].estimate.reason", Shape::text},
        {"steps[].estimate.*", Shape::object},
    };
    add_quantity(t, needs, "steps[].estimate.*.displacement");
    add_quantity(t, needs, "steps[].estimate.*.rotation");
    add_quantity(t, needs, "modes[].estimate.frequency");
    for (const char* key : {"schema_version", "input_key", "case", "rotation", "formulation",
                            "status", "message", "wall_seconds", "steps"}) {
        needs.push_back({"", nullptr, {key}});
    }
    // Table III reads a modal run's mesh and options.
    needs.push_back({"", "frequencies_hz", {"options"}});
    needs.push_back({"", "frequencies_hz", {"elements_per_member"}});
    needs.push_back({"modes[]", nullptr, {"frequency_hz"}});
    needs.push_back({"steps[]", nullptr, {"load_factor", "time"}});
    needs.push_back({"steps[]", nullptr, {"points"}});
    needs.push_back({"steps[].points.*", nullptr, {"displacement"}});
    needs.push_back({"steps[].points.*", nullptr, {"rotation_vector"}});
    needs.push_back({"steps[].reactions.*", nullptr, {"force"}});
    needs.push_back({"steps[].reactions.*", nullptr, {"moment"}});
    needs.push_back({"steps[].estimate.*", nullptr, {"displacement"}});
    needs.push_back({"steps[].estimate.*", nullptr, {"rotation"}});
    needs.push_back({"steps[].points.*", "reaction_force", {"reaction_moment"}});
    return t;
}

// One run of a split study (distribution/distributed.cpp, make_unit): the result is what the
// study's own combine step reads.
std::vector<TypeRule> study_run_types(std::vector<NeedRule>& needs) {
    for (const char* key : {"study", "key", "input_key", "seconds", "result"})
        needs.push_back({"", nullptr, {key}});
    return {{"study", Shape::text},
            {"key", Shape::text},
            {"input_key", Shape::text},
            {"seconds", Shape::number},
            {"result", Shape::object}};
}

// A study made whole in a shard folder: the list of the files it wrote.
std::vector<TypeRule> whole_study_types(std::vector<NeedRule>& needs) {
    for (const char* key : {"study", "input_key", "seconds", "files"})
        needs.push_back({"", nullptr, {key}});
    return {{"study", Shape::text},
            {"input_key", Shape::text},
            {"seconds", Shape::number},
            {"files", Shape::array},
            {"files[]", Shape::text}};
}

Schema make_schema(RunFileKind kind) {
    Schema s;
    std::vector<TypeRule> types;
    switch (kind) {
        case RunFileKind::case_run:
            types = case_run_types(s.needs);
            break;
        case RunFileKind::study_run:
            types = study_run_types(s.needs);
            break;
        case RunFileKind::whole_study:
            types = whole_study_types(s.needs);
            break;
    }
    for (const TypeRule& r : types) {
        s.types[r.path] = r.shape;
        const std::string& p = r.path;
        s.prefixes.insert(p);
        for (size_t cut = p.find_last_of(".["); cut != std::string::npos && cut > 0;
             cut = p.find_last_of(".[", cut - 1)) {
            s.prefixes.insert(p.substr(0, cut));
        }
    }
    return s;
}

const Schema& schema_of(RunFileKind kind) {
    static const Schema kCase = make_schema(RunFileKind::case_run);
    static const Schema kStudyRun = make_schema(RunFileKind::study_run);
    static const Schema kWholeStudy = make_schema(RunFileKind::whole_study);
    switch (kind) {
        case RunFileKind::case_run:
            return kCase;
        case RunFileKind::study_run:
            return kStudyRun;
        case RunFileKind::whole_study:
            return kWholeStudy;
    }
    return kCase;
}

// A key as the JSON path shows it: bare when it is a plain name, else quoted with JSON escapes,
// so that the message stays one line whatever the key holds.
std::string path_key(const std::string& parent, const std::string& key) {
    const bool plain = !key.empty() && key.find_first_not_of(
                                           "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                           "0123456789_-") == std::string::npos;
    if (!plain) return parent + "[" + json(key).dump() + "]";
    return parent.empty() ? key : parent + "." + key;
}

std::string what_it_is(const json& v) {
    if (v.is_number_float() && !std::isfinite(v.get<double>())) return "a number beyond the range";
    if (v.is_number()) return "the number " + v.dump();
    return std::string("a") + (v.is_array() || v.is_object() ? "n " : " ") + v.type_name();
}

struct Walker {
    const Schema& schema;
    const std::string& file;

    [[noreturn]] void refuse(const std::string& where, const std::string& problem) const {
        throw InputError(file + ": " + (where.empty() ? "(top level)" : where) + ": " + problem);
    }

    void expect_numbers(const json& v, const std::string& where, size_t least, size_t most,
                        const char* what) const {
        if (!v.is_array() || v.size() < least || v.size() > most)
            refuse(where, std::string("expected ") + what + ", found " + what_it_is(v));
        for (size_t i = 0; i < v.size(); ++i) {
            if (!v[i].is_number() || !std::isfinite(v[i].get<double>())) {
                refuse(where + "[" + std::to_string(i) + "]",
                       "expected a finite number, found " + what_it_is(v[i]));
            }
        }
    }

    void expect(const json& v, Shape shape, const std::string& where) const {
        const auto wrong = [&](const char* expected) {
            refuse(where, std::string("expected ") + expected + ", found " + what_it_is(v));
        };
        switch (shape) {
            case Shape::object:
                if (!v.is_object()) wrong("an object");
                break;
            case Shape::array:
                if (!v.is_array()) wrong("an array");
                break;
            case Shape::text:
                if (!v.is_string()) wrong("a string");
                break;
            case Shape::boolean:
                if (!v.is_boolean()) wrong("true or false");
                break;
            case Shape::count:
                if (!v.is_number_unsigned() && !(v.is_number_integer() && v.get<int64_t>() >= 0))
                    wrong("a whole number ≥ 0");
                break;
            case Shape::number:
                if (!v.is_number() || !std::isfinite(v.get<double>())) wrong("a finite number");
                break;
            case Shape::vector3:
                expect_numbers(v, where, 3, 3, "3 numbers");
                break;
            case Shape::numbers:
                expect_numbers(v, where, 0, v.size(), "an array of numbers");
                break;
            case Shape::station:
                expect_numbers(v, where, 4, 4, "4 numbers (s, x, y, z)");
                break;
            case Shape::matrix3:
                if (!v.is_array() || v.size() != 3) wrong("3 rows of 3 numbers");
                for (size_t r = 0; r < 3; ++r)
                    expect_numbers(v[r], where + "[" + std::to_string(r) + "]", 3, 3, "3 numbers");
                break;
        }
    }

    void needs(const json& v, const std::string& rule_path, const std::string& where) const {
        for (const NeedRule& n : schema.needs) {
            if (rule_path != n.at || (n.when && !v.contains(n.when))) continue;
            bool found = false;
            for (const char* key : n.one_of) found = found || v.contains(key);
            if (found) continue;
            std::string problem = "missing";
            if (n.one_of.size() > 1) {
                problem += " (";
                for (size_t i = 1; i < n.one_of.size(); ++i)
                    problem += std::string(i > 1 ? ", " : "") + "nor " + n.one_of[i];
                problem += ")";
            }
            if (n.when) problem += std::string(" (required with ") + n.when + ")";
            refuse(path_key(where, n.one_of.front()), problem);
        }
    }

    // `rule_path`: the node's path in the schema's terms, empty when no rule reaches it.
    void walk(const json& v, const std::string& rule_path, bool ruled, const std::string& where,
              int depth) const {
        if (depth > kMaxRunFileDepth)
            refuse(where, "nested deeper than " + std::to_string(kMaxRunFileDepth) + " levels");
        if (ruled) {
            const auto rule = schema.types.find(rule_path);
            if (rule != schema.types.end()) expect(v, rule->second, where);
        }
        if (v.is_number_float() && !std::isfinite(v.get<double>()))
            refuse(where, "expected a finite number, found " + what_it_is(v));
        if (v.is_object()) {
            if (ruled) needs(v, rule_path, where);
            for (const auto& [key, child] : v.items()) {
                std::string next = rule_path.empty() ? key : rule_path + "." + key;
                bool next_ruled = ruled && schema.prefixes.count(next);
                if (ruled && !next_ruled) {
                    next = rule_path.empty() ? "*" : rule_path + ".*";
                    next_ruled = schema.prefixes.count(next) > 0;
                }
                walk(child, next, next_ruled, path_key(where, key), depth + 1);
            }
        } else if (v.is_array()) {
            const std::string next = rule_path + "[]";
            const bool next_ruled = ruled && schema.prefixes.count(next);
            for (size_t i = 0; i < v.size(); ++i)
                walk(v[i], next, next_ruled, where + "[" + std::to_string(i) + "]", depth + 1);
        }
    }
};

}  // namespace

std::optional<json> parse_run_file(const std::string& text, const std::string& file,
                                   RunFileKind kind, const std::optional<std::string>& input_key) {
    json j;
    try {
        j = json::parse(text);
    } catch (const json::parse_error& e) {
        throw InputError(file + ": not complete JSON (" + e.what() + ")");
    } catch (const json::exception& e) {
        throw InputError(file + ": not valid JSON (" + e.what() + ")");  // e.g. 1e999
    }
    const Walker walker{schema_of(kind), file};
    if (!j.is_object()) walker.refuse("", "expected a JSON object, found " + what_it_is(j));
    const auto key = j.find("input_key");
    if (key == j.end()) walker.refuse("input_key", "missing");
    if (!key->is_string())
        walker.refuse("input_key", "expected a string, found " + what_it_is(*key));
    if (input_key && key->get<std::string>() != *input_key) return std::nullopt;
    // Checked before the fields: a file of another schema fails on its version, not on a field
    // that version names differently.
    const auto version = j.find("schema_version");
    if (kind == RunFileKind::case_run && version != j.end() && version->is_number() &&
        *version != kSchemaVersion) {
        walker.refuse("schema_version", what_it_is(*version) + ", this rotbeam reads " +
                                            std::to_string(kSchemaVersion));
    }
    walker.walk(j, "", true, "", 0);
    return j;
}

std::optional<json> read_run_file(const std::string& file, RunFileKind kind,
                                  const std::optional<std::string>& input_key) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw InputError(file + ": cannot be read");
    std::ostringstream text;
    text << in.rdbuf();
    return parse_run_file(text.str(), file, kind, input_key);
}

}  // namespace rotbeam
