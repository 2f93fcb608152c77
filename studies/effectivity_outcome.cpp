#include "effectivity_outcome.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "core/static_driver.hpp"
#include "study_common.hpp"

namespace rotbeam::cli {

namespace {

using json = nlohmann::json;

bool in_band(double e) { return e >= kEffectivityLow && e <= kEffectivityHigh; }

// A failure that neither the estimate (it says it is reliable) nor the sequence (the true error
// falls under refinement) explains.
bool failure_unexplained(const EffectivityRow* f) {
    return f->q.estimate.value("reliable", false) && !f->other_state;
}

std::string sequence_label(const SequenceHeader& h) {
    return h.case_name + " " + h.combination + " " + h.strategy;
}

}  // namespace

void EffectivityRange::add(double e) {
    ++n;
    lo = std::min(lo, e);
    hi = std::max(hi, e);
}

std::string EffectivityRange::text() const {
    return n == 0 ? "—" : fixed(lo, 3) + " … " + fixed(hi, 3);
}

void classify_rows(SequenceOutcome& o) {
    for (const EffectivityRow& row : o.rows) {
        if (row.failure) o.failures.push_back(&row);
        if (!std::isfinite(row.effectivity)) continue;  // at the floor
        (row.asymptotic ? o.asymptotic : o.other).add(row.effectivity);
        if (row.asymptotic && !in_band(row.effectivity)) o.violations.push_back(&row);
        if (row.asymptotic && !row.q.estimate.value("reliable", false)) ++o.asymptotic_unreliable;
    }
}

OutcomeTotals outcome_totals(const std::vector<SequenceOutcome>& all) {
    OutcomeTotals t;
    for (const SequenceOutcome& s : all) {
        t.asymptotic += s.asymptotic.n;
        t.violations += static_cast<int>(s.violations.size());
        t.failures += static_cast<int>(s.failures.size());
        for (const EffectivityRow* f : s.failures) {
            t.unexplained += failure_unexplained(f) ? 1 : 0;
            t.other_state += f->other_state ? 1 : 0;
        }
    }
    return t;
}

json outcome_json(const SequenceOutcome& o) {
    json rows = json::array();
    for (const EffectivityRow& row : o.rows) rows.push_back(to_json(row));
    return {{"case", o.h.case_name}, {"combination", o.h.combination}, {"strategy", o.h.strategy},
            {"x_is", o.h.x_label},   {"levels", o.h.levels},           {"statuses", o.statuses},
            {"rows", rows}};
}

void summary_table(const std::vector<SequenceOutcome>& all, std::ostringstream& md) {
    md << "| case | strategy | combination | levels | asymptotic rows | effectivity there | "
          "not reliable there | other rows | effectivity there | outside [0.5, 2] | failures "
          "(other state; reliable otherwise) |\n|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const SequenceOutcome& o : all) {
        std::string levels;
        for (size_t k = 0; k < o.h.level_text.size(); ++k) {
            levels += (k ? ", " : "") + o.h.level_text[k];
            if (!has_solution(o.statuses[k])) levels += " (" + o.statuses[k] + ")";
        }
        const auto other = std::count_if(o.failures.begin(), o.failures.end(),
                                         [](auto* r) { return r->other_state; });
        const auto reliable =
            std::count_if(o.failures.begin(), o.failures.end(), failure_unexplained);
        md << "| " << o.h.case_name << " | " << o.h.strategy << " | " << o.h.combination << " | "
           << o.h.x_symbol << levels << " | " << o.asymptotic.n << " | " << o.asymptotic.text()
           << " | " << o.asymptotic_unreliable << " | " << o.other.n << " | " << o.other.text()
           << " | " << o.violations.size() << " | " << o.failures.size() << " (" << other << "; "
           << reliable << ") |\n";
    }
    md << "\n";
}

void level_tables(const std::vector<SequenceOutcome>& all, std::ostringstream& md) {
    std::map<std::string, std::vector<const SequenceOutcome*>> groups;
    std::vector<std::string> order;
    for (const SequenceOutcome& o : all) {
        const std::string g = o.h.case_name + ", " + o.h.strategy;
        if (!groups.count(g)) order.push_back(g);
        groups[g].push_back(&o);
    }
    for (const std::string& g : order) {
        const SequenceHeader& first = groups[g].front()->h;
        md << "**" << g << "**: effectivity per level (" << first.x_label
           << "), min … max over the quantities above the floor, [asymptotic / all]\n\n| "
              "combination |";
        for (const std::string& x : first.level_text) md << " " << x << " |";
        md << "\n|---|";
        for (size_t k = 0; k < first.level_text.size(); ++k) md << "---|";
        md << "\n";
        for (const SequenceOutcome* o : groups[g]) {
            md << "| " << o->h.combination << " |";
            for (size_t k = 0; k < o->h.level_text.size(); ++k) {
                EffectivityRange r;
                int asymptotic = 0;
                for (const EffectivityRow& row : o->rows) {
                    if (row.level != k || !std::isfinite(row.effectivity)) continue;
                    r.add(row.effectivity);
                    asymptotic += row.asymptotic ? 1 : 0;
                }
                // A dynamic run ending `inaccurate` by its own estimate keeps its rows.
                const std::string& status = o->statuses[k];
                md << " "
                   << (has_solution(status) ? r.text()
                       : r.n > 0            ? r.text() + " (" + status + ")"
                                            : status)
                   << " [" << asymptotic << "/" << r.n << "] |";
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
            md << "- " << sequence_label(o.h) << ", " << o.h.x_label << " "
               << o.h.level_text[row->level] << ", " << markdown_cell(row->q.quantity) << ": ";
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

}  // namespace rotbeam::cli
