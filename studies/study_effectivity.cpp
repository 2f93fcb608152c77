// The effectivity study (docs/error-estimates.md, "Effectivity"; docs/studies.md): the run's error
// estimate against the true error on every case with an independent reference, for every
// combination, over a refinement sequence of the formulation's own strategies (p+1 with its p+2
// decay check for the displacement formulation; h/2, h/4 and the coarser 2h, 4h, each with the
// observed order, for the mixed one). Each level is one `rotbeam run` with its estimate
// (add_run_estimate, the code path of the program); the rows, asymptotic classification and
// failures are effectivity_rows.hpp's. Outputs: study-effectivity.{json,md}, the table per level,
// and a figure of the effectivity against the refinement, one panel per strategy, with the band
// [0.5, 2].
#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "core/results.hpp"
#include "core/static_driver.hpp"
#include "effectivity_dynamic.hpp"
#include "effectivity_outcome.hpp"
#include "effectivity_sequences.hpp"
#include "manufactured_rod_case.hpp"
#include "studies.hpp"

namespace rotbeam::cli {

namespace {

using json = nlohmann::json;

std::string estimated_key(const RunSpec& spec) { return "estimated|" + spec_key(spec); }

std::string effectivity_reference_key(const RunSpec& spec, size_t index, ReferenceKind kind) {
    return kind == ReferenceKind::continuum
               ? "continuum|" + spec.case_name
               : "reference" + std::to_string(index) + "|" + spec_key(spec);
}

void add_unique(std::vector<StudyRun>& plan, StudyRun run) {
    for (const StudyRun& r : plan) {
        if (r.key == run.key) return;
    }
    plan.push_back(std::move(run));
}

std::vector<StudyRun> plan_effectivity(const StudyOptions& o) {
    std::vector<StudyRun> plan;
    for (const EffectivitySequence& s : effectivity_sequences(o.quick)) {
        const std::vector<RunSpec> refs = reference_specs(s);
        for (size_t i = 0; i < refs.size(); ++i) {
            add_unique(
                plan, {effectivity_reference_key(refs[i], i, s.reference),
                       s.reference == ReferenceKind::continuum ? StudyRun::Kind::continuum_reference
                                                               : StudyRun::Kind::case_run,
                       refs[i]});
        }
        for (size_t k = 0; k < s.levels.size(); ++k) {
            add_unique(plan,
                       {estimated_key(s.spec(k)), StudyRun::Kind::estimated_case_run, s.spec(k)});
        }
    }
    plan_motion_runs(plan, o.quick);
    return plan;
}

SequenceHeader static_header(const EffectivitySequence& s) {
    SequenceHeader h{s.case_name,
                     s.combination.label(),
                     s.strategy(),
                     s.x_label(),
                     s.kind == RefinementKind::p ? "p = " : "N = ",
                     {},
                     s.levels};
    for (const int x : s.levels) h.level_text.push_back(std::to_string(x));
    return h;
}

SequenceOutcome measure_sequence(const EffectivitySequence& s, const StudyResults& results) {
    SequenceOutcome out;
    out.h = static_header(s);
    std::vector<json> references;
    const std::vector<RunSpec> refs = reference_specs(s);
    for (size_t i = 0; i < refs.size(); ++i) {
        references.push_back(
            result_of(results, effectivity_reference_key(refs[i], i, s.reference)));
    }
    std::vector<LevelQuantities> levels;
    double order = kNoValue;  // the h-rate the estimate states (the same for every quantity)
    for (size_t k = 0; k < s.levels.size(); ++k) {
        const json& r = result_of(results, estimated_key(s.spec(k)));
        out.statuses.push_back(r.value("status", "error"));
        const bool usable = has_solution(out.statuses.back()) && r.contains("estimate");
        levels.push_back(usable ? level_quantities(s, r, references) : LevelQuantities{});
        if (usable && r["estimate"].contains("theoretical_order")) {
            const json& t = r["estimate"]["theoretical_order"];
            order = t.value(
                s.reference == ReferenceKind::converged_modes ? "frequency" : "displacement",
                kNoValue);
        }
    }
    out.rows = effectivity_rows(levels, s.kind, order);
    classify_rows(out);
    return out;
}

// One data file per strategy: "x effectivity asymptotic(0/1)".
std::string plot_effectivity(const StudyOptions& o,
                             const std::vector<EffectivitySequence>& sequences,
                             const std::vector<SequenceOutcome>& all) {
    std::map<RefinementKind, std::ostringstream> data;
    for (size_t i = 0; i < all.size(); ++i) {
        for (const EffectivityRow& row : all[i].rows) {
            if (!std::isfinite(row.effectivity)) continue;
            data[sequences[i].kind] << sequences[i].levels[row.level] << " " << row.effectivity
                                    << " " << (row.asymptotic ? 1 : 0) << "\n";
        }
    }
    const std::string p_file = "data/effectivity_p.dat", h_file = "data/effectivity_h.dat",
                      c_file = "data/effectivity_h_coarser.dat";
    write_text(o, p_file, "# order effectivity asymptotic\n" + data[RefinementKind::p].str());
    write_text(o, h_file, "# elements effectivity asymptotic\n" + data[RefinementKind::h].str());
    write_text(o, c_file,
               "# elements effectivity asymptotic\n" + data[RefinementKind::h_coarser].str());
    const std::string base = "effectivity";
    plot("study_effectivity.gp", {{"pfile", out_path(o, p_file)},
                                  {"hfile", out_path(o, h_file)},
                                  {"cfile", out_path(o, c_file)},
                                  {"plottitle",
                                   "Effectivity (estimated / true error) against the "
                                   "refinement, every case and combination"},
                                  {"outbase", out_path(o, base)}});
    return base + ".png";
}

json combine_effectivity(const StudyOptions& o, const StudyResults& results) {
    const std::vector<EffectivitySequence> sequences = effectivity_sequences(o.quick);
    std::vector<SequenceOutcome> all;
    for (const EffectivitySequence& s : sequences) all.push_back(measure_sequence(s, results));
    json out = {{"study", "effectivity"}, {"quick", o.quick}, {"sequences", json::array()}};
    for (const SequenceOutcome& s : all) out["sequences"].push_back(outcome_json(s));
    const OutcomeTotals totals = outcome_totals(all);
    const int asymptotic = totals.asymptotic, violations = totals.violations,
              failures = totals.failures, unexplained_n = totals.unexplained,
              other_state = totals.other_state;
    out["asymptotic_rows"] = asymptotic;
    out["band_violations"] = violations;
    out["unexplained_failures"] = unexplained_n;
    out["other_state_failures"] = other_state;
    std::ostringstream md;
    md << "## Study: effectivity of the error estimates\n\nEffectivity = estimated / true error "
          "of every estimated quantity (each named point's displacement and rotation at every "
          "load step; every frequency) on the cases with an independent reference: the roll-up "
          "(cantilever-moment to λ = 2 and, full form, cantilever-moment-4 to λ = 4, exact at "
          "every "
          "load factor), the static manufactured rod ("
       << kManufacturedRodCase
       << ": exact at its quarter points at every load factor, 20 steps to a twist of 2.5π "
          "about a varying axis, four members of N elements), the 45° bend, the precessing "
          "helix, the helix to κL = 4π and the slender tip-loaded cantilever (continuum "
          "reference), the joined beam's frequencies (the displacement "
          "formulation at order 8, 10 elements per member, consistent mass; its distance to "
          "order 7 × 100 is the floor). Each level is `rotbeam run` with its estimate: the "
          "displacement formulation on a fixed mesh with increasing order p (its p+1 estimate, "
          "decay-checked by p+2 below order 6), the mixed one with doubled elements, twice: with "
          "its h/2, h/4 estimate and with its coarser 2h, 4h one (`analysis.estimate_companions: "
          "coarser`), both with the observed order. A row is **asymptotic** when the true errors "
          "alone show it (p: they fall by more than half at each of the next two orders; h: "
          "monotone over N, 2N, 4N, or N/4, N/2, N for 2h, 4h, with both observed orders within "
          "0.5 of the theory); there the effectivity must lie within [0.5, 2]. True errors at or "
          "below "
          "the floor (1e-9 of the reference length, 1e-9 rad) are not counted. A **failure** is "
          "a true error above 3 × its estimate, with the estimate's own verdict as its cause "
          "(estimates/estimator_failure.hpp, the rule of the estimator-failures section), or "
          "**other state** where the quantity's true error does not fall under refinement (over "
          "three or more levels the smallest above half the largest): the discrete solutions "
          "converge to another state than the reference (another solution of the equations, "
          "reached by the continuation, or the reference's own error), which no discretization "
          "estimate can see. The manufactured motion's dynamic estimate has its own section "
          "below."
       << (o.quick ? " Quick form: the roll-up, the bend and the manufactured rod with the "
                     "quaternion only."
                   : "")
       << "\n\nAsymptotic rows: " << asymptotic << "; outside [0.5, 2] there: " << violations
       << "; estimator failures: " << failures << " (other state: " << other_state
       << "; of a reliable estimate otherwise, unexplained: " << unexplained_n << ").\n\n";
    summary_table(all, md);
    level_tables(all, md);
    md << "**Asymptotic rows outside [0.5, 2]**\n\n";
    row_list(all, true, md);
    md << "**Estimator failures** (true error > 3 × estimate, with the cause)\n\n";
    row_list(all, false, md);
    const std::string figure = plot_effectivity(o, sequences, all);
    out["figures"] = {figure};
    md << "![" << figure << "](" << figure << ")\n\n";
    out["dynamic"] = dynamic_effectivity(o.quick, results, md);
    write_text(o, "study-effectivity.md", md.str());
    out["schema_version"] = kSchemaVersion;
    write_text(o, "study-effectivity.json", out.dump(1) + "\n");
    return out;
}

}  // namespace

SplitStudy effectivity_study() { return {plan_effectivity, combine_effectivity}; }

json study_effectivity(const StudyOptions& o) { return run_split_study(effectivity_study(), o); }

}  // namespace rotbeam::cli
