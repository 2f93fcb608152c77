#include "runs/beamdyn_frame.hpp"

#include <cmath>

namespace rotbeam {

namespace {

using json = nlohmann::json;

Vec3 vec3(const json& j) { return {j[0].get<double>(), j[1].get<double>(), j[2].get<double>()}; }

json to_json(const Vec3& v) { return json::array({v.x(), v.y(), v.z()}); }

json points_in(const Mat3& dcm, const json& points) {
    json out = json::object();
    for (const auto& [name, p] : points.items()) {
        out[name] = {{"TD", to_json(dcm * vec3(p["displacement"]))},
                     {"RD", to_json(wiener_milenkovic_of(dcm * vec3(p["rotation_vector"])))}};
    }
    return out;
}

json reactions_in(const Mat3& dcm, const json& reactions) {
    json out = json::object();
    for (const auto& [name, r] : reactions.items()) {
        out[name] = {{"F", to_json(dcm * vec3(r["force"]))},
                     {"M", to_json(dcm * vec3(r["moment"]))}};
    }
    return out;
}

}  // namespace

Vec3 wiener_milenkovic_of(const Vec3& psi) {
    const double phi = psi.norm();
    // 4 tan(φ/4)/φ → 1 + φ²/48: below 1e-8 the correction is under 1e-17, beneath round-off.
    if (phi < 1e-8) return psi;
    return (4.0 * std::tan(phi / 4.0) / phi) * psi;
}

void add_beamdyn_frame(const Mat3& root_dcm, nlohmann::json& result) {
    json dcm = json::array();
    for (int r = 0; r < 3; ++r) dcm.push_back(to_json(root_dcm.row(r).transpose()));
    result["beamdyn_frame"] = {{"dcm", dcm}};
    if (!result.contains("steps")) return;
    for (json& step : result["steps"]) {
        const json& from = step.contains("rotating_frame") ? step["rotating_frame"] : step;
        json b = {{"points", points_in(root_dcm, from["points"])}};
        if (from.contains("reactions")) b["reactions"] = reactions_in(root_dcm, from["reactions"]);
        step["beamdyn"] = std::move(b);
    }
}

bool has_beamdyn_columns(const nlohmann::json& result) {
    return result.contains("beamdyn_frame") && !result["steps"].empty() &&
           result["steps"][0].contains("beamdyn");
}

void write_beamdyn_header(const nlohmann::json& result, std::ostream& os) {
    const json& b = result["steps"][0]["beamdyn"];
    for (const auto& [name, point] : b["points"].items()) {
        for (const char* c : {"TDxr", "TDyr", "TDzr", "RDxr", "RDyr", "RDzr"}) {
            os << "," << name << "_" << c;
        }
    }
    if (!b.contains("reactions")) return;
    for (const auto& [name, reaction] : b["reactions"].items()) {
        for (const char* c : {"Fxr", "Fyr", "Fzr", "Mxr", "Myr", "Mzr"}) {
            os << "," << name << "_" << c;
        }
    }
}

void write_beamdyn_row(const nlohmann::json& step, std::ostream& os) {
    const json& b = step["beamdyn"];
    const auto put = [&os](const json& v) {
        for (int i = 0; i < 3; ++i) os << "," << v[static_cast<std::size_t>(i)].get<double>();
    };
    for (const auto& [name, point] : b["points"].items()) {
        put(point["TD"]);
        put(point["RD"]);
    }
    if (!b.contains("reactions")) return;
    for (const auto& [name, reaction] : b["reactions"].items()) {
        put(reaction["F"]);
        put(reaction["M"]);
    }
}

}  // namespace rotbeam
