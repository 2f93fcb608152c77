// One refinement sequence of the effectivity study measured (study_effectivity.cpp): its rows
// (effectivity_rows.hpp) with the counts the report gives, and the report's tables over many
// sequences, static or dynamic alike: a summary per sequence, the effectivity per level, the
// asymptotic rows outside [kEffectivityLow, kEffectivityHigh] and the estimator failures with
// their causes.
#pragma once

#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "effectivity_rows.hpp"

namespace rotbeam::cli {

// What the tables say about a sequence.
// bugprone-exception-escape: the implicit special members may throw through the json and string
// members; the headers and outcomes are built once and never moved inside a noexcept context.
struct SequenceHeader {                   // NOLINT(bugprone-exception-escape)
    std::string case_name;                // "cantilever-moment", "manufactured motion in time"
    std::string combination;              // "mixed/quaternion", or the motion run's label
    std::string strategy;                 // "p+1", "h/2,h/4", "dt/2", "tolerance/4"
    std::string x_label;                  // "order p", "elements per member", "Δt", …
    std::string x_symbol;                 // the summary table's "p = ", "N = ", "Δt = "
    std::vector<std::string> level_text;  // each level's refined parameter as printed
    nlohmann::json levels;                // the same in the JSON
};

// Effectivity range and count over some rows.
struct EffectivityRange {
    int n = 0;
    double lo = 1e300, hi = 0.0;
    void add(double e);
    std::string text() const;  // "0.868 … 1.009", "—" when empty
};

struct SequenceOutcome {  // NOLINT(bugprone-exception-escape): as SequenceHeader
    SequenceHeader h;
    std::vector<std::string> statuses;  // per level: the run's status
    std::vector<EffectivityRow> rows;
    EffectivityRange asymptotic, other;
    std::vector<const EffectivityRow*> violations, failures;
    int asymptotic_unreliable = 0;
};

// Fills the ranges, the band violations and the failures from o.rows (call once the rows are in
// place: the lists point into them).
void classify_rows(SequenceOutcome& o);

// The study's counts over some sequences.
struct OutcomeTotals {
    int asymptotic = 0, violations = 0, failures = 0, unexplained = 0, other_state = 0;
};
OutcomeTotals outcome_totals(const std::vector<SequenceOutcome>& all);

// {"case", "combination", "strategy", "x_is", "levels", "statuses", "rows"}.
nlohmann::json outcome_json(const SequenceOutcome& o);

// "| case | strategy | combination | levels | asymptotic | … |" over every sequence.
void summary_table(const std::vector<SequenceOutcome>& all, std::ostringstream& md);
// Per case and strategy: the effectivity range at each level, with the asymptotic rows' count.
void level_tables(const std::vector<SequenceOutcome>& all, std::ostringstream& md);
// The asymptotic rows outside the band (`violations`) or the estimator failures, "None." if none.
void row_list(const std::vector<SequenceOutcome>& all, bool violations, std::ostringstream& md);

}  // namespace rotbeam::cli
