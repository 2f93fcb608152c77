// Case loader: constraints, point and distributed loads, time functions (docs/case-format.md).
#include <algorithm>
#include <cmath>

#include "cases/loader/model_builder.hpp"

namespace rotbeam::cases {

namespace {

std::vector<std::string> member_names(const Model& model) {
    std::vector<std::string> names;
    for (const Member& m : model.members) names.push_back(m.name);
    return names;
}

int member_index(const Model& model, const std::string& name) {
    for (size_t i = 0; i < model.members.size(); ++i) {
        if (model.members[i].name == name) return static_cast<int>(i);
    }
    return -1;
}

LoadFrame read_frame(const YamlReader& r, const YAML::Node& n, const std::string& key) {
    if (!n["frame"]) return LoadFrame::dead;
    return r.choice(n["frame"], key + ".frame", {"dead", "follower"}) == "follower"
               ? LoadFrame::follower
               : LoadFrame::dead;
}

void read_table(const YamlReader& r, const YAML::Node& n, const std::string& key, TimeFunction& f) {
    f.times = r.numbers(r.required(n, key, "times"), key + ".times");
    f.values = r.numbers(r.required(n, key, "values"), key + ".values");
    if (f.times.size() < 2) r.fail(n["times"], key + ".times", "a table needs at least 2 entries");
    if (f.times.size() != f.values.size()) {
        r.fail(n["values"], key + ".values",
               "has " + std::to_string(f.values.size()) + " entries but times has " +
                   std::to_string(f.times.size()));
    }
    for (size_t i = 1; i < f.times.size(); ++i) {
        if (!(f.times[i] > f.times[i - 1]))
            r.fail(n["times"], key + ".times", "must increase strictly");
    }
}

}  // namespace

TimeFunction read_time_function(const YamlReader& r, const YAML::Node& n, const std::string& key) {
    TimeFunction f;
    if (n.IsScalar()) {
        r.choice(n, key, {"constant"});  // the other kinds need parameters
        return f;
    }
    r.expect_map(
        n, key,
        {"type", "value", "start", "duration", "amplitude", "omega", "phase", "times", "values"});
    const std::string type =
        r.choice(r.required(n, key, "type"), key + ".type", {"constant", "ramp", "sine", "table"});
    const std::vector<std::pair<const char*, std::vector<std::string>>> owners = {
        {"value", {"constant", "ramp"}},
        {"start", {"ramp", "sine"}},
        {"duration", {"ramp"}},
        {"amplitude", {"sine"}},
        {"omega", {"sine"}},
        {"phase", {"sine"}},
        {"times", {"table"}},
        {"values", {"table"}}};
    for (const auto& [k, kinds] : owners) {
        if (n[k] && std::find(kinds.begin(), kinds.end(), type) == kinds.end()) {
            r.fail(n[k], child_key(key, k), "not a parameter of a " + type + " time function");
        }
    }
    if (n["value"]) f.value = r.number(n["value"], key + ".value");
    if (n["start"]) f.start = r.non_negative(n["start"], key + ".start");
    if (type == "ramp") {
        f.kind = TimeFunction::Kind::ramp;
        f.duration = r.positive(r.required(n, key, "duration"), key + ".duration");
    } else if (type == "sine") {
        f.kind = TimeFunction::Kind::sine;
        f.value = n["amplitude"] ? r.number(n["amplitude"], key + ".amplitude") : 1.0;
        f.omega = r.positive(r.required(n, key, "omega"), key + ".omega");
        if (n["phase"]) f.phase = r.number(n["phase"], key + ".phase");
    } else if (type == "table") {
        f.kind = TimeFunction::Kind::table;
        read_table(r, n, key, f);
    }
    return f;
}

void read_constraints(const YamlReader& r, const YAML::Node& root, Model& model) {
    const YAML::Node cs = root["constraints"];
    if (!cs) return;
    r.expect_named_map(cs, "constraints");
    for (const auto& item : cs) {
        const std::string key = "constraints." + item.first.Scalar();
        Constraint c;
        c.point = model.point_index(r.name_in(item.first, key, point_names(model), "point"));
        const YAML::Node& n = item.second;
        if (n.IsScalar()) {
            r.choice(n, key, {"clamped"});  // prescribed motion needs parameters
            model.constraints.push_back(c);
            continue;
        }
        r.expect_map(n, key, {"type", "displacement", "rotation", "time"});
        const std::string type =
            r.choice(r.required(n, key, "type"), key + ".type", {"clamped", "prescribed"});
        if (type == "clamped") {
            for (const char* k : {"displacement", "rotation", "time"}) {
                if (n[k]) r.fail(n[k], child_key(key, k), "only for type prescribed");
            }
        } else {
            c.kind = Constraint::Kind::prescribed;
            if (!n["displacement"] && !n["rotation"]) {
                r.fail(n, key + ".displacement", "missing required key (or rotation)");
            }
            if (n["displacement"])
                c.displacement = r.vec3(n["displacement"], key + ".displacement");
            if (n["rotation"]) c.rotation = r.vec3(n["rotation"], key + ".rotation");
            if (n["time"]) c.time = read_time_function(r, n["time"], key + ".time");
        }
        model.constraints.push_back(c);
    }
}

void read_loads(const YamlReader& r, const YAML::Node& root, Model& model) {
    const YAML::Node loads = root["loads"];
    if (!loads) return;
    r.expect_named_map(loads, "loads");
    for (const auto& item : loads) {
        const std::string key = "loads." + item.first.Scalar();
        const YAML::Node& n = item.second;
        r.expect_map(n, key, {"point", "member", "force", "moment", "frame", "time"});
        if (n["point"] && n["member"])
            r.fail(n["member"], key + ".member", "give point or member, not both");
        if (!n["point"] && !n["member"])
            r.fail(n, key + ".point", "missing required key (or member)");
        if (!n["force"] && !n["moment"])
            r.fail(n, key + ".force", "missing required key (or moment)");
        const Vec3 force = n["force"] ? r.vec3(n["force"], key + ".force") : Vec3::Zero();
        const Vec3 moment = n["moment"] ? r.vec3(n["moment"], key + ".moment") : Vec3::Zero();
        const LoadFrame frame = read_frame(r, n, key);
        const TimeFunction time =
            n["time"] ? read_time_function(r, n["time"], key + ".time") : TimeFunction{};
        if (n["point"]) {
            const std::string p =
                r.name_in(n["point"], key + ".point", point_names(model), "point");
            model.point_loads.push_back({model.point_index(p), force, moment, frame, time});
        } else {
            const std::string m =
                r.name_in(n["member"], key + ".member", member_names(model), "member");
            model.distributed_loads.push_back({member_index(model, m), force, moment, frame, time});
        }
    }
}

}  // namespace rotbeam::cases
