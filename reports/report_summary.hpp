// The report's front: one sentence per case saying whether every combination met its accuracy,
// and the matrix case × combination (met, stopped and why, inaccurate, not run), each cell linked
// to the run's row in the runs table; and the runs table's estimate and true-error cells.
//
// "Met" means: solved, and either every published check of the combination at the case's own
// discretization passed (`verify`'s rows, docs/case-format.md "references"), or, for a run that
// carries its error estimate, every estimate within half the case's stated accuracy
// (discretization.accuracy, docs/accuracy-control.md; a dynamic run's histories each relative to
// its amplitude). A solved run with neither (`suite --estimate off`, or a case that states no
// accuracy for the formulation) is "unchecked": the report does not claim an accuracy, but shows
// the worst estimate when there is one ("unchecked: none stated, estimate 1.5e-01"). A run refused
// in the words the case states for its formulation (a BeamDyn deck's catalog entry,
// cases/loader/deck_case.hpp) is "refused as stated", with the words: no hole in the matrix.
#pragma once

#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/model.hpp"
#include "core/static_state.hpp"

namespace rotbeam::cli {

// A run's "formulation/rotation", the label of its cells and curves.
std::string combination(const nlohmann::json& run);

// The HTML id of the runs table's row of runs[index].
std::string run_row_id(size_t index);

// The "## Summary" section.
std::string summary_section(const std::vector<nlohmann::json>& runs,
                            const nlohmann::json& published_checks);

// The run's worst estimated error relative to its scale (estimates/accuracy_scale.hpp), or why
// there is none.
std::string estimate_cell(const nlohmann::json& run);

// The independent reference of a static case's named points: the exact roll-up's tip
// (cantilever-moment), else the continuum reference (core/continuum) where the solver covers the
// case. `state(point index, load factor)`: nullopt where there is none.
struct PointReference {
    std::string name;    // "exact" | "continuum"
    const Model* model;  // the case's model (its points; loaded once per case)
    std::function<std::optional<PointState>(size_t, double)> state;
};
std::optional<PointReference> point_reference(const std::string& case_name);

// The run's true error where a reference exists: the largest ‖u − u_ref‖/L over the load steps
// (L the estimates' reference length), against the exact roll-up, or for another static case
// against its continuum reference (core/continuum) where the solver covers it; else the largest
// difference to the published values checked at the case's own discretization; "—" without a
// reference.
std::string true_error_cell(const nlohmann::json& run, const nlohmann::json& published_checks);

}  // namespace rotbeam::cli
