// The joined beam's 0–2 s response (docs/benchmarks.md §3, cases/joined-beam-dead.yaml and
// cases/joined-beam-follower.yaml) as the dynamic speed-versus-accuracy study and the joined-beam
// targets of `rotbeam bench` use it: one integration setting (integrator, Δt or tolerance) per
// run, the joint's displacement and rotation histories (the joint is the free end, the tip, of
// both members), and the time-converged references the errors are measured against.
//
// Two errors, kept apart (docs/studies.md, "Joined beam: dynamic speed versus accuracy"):
// - time error: a combination on the paper's mesh (10 elements per member) against its own
//   same-mesh time-converged answer — the formulation's high-order scheme (Gauss–Legendre 3,
//   order 6, for the displacement formulation; Radau IIA 3, order 5, for the mixed) at two fixed
//   steps, accepted only when they agree to kReferenceAgreement of the amplitude; what the
//   integrator and its setting control;
// - space error: the paper mesh's reference against a refined-mesh reference (displacement,
//   order 3 on the same 10 elements per member); what the mesh controls and no Δt or tolerance
//   removes.
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
    Integrator integrator;
    double time_step = 0.0;  // fixed step; adaptive runs and IDA: the first step
    // IDA: rtol = atol (analysis.relative_tolerance and absolute_tolerance); the other schemes:
    // adaptive steps with analysis.time_tolerance when > 0, fixed steps when 0.
    double tolerance = 0.0;
    // > 0: the time steps' Newton and stage-iteration tolerance (solver.residual_tolerance and
    // increment_tolerance); 0: the defaults (1e-12; the mixed formulation's time steps 1e-10,
    // core/dae_driver.hpp). It applies to the static start too.
    double newton_tolerance = 0.0;
    std::string label() const;   // "dt=0.001" | "tol=1e-06", then ", newton=1e-07" when set
    std::string scheme() const;  // "gauss-legendre-3" | "gauss-legendre-3 adaptive"
};

// The window and output spacing of the study and the bench.
struct ResponseWindow {
    std::string case_name = "joined-beam-dead";
    double end_time = 2.0;
    double output_interval = 0.002;
    int elements = 10;            // per member (the paper's mesh)
    int order = 1;                // displacement element order
    std::string mass_rule;        // displacement: "" = the case's (consistent); "midpoint" = the
                                  // mixed element's inertia (the cross-formulation check)
    std::string point = "joint";  // the case's named point whose histories are measured
};

ResponseWindow full_window();
ResponseWindow quick_window();  // 0–0.2 s: the --quick variants

// The run's overrides (formulation-specific keys only where they apply).
std::vector<std::string> response_overrides(const Combination& c, const TimeSetting& s,
                                            const ResponseWindow& w);
RunSpec response_spec(const Combination& c, const TimeSetting& s, const ResponseWindow& w);

// The joint's displacement and rotation vector (log R) at every output time of a run.
struct JointResponse {
    History displacement, rotation;
    std::size_t size() const { return displacement.size(); }
};

// Empty unless the run converged. `point`: the named point (the joined beam's joint by default).
JointResponse joint_response(const nlohmann::json& result, const std::string& point = "joint");
History joint_history(const nlohmann::json& result);  // its displacement

// The time error of a response: the larger of its displacement's and its rotation's
// history_error, each relative to the reference history's largest norm (NaN if either is).
double response_error(const JointResponse& u, const JointResponse& reference);

// The sweep of a formulation: every scheme it takes, each coarse → fine (fixed steps, then
// adaptive tolerances for the high-order schemes; IDA tolerances).
std::vector<TimeSetting> time_settings(Formulation formulation, bool quick);

// The high-order scheme of a formulation's references (Gauss–Legendre 3 | Radau IIA 3).
Integrator reference_integrator(Formulation formulation);
// The second-order fixed-step scheme of a formulation (generalized-α | trapezoidal).
Integrator fixed_step_integrator(Formulation formulation);

// Two fixed-step runs of a reference agree to this fraction of the amplitude before the finer
// one is used: 1e-2 of the 1e-3 accuracy the bench asks for, so that a measured error of 1e-3
// is off by at most 1 %.
constexpr double kReferenceAgreement = 1e-5;

struct ReferenceResponse {
    History history;                    // the joint's displacement
    History rotation;                   // the joint's rotation vector (empty: richardson_reference)
    std::string how;                    // in words, for the report
    double step_difference = kNoValue;  // history error of the coarser run against the finer one
    double extrapolation_change = kNoValue;  // richardson_reference: finer run vs extrapolation
    double cpu_seconds = 0.0;                // to compute both runs (0 when read from the cache)
    std::string version;                     // program version that computed it
    std::string status;                      // "converged" or why not
    bool from_cache = false;
    JointResponse response() const { return {history, rotation}; }
};

// The same-mesh time-converged reference of a combination on window w: the formulation's
// reference_integrator at `coarse_step` and `coarse_step`/2; "converged" when the two agree to
// `agreement` (step_difference, the response_error of the coarser run against the finer), the
// finer run being the reference (its own error, for a scheme of order ≥ 5, is below 1/30 of the
// difference). Read from / written to `cache_dir` (empty: no cache).
ReferenceResponse same_mesh_reference(const Combination& c, const ResponseWindow& w,
                                      double coarse_step, const std::string& cache_dir,
                                      double agreement = kReferenceAgreement);

// One same_mesh_reference to make: its inputs and, once made, its result.
struct ReferenceJob {
    Combination combination;
    ResponseWindow window;
    double coarse_step;
    ReferenceResponse result;
    double agreement = kReferenceAgreement;
};

// Makes every job's same_mesh_reference on `threads` threads, the job with the most time steps
// first (the coarser run's end_time / coarse_step: the costliest start first, so that the last
// one to finish is short). References are not timed, and each is two single-threaded runs, so
// the thread that makes one does not change it. A reference that cannot be written (a full disk)
// stops the others and is rethrown here (runs/parallel.hpp).
void compute_references(std::vector<ReferenceJob>& jobs, const std::string& cache_dir, int threads);

// The joint displacement's reference of the formulation's second-order fixed-step scheme
// (generalized-α with ρ∞ = 1 | the trapezoidal rule) at `coarse_step` and `coarse_step`/2,
// extrapolated pointwise at order 2 (both schemes are the trapezoidal rule for this undamped
// case). Trusted to ~1e-3 of the amplitude only (the excited higher modes keep it out of its
// asymptotic range, docs/studies.md): the formulations' agreement study uses it, where that
// suffices; the speed-versus-accuracy study and the bench do not. Cached like
// same_mesh_reference.
ReferenceResponse richardson_reference(const Combination& c, const ResponseWindow& w,
                                       double coarse_step, const std::string& cache_dir);

// The coarser reference step the study and the bench use (docs/performance.md,
// "joined-beam-dynamic", says how they were chosen).
double reference_coarse_step(Formulation formulation, bool quick);

// A run the program refused because the combination's analysis does not exist (an InputError
// "not available", or run_case's `available: false`).
bool is_unavailable(const nlohmann::json& result);

// Newton iterations and time steps of a dynamic run (either formulation's JSON).
int dynamic_newton_iterations(const nlohmann::json& result);
long dynamic_steps(const nlohmann::json& result);

// Thread CPU time [s] of this thread (decisions on a shared machine use CPU, not wall time).
double thread_cpu_seconds();

}  // namespace rotbeam::cli
