// The report's dynamic and modal paper reproductions (seed 002 Example 3 and 4): the joined beam's
// joint histories, dead against follower (Figs. 6–7), the blade's tip and root histories
// (Figs. 10–11), and the joined beam's natural frequencies (Table III). Each section writes its
// data files to DIR/data, draws its figures with a gnuplot script from reports/, and returns its
// Markdown (empty when no run of its case is present).
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace rotbeam::cli {

std::string joined_beam_histories_section(const std::string& out_dir,
                                          const std::vector<nlohmann::json>& runs);

std::string blade_histories_section(const std::string& out_dir,
                                    const std::vector<nlohmann::json>& runs);

std::string table_three_section(const std::vector<nlohmann::json>& runs);

}  // namespace rotbeam::cli
