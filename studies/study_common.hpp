// What the studies share: the combinations (formulation × parameterization × interpolation), one
// run through run_case() (the code path of `rotbeam run`) with --set-style overrides, the error
// measures against the exact roll-up and the continuum reference, and the output helpers (data
// files, gnuplot, Markdown tables).
//
// Extension point for the dynamic/modal studies: a study is a function `nlohmann::json
// study_<name>(const StudyOptions&)` that writes DIR/study-<name>.md (+ data and figures) and is
// registered in study_commands.cpp's table; the suite's report includes every study-*.md found.
#pragma once

#include <limits>
#include <mutex>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "combinations/registry.hpp"
#include "core/model.hpp"
#include "core/types.hpp"

namespace rotbeam::cli {

constexpr double kNoValue = std::numeric_limits<double>::quiet_NaN();

struct StudyOptions {
    std::string out_dir = "out";
    bool quick = false;
    // joined-beam-dynamics only: the follower load with the --quick sweep (fixed step to 0.5 ms,
    // IDA to 1e-5) on the full window, when the full sweep of both loads costs too much.
    bool reduced_follower = false;
    // Threads for a study's untimed work that runs in parallel (the dynamic studies' same-mesh
    // references); what a study times runs on one thread whatever this is.
    int jobs = 1;
};

// Formulation × parameterization (× interpolation), from the registry (combinations/registry.hpp);
// label() e.g. "displacement/quaternion/relative".
using Combination = comb::Combination;

// Every formulation × parameterization the registry lists (availability is found by running:
// make_problem's InputError reads "unavailable"); with_interpolation doubles the displacement ones
// (relative, direct).
std::vector<Combination> all_combinations(bool with_interpolation);

struct RunSpec {
    std::string case_name;  // catalog name or path
    Combination combination;
    std::vector<std::string> overrides;  // key.path=value, as `--set`
    int elements = 0;                    // > 0: elements of every member
};

Model build_model(const RunSpec& spec);
// run_case() on the spec's model, with its error estimate when `estimate` (add_run_estimate,
// warm-started from the run's solved path as `rotbeam run` does). A combination the program
// refuses (InputError, e.g. "not available") comes back as {"status": "unavailable", "message":
// ...} with no steps.
nlohmann::json run_spec(const RunSpec& spec, bool estimate = false);
bool converged_steps_exist(const nlohmann::json& result);

// The 45° bend's tip as an exact point of the arc: the catalog prints it to 5 decimals, which the
// continuum solver refuses ("arc ends are not equidistant from the centre", 2e-6 in 100 in).
// The finite elements and the reference both solve this exact arc.
extern const char* const kExactBendTip;

// Straight length between a single member's end points (the cases the studies use).
double member_length(const Model& model);

Vec3 point_displacement(const nlohmann::json& step, const std::string& point = "tip");
// ‖u_tip − u_exact‖/L of a roll-up step (core/oracles/rollup.hpp at the step's load factor).
double rollup_tip_error(const nlohmann::json& step, double length);
// ‖u_tip − u_ref‖ / scale against the reference step with the same load factor (NaN if absent).
double reference_tip_error(const nlohmann::json& step, const nlohmann::json& reference,
                           double scale);
// Serializes GSL users of the studies (the continuum solver, the Timoshenko oracle): their guards
// swap GSL's process-wide error handler, which races when studies run in parallel threads.
std::mutex& gsl_mutex();
// The continuum reference (`rotbeam reference`) of a case with overrides (under gsl_mutex).
nlohmann::json continuum_reference(const std::string& case_name,
                                   const std::vector<std::string>& overrides);

int total_newton_iterations(const nlohmann::json& result);

// One curve of a study: x values (elements, unknowns, time, ...) against an error, with a label
// free of spaces (gnuplot takes the titles as a word list).
struct Series {
    std::string label;
    std::vector<double> elements, dofs, seconds, error;
    void add(double n, double d, double s, double e) {
        elements.push_back(n);
        dofs.push_back(d);
        seconds.push_back(s);
        error.push_back(e);
    }
};
// Writes "elements dofs seconds error" rows (finite errors only; a blank line where non-finite
// ones were between them, so plots break the curve there); returns the path.
std::string write_series(const StudyOptions& o, const std::string& relative_path,
                         const Series& series);
// Joins words with single spaces (the gnuplot word lists).
std::string join_words(const std::vector<std::string>& words);

// Output: text files under the study folder, gnuplot (reports/<script>), numbers for tables.
void write_text(const StudyOptions& o, const std::string& relative_path, const std::string& text);
std::string out_path(const StudyOptions& o, const std::string& relative_path);
// Throws when gnuplot fails (gnuplot.hpp).
void plot(const std::string& script, const std::vector<std::pair<std::string, std::string>>& vars);
std::string sci(double value, int digits = 2);  // "—" for NaN
// `value` with `digits` decimals ("0.50"); "—" for a non-finite value, like sci.
std::string fixed(double value, int digits = 2);
// The same, with a non-finite value as the stream prints it ("nan", "inf").
std::string fixed_as_printed(double value, int digits);
std::string quoted(const std::string& s);  // for gnuplot data-file titles
// Free text (a solver's or the loader's message) as Markdown, e.g. one cell of a pipe table: the
// backslash, `|`, the backtick, `<`, `*` and `_` escaped with a backslash, line breaks as spaces.
// Unescaped, a `|` would split the cell, a backtick open a code span that swallows the rest of the
// row, a `<` open raw HTML, and `*` or `_` emphasis.
std::string markdown_cell(const std::string& text);

}  // namespace rotbeam::cli
