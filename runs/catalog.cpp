#include "catalog.hpp"

#include <algorithm>
#include <cstdlib>
#include <filesystem>

#include "core/errors.hpp"

namespace rotbeam::cli {

namespace fs = std::filesystem;

std::string catalog_directory() {
    if (const char* env = std::getenv("ROTBEAM_CASES"); env && *env) return env;
    return ROTBEAM_CASES_DIR;
}

std::vector<std::string> catalog_cases() {
    std::vector<std::string> names;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(catalog_directory(), ec)) {
        if (entry.path().extension() == ".yaml") names.push_back(entry.path().stem().string());
    }
    std::sort(names.begin(), names.end());
    return names;
}

std::string resolve_case_path(const std::string& argument) {
    if (fs::exists(argument)) return argument;
    const fs::path in_catalog = fs::path(catalog_directory()) / (argument + ".yaml");
    if (argument.find('/') == std::string::npos && fs::exists(in_catalog)) return in_catalog;
    const std::string guess = closest_match(fs::path(argument).stem().string(), catalog_cases());
    throw InputError(argument + ": no such case file" +
                     (guess.empty() ? "" : " (did you mean the catalog case '" + guess + "'?)"));
}

}  // namespace rotbeam::cli
