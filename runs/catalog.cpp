#include "catalog.hpp"

#include <algorithm>
#include <cstdlib>
#include <filesystem>

#include "core/errors.hpp"

namespace rotbeam::cli {

namespace fs = std::filesystem;

namespace {

size_t edit_distance(const std::string& a, const std::string& b) {
    std::vector<size_t> row(b.size() + 1);
    for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (size_t i = 1; i <= a.size(); ++i) {
        size_t diagonal = row[0];
        row[0] = i;
        for (size_t j = 1; j <= b.size(); ++j) {
            const size_t up = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1])});
            diagonal = up;
        }
    }
    return row[b.size()];
}

}  // namespace

std::string closest_match(const std::string& word, const std::vector<std::string>& candidates) {
    std::string best;
    size_t best_distance = std::max<size_t>(2, word.size() / 3) + 1;
    for (const std::string& c : candidates) {
        const size_t d = edit_distance(word, c);
        if (d < best_distance) {
            best_distance = d;
            best = c;
        }
    }
    return best;
}

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
