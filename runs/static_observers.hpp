// Observers of a solved static state: what a run reports, computed from the state
// (core/static_state.hpp) after a reported step. They read, never change, the state; the one
// static solve path (solve_static.hpp) calls them.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/kinematic_check.hpp"
#include "core/model.hpp"
#include "core/static_driver.hpp"
#include "core/static_state.hpp"

namespace rotbeam {

// The step entry of a reported load step: every named point's displacement and rotation, the
// rotation angle continued along the beam from the root (core/beam_rotation.hpp), the load factor
// and the step's Newton iterations (core/results.hpp, step_json).
nlohmann::json observe_points(const Model& model, const StaticState& state, const StepRecord& step);

// How the reported state of a load step was accepted (core/convergence.hpp): the criterion, the
// scaled residual, the bound on the scaled algebraic error, and the expected round-off floor when
// the last solve computed it.
nlohmann::json observe_convergence(const StepRecord& step);

// The deformed centre line, for shape plots, as [member, x, y, z] per node; nothing when the
// formulation gives none or it has more than 2000 points (the result file stays small for the
// studies' refined runs).
std::optional<nlohmann::json> observe_centerline(const StaticState& state);

// Section resultants of the state at `load_factor`, per member, ordered by arc length; nothing
// when the formulation gives none.
std::optional<nlohmann::json> observe_sections(const Model& model, const StaticState& state,
                                               double load_factor);

// Why the stability of the model's static equilibria is not assessed: the formulation's reason
// (combinations/registry.hpp); empty when it is assessed (core/static_stability.hpp; loads
// without a potential kinetically, core/static_stability_kinetic.hpp).
std::string stability_not_assessed(const Model& model);

// The stability of a reported step: {assessment, criterion and negative_eigenvalues (energy) or
// growing_modes and kinetic (kinetic) when assessed, reason (when not assessed or critical)};
// `not_assessed` is stability_not_assessed's reason when the step was not assessed for it.
nlohmann::json observe_stability(const StepRecord& step, const std::string& not_assessed);

// The kinematic check (core/kinematic_check.hpp): the worst element when it is past the bound.
std::optional<KinematicDefect> observe_unresolved_kinematics(const StaticState& state);

}  // namespace rotbeam
