#include "estimate_columns.hpp"

#include <string>
#include <vector>

namespace rotbeam {

namespace {

bool dynamic(const nlohmann::json& result) { return result["estimate"].contains("time_method"); }

// "_<method>" with a comma made '+' (CSV-safe).
std::string suffix(const nlohmann::json& method) {
    std::string s(1, '_');
    for (const char c : method.get<std::string>()) s.push_back(c == ',' ? '+' : c);
    return s;
}

// The (suffix, path in the quantity's estimate) of each column of one quantity.
struct Column {
    std::string suffix;
    std::vector<std::string> path;
};

std::vector<Column> columns(const nlohmann::json& result) {
    const nlohmann::json& e = result["estimate"];
    if (!dynamic(result)) return {{suffix(e["method"]), {"error"}}};
    return {{suffix(e["space_method"]), {"space", "error"}},
            {suffix(e["time_method"]), {"time", "error"}},
            {"", {"error"}}};
}

constexpr std::pair<const char*, const char*> kQuantities[] = {{"displacement", "u_err"},
                                                               {"rotation", "angle_err"}};

}  // namespace

bool has_estimate_columns(const nlohmann::json& result) {
    if (!result.contains("estimate") || result["steps"].empty()) return false;
    const std::string status = result["estimate"].value("status", std::string());
    return status == "estimated" || status == "partial";
}

void write_estimate_header(const nlohmann::json& result, std::ostream& os) {
    const std::vector<Column> cs = columns(result);
    for (const auto& [name, point] : result["steps"][0]["points"].items()) {
        for (const auto& [quantity, label] : kQuantities) {
            const char* unit = std::string(quantity) == "rotation" ? "[rad]" : "[length]";
            for (const Column& c : cs) os << "," << name << "_" << label << c.suffix << unit;
        }
    }
}

void write_estimate_row(const nlohmann::json& result, const nlohmann::json& step,
                        std::ostream& os) {
    const std::vector<Column> cs = columns(result);
    const nlohmann::json none = nlohmann::json::object();
    const nlohmann::json& e = step.contains("estimate") ? step["estimate"] : none;
    for (const auto& [name, point] : result["steps"][0]["points"].items()) {
        for (const auto& [quantity, label] : kQuantities) {
            for (const Column& c : cs) {
                os << ",";
                const nlohmann::json* v = e.contains(name) ? &e[name] : nullptr;
                v = v && v->contains(quantity) ? &(*v)[quantity] : nullptr;
                for (const std::string& k : c.path) v = v && v->contains(k) ? &(*v)[k] : nullptr;
                if (v) os << v->get<double>();
            }
        }
    }
}

}  // namespace rotbeam
