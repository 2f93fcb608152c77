// "Model only what the scene requires": the time it saves, measured. Every
// analysis kind (static, modal, dynamic) and formulation is run twice on the same model — as the
// scene requires (the default) and with solver.assemble_all_terms (inertia and damping at rest in
// statics, damping of undamped sections, the load stiffness of dead loads, all with zero
// coefficients; core/model.hpp) — alternating, and the medians of the in-process run_case() times
// are compared. The two results must agree to round-off (checked on every step's numbers and the
// frequencies; a disagreement is reported as an error in the table, never hidden).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

#include "core/errors.hpp"
#include "core/static_driver.hpp"
#include "runs/run_case.hpp"
#include "runs/timing.hpp"
#include "studies/study_common.hpp"
#include "study_speed.hpp"

namespace rotbeam::cli {

namespace {

// Largest |a − b| and |a| over the numeric leaves of two results of the same run (the same
// structure: steps, points, frequencies).
void compare_numbers(const nlohmann::json& a, const nlohmann::json& b, double& difference,
                     double& magnitude) {
    if (a.is_number() && b.is_number()) {
        difference = std::max(difference, std::abs(a.get<double>() - b.get<double>()));
        magnitude = std::max(magnitude, std::abs(a.get<double>()));
        return;
    }
    if (a.type() != b.type() || a.size() != b.size()) {
        difference = std::numeric_limits<double>::infinity();
        return;
    }
    if (a.is_array()) {
        for (size_t i = 0; i < a.size(); ++i) compare_numbers(a[i], b[i], difference, magnitude);
    } else if (a.is_object()) {
        for (auto it = a.begin(); it != a.end(); ++it) {
            if (!b.contains(it.key())) {
                difference = std::numeric_limits<double>::infinity();
                return;
            }
            compare_numbers(it.value(), b[it.key()], difference, magnitude);
        }
    }
}

// max |Δ| / max |value| over the steps and frequencies of two results.
double result_difference(const nlohmann::json& a, const nlohmann::json& b) {
    double difference = 0.0, magnitude = 0.0;
    for (const char* key : {"steps", "frequencies_hz"}) {
        if (a.contains(key) || b.contains(key)) {
            compare_numbers(a.value(key, nlohmann::json()), b.value(key, nlohmann::json()),
                            difference, magnitude);
        }
    }
    return magnitude > 0.0 ? difference / magnitude : difference;
}

struct SavingCase {
    std::string analysis, case_name;
    std::vector<std::string> overrides;
};

// The catalog analyses, dynamic ones shortened to 100 time steps (the per-step cost is what is
// compared).
std::vector<SavingCase> saving_cases(bool quick) {
    std::vector<SavingCase> c = {
        {"static", "cantilever-moment", {}},
        {"static", "bend-45", {}},
        {"modal", "joined-beam", {}},
        {"dynamic", "blade-mh104", {"analysis.end_time=0.1"}},
    };
    if (!quick) c.push_back({"dynamic", "joined-beam-follower", {"analysis.end_time=0.1"}});
    return c;
}

double seconds_of(const std::function<void()>& work) {
    const auto start = std::chrono::steady_clock::now();
    work();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string counters_text(const nlohmann::json& r) {
    const nlohmann::json c = r.value("counters", nlohmann::json::object());
    std::ostringstream s;
    s << c.value("inertial_terms", 0L) << " / " << c.value("damping_terms", 0L) << " / "
      << c.value("follower_stiffness", 0L);
    return s.str();
}

std::string ms_3_digits(double seconds) {
    std::ostringstream s;
    s.precision(3);
    s << seconds * 1e3;
    return s.str();
}

std::string fixed_ratio(double ratio) {
    std::ostringstream s;
    s.precision(2);
    s << std::fixed << ratio;
    return s.str();
}

std::string percent(double fraction) {
    std::ostringstream s;
    s.precision(1);
    s << std::fixed << 100.0 * fraction << " %";
    return s.str();
}

// Tolerance on max |Δ| / max |value| between the two modes: both add the same nonzero terms in
// the same order; the extra terms are exact zeros, so anything above a few ε is a defect.
constexpr double kSameResult = 1e-12;

// Per analysis kind, in words: the median and range of t(all)/t(needed) over the runs where
// assembling everything added terms, and the same over the control runs where it added none (the
// same work twice: their spread is the timing noise the first numbers must be read against).
void summary_in_words(const nlohmann::json& rows, std::ostringstream& md) {
    for (const char* kind : {"static", "modal", "dynamic"}) {
        std::vector<double> added, control;
        int different = 0;
        for (const auto& r : rows) {
            if (r["analysis"] != kind) continue;
            (r["counters_all"] != r["counters_needed"] ? added : control)
                .push_back(r["ratio"].get<double>());
            if (!r["same_result"].get<bool>()) ++different;
        }
        if (added.empty() && control.empty()) continue;
        auto range = [](const std::vector<double>& v) {
            return fixed_ratio(median(v)) + " (" +
                   fixed_ratio(*std::min_element(v.begin(), v.end())) + "–" +
                   fixed_ratio(*std::max_element(v.begin(), v.end())) + ", " +
                   std::to_string(v.size()) + " runs)";
        };
        md << "- " << kind << ": ";
        if (!added.empty()) md << "t(all)/t(needed) = " << range(added);
        if (!added.empty() && !control.empty()) md << "; ";
        if (!control.empty()) md << "control runs without added terms " << range(control);
        md << "; "
           << (different == 0 ? "every result identical to round-off"
                              : std::to_string(different) + " results DIFFER")
           << ".\n";
    }
    md << "\n";
}

}  // namespace

nlohmann::json assembly_savings(const StudyOptions& o, std::ostringstream& md) {
    const int repeats = o.quick ? 3 : 7;
    const double budget = o.quick ? 0.2 : 1.0;  // seconds per mode and row
    md << "### Model only what the scene requires: the time it saves\n\nEach catalog analysis "
          "(dynamic ones shortened to 0.1 s = 100 steps) run as the scene requires and with "
          "`solver.assemble_all_terms: true` (every term assembled: inertia and damping at rest "
          "in statics, damping of undamped sections, load stiffness of dead loads, with zero "
          "coefficients), alternating, median of at least "
       << repeats << " in-process run_case() times each (more for short runs, up to " << budget
       << " s per mode). The status is the default run's (the roll-up's catalog λ = 2 is past "
          "the reach of some combinations; a failed run is timed too, both modes fail alike). "
          "`saving` = 1 − t(needed)/t(all). Counters: "
          "inertial / damping / load-stiffness terms. `Δ result` = max |Δ| / max |value| over "
          "every step's output and the frequencies: must be ≤ "
       << sci(kSameResult, 0)
       << " (the added terms are exact zeros). Rows whose counters do not change (the mixed "
          "dynamics and modal analyses always need their inertia; the mixed quaternion has no "
          "inertial kernel yet) run the same work twice: their ratio is the timing noise.\n\n"
          "| analysis | case | combination | status | counters needed | counters all | t needed "
          "[ms] | t all [ms] | t all / t needed | saving | Δ result |\n"
          "|---|---|---|---|---|---|---|---|---|---|---|\n";
    nlohmann::json out = nlohmann::json::array();
    for (const SavingCase& c : saving_cases(o.quick)) {
        for (const Combination& comb : all_combinations(false)) {
            const RunSpec needed{c.case_name, comb, c.overrides, 0};
            RunSpec all = needed;
            all.overrides.push_back("solver.assemble_all_terms=true");
            Model needed_model, all_model;
            try {
                needed_model = build_model(needed);
                all_model = build_model(all);
            } catch (const InputError&) {
                continue;  // not this case's business (run_spec reports what is unavailable)
            }
            const nlohmann::json r_needed = run_spec(needed), r_all = run_spec(all);
            const std::string status = r_needed.value("status", "error");
            if (!has_solution(status) && status != "diverged" && status != "singular") {
                // Not run at all (unavailable, refused): nothing to time.
                std::string message = r_needed.value("message", "");
                if (message.size() > 80) message = message.substr(0, 77) + "...";
                md << "| " << c.analysis << " | " << c.case_name << " | " << comb.label() << " | "
                   << status << ": " << markdown_cell(message) << " | | | | | | | |\n";
                continue;
            }
            const double difference = result_difference(r_needed, r_all);
            // Short runs are repeated until both modes have taken ~budget seconds: a median of
            // a handful of millisecond runs on a shared machine is mostly scheduler noise. A cap
            // on the repeats (timing_repeats) below the minimum leaves nothing for the first
            // run's time to decide, and that run is not made.
            int count = timing_repeats(repeats);
            if (count == repeats) {
                const double first = seconds_of([&] {
                    run_case(RunRequest{c.case_name, needed_model, false});
                });
                count = timing_repeats(
                    std::clamp(static_cast<int>(budget / std::max(first, 1e-6)), repeats, 101));
            }
            std::vector<double> t_needed, t_all;
            for (int i = 0; i < count; ++i) {
                t_needed.push_back(seconds_of([&] {
                    run_case(RunRequest{c.case_name, needed_model, false});
                }));
                t_all.push_back(seconds_of([&] {
                    run_case(RunRequest{c.case_name, all_model, false});
                }));
            }
            const double tn = median(t_needed), ta = median(t_all);
            const bool same = difference <= kSameResult && status == r_all.value("status", "");
            md << "| " << c.analysis << " | " << c.case_name << " | " << comb.label() << " | "
               << status << " | " << counters_text(r_needed) << " | " << counters_text(r_all)
               << " | " << ms_3_digits(tn) << " | " << ms_3_digits(ta) << " | "
               << fixed_ratio(ta / tn) << " | " << percent(1.0 - tn / ta) << " | "
               << sci(difference, 1) << (same ? "" : " **DIFFERENT (" + status + ")**") << " |\n";
            out.push_back({{"analysis", c.analysis},
                           {"case", c.case_name},
                           {"combination", comb.label()},
                           {"status", status},
                           {"repeats", count},
                           {"seconds_needed", tn},
                           {"seconds_all", ta},
                           {"ratio", ta / tn},
                           {"result_difference", difference},
                           {"same_result", same},
                           {"counters_needed", r_needed.value("counters", nlohmann::json())},
                           {"counters_all", r_all.value("counters", nlohmann::json())}});
        }
    }
    md << "\n";
    summary_in_words(out, md);
    return out;
}

}  // namespace rotbeam::cli
