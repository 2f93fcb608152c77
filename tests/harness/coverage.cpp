#include "tests/harness/coverage.hpp"

#include <map>
#include <set>
#include <sstream>
#include <tuple>

namespace rotbeam::test {

namespace {
std::map<std::string, std::set<std::pair<std::string, std::string>>>& pairs() {
    static std::map<std::string, std::set<std::pair<std::string, std::string>>> p;
    return p;
}
}  // namespace

void checked(std::string_view kind, std::string_view combination, std::string_view state) {
    pairs()[std::string(kind)].emplace(std::string(combination), std::string(state));
}

std::string coverage_report() {
    std::ostringstream out;
    std::size_t total = 0;
    out << "checked (combination × state) pairs:";
    for (const auto& [kind, set] : pairs()) {
        std::set<std::string> combinations;
        for (const auto& pair : set) combinations.insert(pair.first);
        out << ' ' << kind << ' ' << set.size() << " (" << combinations.size() << " combinations),";
        total += set.size();
    }
    out << " in all " << total;
    return out.str();
}

}  // namespace rotbeam::test
