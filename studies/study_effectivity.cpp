// The effectivity study (docs/error-estimates.md, "Effectivity"; docs/studies.md): the run's error
// estimate against the true error on every case with an independent reference, for every
// combination, over a refinement sequence of the formulation's own strategy (p+1 with its p+2
// decay check for the displacement formulation, h/2, h/4 with the observed order for the mixed
// one). Each level is one `rotbeam run` with its estimate (add_run_estimate, the code path of the
// program); the rows, asymptotic classification and failures are effectivity_rows.hpp's. Outputs:
// study-effectivity.{json,md}, the table per level, and a figure of the effectivity against the
// refinement, one panel per strategy, with the band [0.5, 2].
#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "core/results.hpp"
#include "core/static_driver.hpp"
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
    return plan;
}

// Effectivity range and count over some rows.
struct Range {
    int n = 0;
    double lo = 1e300, hi = 0.0;
    void add(double e) {
        ++n;
        lo = std::min(lo, e);
        hi = std::max(hi, e);
    }
    std::string text() const { return n == 0 ? "—" : fixed(lo, 3) + " … " + fixed(hi, 3); }
};

struct SequenceOutcome {
    const EffectivitySequence* s = nullptr;
    std::vector<std::string> statuses;  // per level: the run's status
    std::vector<EffectivityRow> rows;
    Range asymptotic, other;
    std::vector<const EffectivityRow*> violations, failures;
    int asymptotic_unreliable = 0;
};

bool in_band(double e) { return e >= kEffectivityLow && e <= kEffectivityHigh; }

// A failure that neither the estimate (it says it is reliable) nor the sequence (the true error
// falls under refinement) explains.
bool failure_unexplained(const EffectivityRow* f) {
    return f->q.estimate.value("reliable", false) && !f->other_state;
}

SequenceOutcome measure_sequence(const EffectivitySequence& s, const StudyResults& results) {
    SequenceOutcome out;
    out.s = &s;
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
    for (const EffectivityRow& row : out.rows) {
        if (row.failure) out.failures.push_back(&row);
        if (!std::isfinite(row.effectivity)) continue;  // at the floor
        (row.asymptotic ? out.asymptotic : out.other).add(row.effectivity);
        if (row.asymptotic && !in_band(row.effectivity)) out.violations.push_back(&row);
        if (row.asymptotic && !row.q.estimate.value("reliable", false)) ++out.asymptotic_unreliable;
    }
    return out;
}

std::string sequence_label(const EffectivitySequence& s) {
    return s.case_name + " " + s.combination.label() + " " + s.strategy();
}

// "| case | strategy | combination | levels | asymptotic | … |" over every sequence.
void summary_table(const std::vector<SequenceOutcome>& all, std::ostringstream& md) {
    md << "| case | strategy | combination | levels | asymptotic rows | effectivity there | "
          "not reliable there | other rows | effectivity there | outside [0.5, 2] | failures "
          "(other state; reliable otherwise) |\n|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const SequenceOutcome& o : all) {
        const EffectivitySequence& s = *o.s;
        std::string levels;
        for (size_t k = 0; k < s.levels.size(); ++k) {
            levels += (k ? ", " : "") + std::to_string(s.levels[k]);
            if (!has_solution(o.statuses[k])) levels += " (" + o.statuses[k] + ")";
        }
        const auto other = std::count_if(o.failures.begin(), o.failures.end(),
                                         [](auto* r) { return r->other_state; });
        const auto reliable =
            std::count_if(o.failures.begin(), o.failures.end(), failure_unexplained);
        md << "| " << s.case_name << " | " << s.strategy() << " | " << s.combination.label()
           << " | " << (s.kind == RefinementKind::p ? "p = " : "N = ") << levels << " | "
           << o.asymptotic.n << " | " << o.asymptotic.text() << " | " << o.asymptotic_unreliable
           << " | " << o.other.n << " | " << o.other.text() << " | " << o.violations.size() << " | "
           << o.failures.size() << " (" << other << "; " << reliable << ") |\n";
    }
    md << "\n";
}

// Per case and strategy: the effectivity range at each level, with the asymptotic rows' count.
void level_tables(const std::vector<SequenceOutcome>& all, std::ostringstream& md) {
    std::map<std::string, std::vector<const SequenceOutcome*>> groups;
    std::vector<std::string> order;
    for (const SequenceOutcome& o : all) {
        const std::string g = o.s->case_name + ", " + o.s->strategy();
        if (!groups.count(g)) order.push_back(g);
        groups[g].push_back(&o);
    }
    for (const std::string& g : order) {
        const EffectivitySequence& first = *groups[g].front()->s;
        md << "**" << g << "**: effectivity per level (" << first.x_label()
           << "), min … max over the quantities above the floor, [asymptotic / all]\n\n| "
              "combination |";
        for (const int x : first.levels) md << " " << x << " |";
        md << "\n|---|";
        for (size_t k = 0; k < first.levels.size(); ++k) md << "---|";
        md << "\n";
        for (const SequenceOutcome* o : groups[g]) {
            md << "| " << o->s->combination.label() << " |";
            for (size_t k = 0; k < o->s->levels.size(); ++k) {
                Range r;
                int asymptotic = 0;
                for (const EffectivityRow& row : o->rows) {
                    if (row.level != k || !std::isfinite(row.effectivity)) continue;
                    r.add(row.effectivity);
                    asymptotic += row.asymptotic ? 1 : 0;
                }
                md << " " << (has_solution(o->statuses[k]) ? r.text() : o->statuses[k]) << " ["
                   << asymptotic << "/" << r.n << "] |";
            }
            md << "\n";
        }
        md << "\n";
    }
}

void row_list(const std::vector<SequenceOutcome>& all, bool violations, std::ostringstream& md) {
    int n = 0;
    for (const SequenceOutcome& o : all) {
        for (const EffectivityRow* row : violations ? o.violations : o.failures) {
            ++n;
            md << "- " << sequence_label(*o.s) << ", " << o.s->x_label() << " "
               << o.s->levels[row->level] << ", " << markdown_cell(row->q.quantity) << ": ";
            if (violations) {
                md << "effectivity " << fixed(row->effectivity, 3) << " (true "
                   << sci(row->q.true_error) << ", next levels " << sci(row->next_true[0]) << ", "
                   << sci(row->next_true[1]) << "; "
                   << (row->q.estimate.value("reliable", false) ? "reliable" : "not reliable")
                   << ")\n";
            } else {
                md << markdown_cell(*row->failure) << "\n";
            }
        }
    }
    if (n == 0) md << "None.\n";
    md << "\n";
}

// One data file per strategy: "x effectivity asymptotic(0/1)".
std::string plot_effectivity(const StudyOptions& o, const std::vector<SequenceOutcome>& all) {
    std::map<RefinementKind, std::ostringstream> data;
    for (const SequenceOutcome& s : all) {
        for (const EffectivityRow& row : s.rows) {
            if (!std::isfinite(row.effectivity)) continue;
            data[s.s->kind] << s.s->levels[row.level] << " " << row.effectivity << " "
                            << (row.asymptotic ? 1 : 0) << "\n";
        }
    }
    const std::string p_file = "data/effectivity_p.dat", h_file = "data/effectivity_h.dat";
    write_text(o, p_file, "# order effectivity asymptotic\n" + data[RefinementKind::p].str());
    write_text(o, h_file, "# elements effectivity asymptotic\n" + data[RefinementKind::h].str());
    const std::string base = "effectivity";
    plot("study_effectivity.gp", {{"pfile", out_path(o, p_file)},
                                  {"hfile", out_path(o, h_file)},
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
    int asymptotic = 0, violations = 0, failures = 0, unexplained_n = 0, other_state = 0;
    for (const SequenceOutcome& s : all) {
        json rows = json::array();
        for (const EffectivityRow& row : s.rows) rows.push_back(to_json(row));
        out["sequences"].push_back({{"case", s.s->case_name},
                                    {"combination", s.s->combination.label()},
                                    {"strategy", s.s->strategy()},
                                    {"x_is", s.s->x_label()},
                                    {"levels", s.s->levels},
                                    {"statuses", s.statuses},
                                    {"rows", rows}});
        asymptotic += s.asymptotic.n;
        violations += static_cast<int>(s.violations.size());
        failures += static_cast<int>(s.failures.size());
        for (const EffectivityRow* f : s.failures) {
            unexplained_n += failure_unexplained(f) ? 1 : 0;
            other_state += f->other_state ? 1 : 0;
        }
    }
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
          "decay-checked by p+2 below order 6), the mixed one with doubled elements (its h/2, "
          "h/4 estimate with the observed order). A row is **asymptotic** when the true errors "
          "alone show it (p: they fall by more than half at each of the next two orders; h: "
          "monotone over N, 2N, 4N with both observed orders within 0.5 of "
          "the theory); there the effectivity must lie within [0.5, 2]. True errors at or below "
          "the floor (1e-9 of the reference length, 1e-9 rad) are not counted. A **failure** is "
          "a true error above 3 × its estimate, with the estimate's own verdict as its cause "
          "(estimates/estimator_failure.hpp, the rule of the estimator-failures section), or "
          "**other state** where the quantity's true error does not fall under refinement (over "
          "three or more levels the smallest above half the largest): the discrete solutions "
          "converge to another state than the reference (another solution of the equations, "
          "reached by the continuation, or the reference's own error), which no discretization "
          "estimate can see. The "
          "manufactured motion (in time) is measured in test_estimate_dynamic "
          "(docs/error-estimates.md)."
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
    const std::string figure = plot_effectivity(o, all);
    out["figures"] = {figure};
    md << "![" << figure << "](" << figure << ")\n\n";
    write_text(o, "study-effectivity.md", md.str());
    out["schema_version"] = kSchemaVersion;
    write_text(o, "study-effectivity.json", out.dump(1) + "\n");
    return out;
}

}  // namespace

SplitStudy effectivity_study() { return {plan_effectivity, combine_effectivity}; }

json study_effectivity(const StudyOptions& o) { return run_split_study(effectivity_study(), o); }

}  // namespace rotbeam::cli
