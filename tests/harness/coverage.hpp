// The count of checked (combination × state) pairs of the harness: every generic check records the
// combination (or parameterization) and the state it checked, and the harness prints, at its end,
// how many distinct pairs each kind of check covered. A pair is recorded where a check takes the
// state (a state outside a parameterization's chart is skipped and not counted).
#pragma once

#include <string>
#include <string_view>

namespace rotbeam::test {

// Records that a check of `kind` ("identity", "jacobian", "objectivity") ran at `state` for
// `combination`.
void checked(std::string_view kind, std::string_view combination, std::string_view state);

// The report printed at the end: pairs per kind and in all.
std::string coverage_report();

}  // namespace rotbeam::test
