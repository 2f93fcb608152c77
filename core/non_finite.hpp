// Where a result document holds a number that is not finite: a result never prints NaN, and the
// status that drops it says where it showed (runs/run_case.cpp).
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace rotbeam {

// The key path of the first non-finite number of the document ("steps[0].points.tip.
// displacement[2]"; "(value)" for a bare number), or empty when every number is finite.
std::string first_non_finite(const nlohmann::json& j);

}  // namespace rotbeam
