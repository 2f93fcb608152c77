#include "effectivity_dynamic.hpp"

#include <sstream>

#include "effectivity_motion.hpp"
#include "effectivity_outcome.hpp"

namespace rotbeam::cli {

namespace {

using json = nlohmann::json;

std::string estimated_motion_key(const MotionRunSpec& m) {
    return "estimated|" + spec_key(motion_run_spec(m));
}

std::string motion_level_text(double x) {
    std::ostringstream s;
    s << x;
    return s.str();
}

SequenceHeader motion_header(const MotionSequence& s) {
    SequenceHeader h{std::string("manufactured motion in ") +
                         (s.direction == MotionDirection::time ? "time" : "space"),
                     s.label(),
                     s.strategy(),
                     s.x_label(),
                     s.x_label() + " = ",
                     {},
                     s.levels};
    for (const double x : s.levels) h.level_text.push_back(motion_level_text(x));
    return h;
}

SequenceOutcome measure_motion_sequence(const MotionSequence& s, const StudyResults& results) {
    SequenceOutcome out;
    out.h = motion_header(s);
    std::vector<LevelQuantities> levels;
    double rate = kNoValue;  // the same at every level
    for (size_t k = 0; k < s.levels.size(); ++k) {
        const json& r = result_of(results, estimated_motion_key(s.spec(k)));
        out.statuses.push_back(r.value("status", "error"));
        levels.push_back(motion_quantities(
            s, k, r, result_of(results, spec_key(motion_run_spec(s.reference(k))))));
        if (std::isnan(rate)) rate = motion_level_rate(s, r);
    }
    out.rows = effectivity_rows(levels, s.kind(), rate);
    classify_rows(out);
    return out;
}

}  // namespace

void plan_motion_runs(std::vector<StudyRun>& plan, bool quick) {
    for (const MotionSequence& s : motion_sequences(quick)) {
        for (size_t k = 0; k < s.levels.size(); ++k) {
            const RunSpec spec = motion_run_spec(s.spec(k));
            const std::string key = estimated_motion_key(s.spec(k));
            bool planned = false;
            for (const StudyRun& r : plan) planned = planned || r.key == key;
            if (!planned) plan.push_back({key, StudyRun::Kind::estimated_case_run, spec});
            plan_case_run(plan, motion_run_spec(s.reference(k)));
        }
    }
}

json dynamic_effectivity(bool quick, const StudyResults& results, std::ostringstream& md) {
    std::vector<SequenceOutcome> all;
    for (const MotionSequence& s : motion_sequences(quick)) {
        all.push_back(measure_motion_sequence(s, results));
    }
    json out = {{"sequences", json::array()}};
    for (const SequenceOutcome& s : all) out["sequences"].push_back(outcome_json(s));
    const OutcomeTotals t = outcome_totals(all);
    out["asymptotic_rows"] = t.asymptotic;
    out["band_violations"] = t.violations;
    out["estimator_failures"] = t.failures;
    out["unexplained_failures"] = t.unexplained;
    out["other_state_failures"] = t.other_state;
    md << "### Dynamics: the manufactured motion\n\nThe dynamic estimate (space: p+1 for the "
          "displacement formulation, h/2, h/4 with the observed order for the mixed one, over the "
          "run's own time grid; time: the Δt/2 companion, or tolerance/4 for IDA and adaptive "
          "steps; "
          "docs/error-estimates.md, Dynamics) against the exact manufactured motion "
          "(docs/reference-solutions.md §7: a free rod spun past 2π about an axis varying in "
          "space and time, four members, exact initial state, ten output times to t = 1). "
          "Quantities: the tip's displacement and rotation histories, the largest error over the "
          "output times: the estimate (space + time) against the true error max_t ‖u_h − u‖ "
          "(angle of R_hᵀR), and the part the sequence refines against that direction's true "
          "error (time: the distance to the same mesh at the finest Δt / 8, or at the finest "
          "tolerance / 64; space: the exact "
          "error of the same mesh at Δt / 8; the other part is in the JSON as `other_part`). "
          "Asymptotic as above, with the rate the estimate states (space: the mixed formulation's "
          "order 2; time: its time order × log2 of the companion's ratio, the ratio between "
          "levels). Sequences: "
       << (quick ? "the displacement formulation with the quaternion and the generalized-α "
                   "(ρ∞ = 0.5), in time"
                 : "every combination in space and in time with the generalized-α (ρ∞ = 0.5) "
                   "or the trapezoidal rule, the quaternion also in time with Gauss–Legendre 2 "
                   "and 3, Radau IIA and IDA, and with adaptive steps over their tolerance "
                   "(generalized-α, Gauss–Legendre 2 and 3; Radau IIA on 4 elements per member)")
       << ".\n\nAsymptotic rows: " << t.asymptotic << "; outside [0.5, 2] there: " << t.violations
       << "; estimator failures: " << t.failures << " (other state: " << t.other_state
       << "; of a reliable estimate otherwise, unexplained: " << t.unexplained << ").\n\n";
    summary_table(all, md);
    level_tables(all, md);
    md << "**Dynamic asymptotic rows outside [0.5, 2]**\n\n";
    row_list(all, true, md);
    md << "**Dynamic estimator failures** (true error > 3 × estimate, with the cause)\n\n";
    row_list(all, false, md);
    return out;
}

}  // namespace rotbeam::cli
