// Table I of seed 002 (the moment-loaded cantilever) reproduced in the report: for every load
// factor of the case, the exact tip, the paper's GEBT columns with their Newton iteration counts
// (from the case file's references: published numbers live once), and every combination the suite
// ran on the case, with its iterations and its distance to the exact tip.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace rotbeam::cli {

// A Markdown section (heading, sentence, table); empty when no run of the case is given.
// `runs` are result documents of any cases; those of `case_name` are used.
std::string table_one_section(const std::string& case_name, const std::vector<nlohmann::json>& runs);

}  // namespace rotbeam::cli
