#include "core/non_finite.hpp"

#include <cmath>

namespace rotbeam {

namespace {

// `inner`, the path inside a child, appended to the child's own part `here`.
std::string joined_path(const std::string& here, const std::string& inner) {
    if (inner == "(value)") return here;
    std::string path = here;
    if (inner.front() != '[') path.push_back('.');
    path.append(inner);
    return path;
}

}  // namespace

std::string first_non_finite(const nlohmann::json& j) {
    if (j.is_number_float()) return std::isfinite(j.get<double>()) ? "" : "(value)";
    if (j.is_object()) {
        for (const auto& [key, item] : j.items()) {
            const std::string inner = first_non_finite(item);
            if (!inner.empty()) return joined_path(key, inner);
        }
    } else if (j.is_array()) {
        for (size_t i = 0; i < j.size(); ++i) {
            const std::string inner = first_non_finite(j[i]);
            if (inner.empty()) continue;
            std::string index(1, '[');  // not "[" + …: GCC 12's -Wrestrict misfires on it
            index.append(std::to_string(i)).push_back(']');
            return joined_path(index, inner);
        }
    }
    return "";
}

}  // namespace rotbeam
