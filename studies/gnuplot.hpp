// Drawing a figure: runs reports/<script> with gnuplot and string variables (-e "k='v'", any text
// quoted). A figure a report links must exist, so a failure (gnuplot missing, or the script
// failing on the data) throws std::runtime_error with gnuplot's last message: no report is written
// with a hole where a figure should be. Shared by the studies, the benches and the report.
#pragma once

#include <map>
#include <string>

namespace rotbeam::cli {

void run_gnuplot_script(const std::string& script, const std::map<std::string, std::string>& vars);

}  // namespace rotbeam::cli
