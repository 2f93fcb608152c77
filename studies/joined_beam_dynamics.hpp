// The joined beam's 0–2 s response (docs/benchmarks.md §3, cases/joined-beam-dead.yaml) as the
// dynamic speed-versus-accuracy study and the joined-beam targets of `rotbeam bench`
// use it: one integration setting (integrator, Δt or IDA tolerance) per run, the joint's
// displacement history, and the self-converged references the errors are measured against.
//
// Two errors, kept apart (docs/studies.md, "Joined beam: dynamic speed versus accuracy"):
// - time error: a combination on the paper's mesh (10 elements per member) against its own
//   same-mesh reference — Richardson extrapolation (order 2) of its fixed-step scheme at the two
//   finest steps; what the integrator and its setting control;
// - space error: the paper mesh's same-mesh reference against a refined-mesh reference
//   (displacement, order 3 on the same 10 elements per member, same extrapolation); what the mesh
//   controls and no Δt or tolerance removes.
// References are computed (never stored in the repository) and cached as JSON under a folder the
// caller names, each with the settings and program version that produced it; a cached file is
// used only when its settings match.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "study_common.hpp"
#include "study_extrapolation.hpp"

namespace rotbeam::cli {

// One way of integrating the response.
struct TimeSetting {
    Integrator integrator;   // generalized_alpha (displacement), trapezoidal or ida (mixed)
    double time_step = 0.0;  // fixed step; IDA: the initial step hint and output spacing only
    double tolerance = 0.0;  // IDA: rtol = atol factor (analysis.relative_tolerance and absolute_tolerance)
    std::string label() const;  // "Δt=0.001" | "ida-tol=1e-06"
};

// The window and output spacing of the study and the bench.
struct ResponseWindow {
    std::string case_name = "joined-beam-dead";
    double end_time = 2.0;
    double output_interval = 0.002;
    int elements = 10;      // per member (the paper's mesh)
    int order = 1;          // displacement element order
    std::string mass_rule;  // displacement: "" = the case's (consistent); "midpoint" = the
                            // mixed element's inertia (the cross-formulation check)
};

ResponseWindow full_window();
ResponseWindow quick_window();  // 0–0.2 s: the --quick variants

// The run's overrides (formulation-specific keys only where they apply).
std::vector<std::string> response_overrides(const Combination& c, const TimeSetting& s,
                                            const ResponseWindow& w);
RunSpec response_spec(const Combination& c, const TimeSetting& s, const ResponseWindow& w);

// The joint's displacement at every output time of a run (empty unless converged).
History joint_history(const nlohmann::json& result);

// The Δt / tolerance sweep of a formulation (coarse → fine).
std::vector<TimeSetting> time_settings(Formulation formulation, bool quick);

// The fixed-step scheme of a formulation (generalized-α with ρ∞ = 1 | trapezoidal).
Integrator fixed_step_integrator(Formulation formulation);

struct ReferenceResponse {
    History history;                    // the extrapolated history
    std::string how;                    // in words, for the report
    double step_difference = 0.0;       // history error of the finer run against the coarser one
    double extrapolation_change = 0.0;  // history error of the finer run against the extrapolation
    double cpu_seconds = 0.0;           // to compute both runs (0 when read from the cache)
    std::string version;                // program version that computed it
    std::string status;                 // "converged" or why not
    bool from_cache = false;
};

// The same-mesh self-converged reference of a combination on window w: its fixed-step scheme at
// `coarse_step` and `coarse_step`/2, extrapolated pointwise at order 2 (both schemes are the
// trapezoidal rule for this undamped case: generalized-α with ρ∞ = 1, GEBT's fixed step); read
// from / written to `cache_dir` (empty: no cache).
ReferenceResponse same_mesh_reference(const Combination& c, const ResponseWindow& w,
                                      double coarse_step, const std::string& cache_dir);

// The coarser reference step the study and the bench use (full: 31.25 µs displacement, 125 µs
// mixed, each with its half; quick: 4× larger).
double reference_coarse_step(Formulation formulation, bool quick);

// A run the program refused because the combination's analysis does not exist (an InputError
// "not available", or run_case's `available: false`, e.g. the mixed quaternion's dynamics).
bool is_unavailable(const nlohmann::json& result);

// Newton iterations and time steps of a dynamic run (either formulation's JSON).
int dynamic_newton_iterations(const nlohmann::json& result);
long dynamic_steps(const nlohmann::json& result);

// Thread CPU time [s] of this thread (decisions on a shared machine use CPU, not wall time).
double thread_cpu_seconds();

}  // namespace rotbeam::cli
