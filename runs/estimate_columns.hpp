// The estimate columns of the CSV files (history_csv.hpp, steps_csv.hpp), from the result JSON's
// per-step `estimate` (docs/error-estimates.md). Per named point, with the unit and the estimate
// in the header:
//   static (p+1 or h/2,h/4):   <point>_u_err_<method>[length], <point>_angle_err_<method>[rad];
//   dynamic (space and time):  <point>_u_err_<space>[length], <point>_u_err_<time>[length],
//                              <point>_u_err[length] (their sum), and the same for the angle;
// where [length] is the case's length unit and a method's comma becomes '+' ("h/2+h/4"). No
// columns when the result has no estimate (off, or not estimated); empty cells at a step without
// one.
#pragma once

#include <nlohmann/json.hpp>
#include <ostream>

namespace rotbeam {

// True when the CSV files of this result carry estimate columns.
bool has_estimate_columns(const nlohmann::json& result);

// ",<column>…" for the points of steps[0].
void write_estimate_header(const nlohmann::json& result, std::ostream& os);

// ",<value>…" for one step, in the header's order.
void write_estimate_row(const nlohmann::json& result, const nlohmann::json& step, std::ostream& os);

}  // namespace rotbeam
