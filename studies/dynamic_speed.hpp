// Speed versus accuracy of dynamic runs: one measured point per (combination, time setting) —
// its cost the thread CPU time of the whole run_case (median of up to 3 repeats for runs under
// 1 s CPU), its error the response_error of a named point's displacement and rotation histories
// against the combination's same-mesh high-order reference (same_mesh_reference:
// Gauss–Legendre 3 or Radau IIA at two fixed steps that must agree) — the Pareto front over all
// points, and which scheme is cheapest at which accuracy, in words generated from the points.
// Used by `rotbeam study joined-beam-dynamics` and by the dynamic part of `rotbeam study
// speed-accuracy` (the joined beam and the free vibration, dynamic_speed_section).
#pragma once

#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "joined_beam_dynamics.hpp"
#include "study_common.hpp"

namespace rotbeam::cli {

struct DynamicPoint {
    std::string combination, series, scheme;
    TimeSetting setting;
    std::string status;
    double cpu = kNoValue, wall = kNoValue, error = kNoValue;
    double spent = 0.0;  // CPU time of the first run, also when it failed (the figure's x)
    int dofs = 0, newton = 0, repeats = 0;
    long steps = 0;
    Formulation formulation = Formulation::displacement;
};

// One setting on window w: the first run gives the history (and its error against `reference`);
// runs cheaper than 1 s CPU are repeated up to 3 times (2 s budget) for the median.
DynamicPoint dynamic_point(const Combination& c, const TimeSetting& s, const ResponseWindow& w,
                           const JointResponse& reference);
nlohmann::json dynamic_point_json(const DynamicPoint& p);

// "0.123 s", "—" for NaN.
std::string cpu_seconds_text(double seconds);

// The Pareto front of (CPU, error) over `points` (pareto_front), as a markdown table appended to
// md, a data file (cpu error per row, for the figure) and the front's points as JSON.
nlohmann::json dynamic_front(const StudyOptions& o, const std::vector<DynamicPoint>& points,
                             const std::string& front_file, std::ostringstream& md);

// The error levels the words are given at: 1e-1 … 1e-8.
const std::vector<double>& accuracy_levels();

// The cheapest point (least CPU; equal CPU: the smaller error) whose error is ≤ `level`, per
// level; -1 when no point reaches it. Such a point is never dominated, so it is on the front.
std::vector<int> cheapest_per_level(const std::vector<DynamicPoint>& points,
                                    const std::vector<double>& levels);

// Which scheme wins at which accuracy, generated from the points: the levels grouped into
// ranges won by one scheme, each with its cheapest run; appended to md, returned as JSON
// (one entry per level: level, winner's index, scheme, combination, setting, CPU, error).
nlohmann::json winners_in_words(const std::vector<DynamicPoint>& points, std::ostringstream& md);

// A figure panel per formulation and scheme (the parameterizations of a panel give the same
// errors to 2–3 digits and would hide each other on one set of axes).
std::string dynamic_panel_title(const TimeSetting& s, Formulation formulation);

// One problem of the speed-accuracy study's dynamic part: a case's window, the combinations and,
// per formulation, the settings swept; references by same_mesh_reference at `coarse_step` of
// the formulation.
struct DynamicSpeedProblem {
    std::string key, title, error_words;
    ResponseWindow window;
    std::vector<Combination> combinations;
    std::map<Formulation, std::vector<TimeSetting>> settings;
    std::map<Formulation, double> coarse_step;
};

// The joined beam (dead load) and the free vibration; --quick: shorter windows, a coarser free
// vibration mesh, one parameterization per formulation and fewer settings.
std::vector<DynamicSpeedProblem> dynamic_speed_problems(bool quick);
// The one of them whose key is `key` ("joined_beam" | "free_vibration"; std::invalid_argument
// otherwise).
DynamicSpeedProblem dynamic_speed_problem(const std::string& key, bool quick);

struct DynamicSpeedResult {
    std::vector<DynamicPoint> points;
    std::vector<ReferenceResponse> references;  // one per combination, in its order
    std::vector<std::string> not_run;           // combinations without a reference, and why
    double cpu_seconds = 0.0;  // the references' (0 when cached) and the sweep's, every thread
};

// The reference of every combination of every problem (same_mesh_reference at the problem's
// coarse_step of the combination's formulation), on `threads` threads (compute_references),
// read from / written to `cache_dir` when not empty: per problem, one per combination, in order.
std::vector<std::vector<ReferenceResponse>> speed_references(
    const std::vector<DynamicSpeedProblem>& problems, const std::string& cache_dir, int threads);

// Every (combination, setting) point of the problem against `references` (speed_references: one
// per combination), on this thread: the points are timed.
DynamicSpeedResult measure_dynamic_speed(const DynamicSpeedProblem& p,
                                         std::vector<ReferenceResponse> references);

// The speed-accuracy study's dynamic section: every problem's references first, on o.jobs
// threads, then its points on this thread; references, front, words, figure and table appended
// to md; the JSON returned.
nlohmann::json dynamic_speed_section(const StudyOptions& o, std::ostringstream& md);

}  // namespace rotbeam::cli
