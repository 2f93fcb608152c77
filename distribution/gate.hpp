// The published-tolerance gate (docs/case-format.md, "The gate"): the rows `rotbeam verify`
// prints, and the published numbers of the cases a suite ran (published.md and the report's
// summary).
#pragma once

#include <nlohmann/json.hpp>
#include <ostream>
#include <string>
#include <vector>

namespace rotbeam {
struct ReferenceValue;
}

namespace rotbeam::cli {

// One checked pair (reference or expected stop × combination); verdict "pass", "FAIL",
// "not reached" (the combination stops first) or "recorded" (not gated).
struct Row {
    std::string case_name, id, quantity, combination, published, computed, difference, tolerance,
        verdict;
};

// Every reference and expected stop of the given catalog cases (names or paths), computed.
std::vector<Row> verify_rows(const std::vector<std::string>& cases);
// A row as `verify --json` writes it.
nlohmann::json row_json(const Row& r);
// The rows as an aligned text table (cells cut at 60 characters).
void print_table(const std::vector<Row>& rows, std::ostream& os);

// The comparison `verify` makes, for the given cases: the report's Markdown section and the rows
// as `verify --json` writes them (for the report's summary).
struct PublishedReferences {
    std::string markdown;
    nlohmann::json checks;
};
PublishedReferences published_references(const std::vector<std::string>& cases);
// The --set overrides that put a case into the discretization a reference applies to.
std::vector<std::string> reference_overrides(const ReferenceValue& ref);

}  // namespace rotbeam::cli
