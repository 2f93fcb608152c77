// The dynamic rows of the effectivity study (study_effectivity.cpp, docs/error-estimates.md,
// "Dynamics"): the dynamic error estimate (estimates/history_estimate.hpp: in space p+1 or h/2, h/4
// over the run's time grid, in time the Δt/2 or tolerance/4 companion) against the exact
// manufactured motion (core/oracles/manufactured_motion.hpp, docs/reference-solutions.md §7), over
// a refinement sequence in space (at a small time step) or in time (on a fine mesh). Each level is
// one run of studies/manufactured_motion_runs.hpp (exact initial state) with its estimate, the
// companions run through the same function.
//
// The quantities are the tip's histories, the largest error over the output times, of the
// displacement and of the rotation: the estimate's `history.tip.<quantity>.max_error` (space +
// time) against the true error max_t ‖u_h − u‖ (angle of R_hᵀR), and its part in the refined
// direction against that direction's true error: `max_time` against the distance to the same mesh
// at a fine step (MotionSequence::reference), `max_space` against the exact error of the same
// mesh at a fine step. The rows, the asymptotic classification and the failures are
// effectivity_rows.hpp's, with the rate the estimate states.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "effectivity_rows.hpp"
#include "manufactured_motion_runs.hpp"
#include "study_common.hpp"

namespace rotbeam::cli {

// The manufactured motion as a study run (StudyRun kind estimated_case_run: run_spec and
// build_model, study_common.hpp, recognize the name): the RunSpec's combination and elements, and
// the overrides kMotionOrder … kMotionRho, carry the MotionRunSpec; the motion is
// motion_within_reach of the combination.
inline constexpr const char* kManufacturedMotionCase = "manufactured-motion";
RunSpec motion_run_spec(const MotionRunSpec& m);
// The inverse; InputError on an override it does not know.
MotionRunSpec motion_spec_of(const RunSpec& r);

enum class MotionDirection { space, time };

// The reference runs' step ratio: at order 2 their time error is 1/64 of the run's (time: of the
// finest level's).
inline constexpr double kReferenceStepRatio = 8.0;

struct MotionSequence {
    MotionRunSpec base;  // everything but the refined parameter
    MotionDirection direction = MotionDirection::time;
    // space: orders p (displacement) or elements per member (mixed); time: Δt, or for IDA its
    // tolerance (rtol = atol), each level the previous one over the time companion's ratio.
    std::vector<double> levels;

    MotionRunSpec spec(size_t level) const;
    // The run (no estimate) whose distance gives the refined part's true error: in time the same
    // mesh at the finest level's Δt / kReferenceStepRatio (IDA: tolerance / its square), the same
    // for every level; in space the level's mesh at Δt / kReferenceStepRatio, whose exact error is
    // the mesh's.
    MotionRunSpec reference(size_t level) const;
    RefinementKind kind() const;   // p for the displacement formulation in space, h otherwise
    std::string strategy() const;  // "p+1", "h/2,h/4", "dt/2", "tolerance/4"
    std::string x_label() const;   // "order p", "elements per member", "Δt", "IDA tolerance"
    std::string label() const;     // "displacement/quaternion/p3/ga0.5"
    std::string combination_label() const;  // as the static rows': "mixed/quaternion"
};

// The dynamic sequences: quick, the displacement formulation's quaternion with generalized-α in
// time; full, every combination with its formulation's default scheme (generalized-α, the
// trapezoidal rule) in space and in time, and with the quaternion every other scheme the estimate
// supports (Gauss–Legendre 2 and 3, Radau IIA, IDA) in time, and with adaptive steps over their
// tolerance the generalized-α, Gauss–Legendre 2 and 3 and Radau IIA.
std::vector<MotionSequence> motion_sequences(bool quick);

// A motion run as the result JSON of a dynamic `rotbeam run` (status, steps with their time and
// the named points' displacement, rotation matrix and angle): what the estimate reads.
nlohmann::json motion_result_json(const MotionRunResult& r);

// The run of `spec` with its dynamic estimate (estimates/history_estimate.hpp), its companions
// being runs of the same function.
nlohmann::json estimated_motion_run(const MotionRunSpec& spec);
// The same for a run already made (`run` of `spec`).
nlohmann::json with_motion_estimate(const MotionRunResult& run, const MotionRunSpec& spec);

// The tip histories' estimates of one level's result (estimated_motion_run) against the exact
// motion, the refined part's against `reference` (the result of s.reference(level)).
LevelQuantities motion_quantities(const MotionSequence& s, size_t level,
                                  const nlohmann::json& result, const nlohmann::json& reference);

// The rate at which the sequence's true errors fall per level when asymptotic, log2 of the ratio
// per level: the space order (mixed: the estimate's `theoretical_order.displacement`), or in time
// the estimate's `theoretical_order.time` × log2(the companion's ratio); NaN without an estimate.
double motion_level_rate(const MotionSequence& s, const nlohmann::json& result);

}  // namespace rotbeam::cli
