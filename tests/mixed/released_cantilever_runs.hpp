// Runs of Radau IIA (core/dae_radau.hpp), fixed or adaptive steps, on the free-vibration
// cantilever of docs/benchmarks.md §8 (cases/free-vibration.yaml) in the mixed formulation: 8
// elements, the rotation vector, undamped, released at rest either from the static deflection
// under the 1 N tip force (tip u_z = 1.9e-3 m: every mode of the mesh excited, the highest with
// amplitudes of 1e-8–1e-7 m, inferred in docs/mixed-dynamics.md "Radau IIA") or from its first
// bending mode (8.4 Hz) scaled to a given tip u_z (one mode; docs/mixed-dynamics.md "Radau IIA",
// orders measured). Shared by the adaptive-step test and its measurement program
// (test_mixed_radau_adaptive.cpp, bench_radau_adaptive.cpp).
#pragma once

#include <algorithm>
#include <cmath>
#include <ctime>
#include <stdexcept>
#include <vector>

#include "core/dae_driver.hpp"
#include "core/step_observer.hpp"
#include "core/time_limit.hpp"
#include "formulations/mixed/mixed_dynamics.hpp"
#include "formulations/mixed/mixed_modal.hpp"
#include "formulations/mixed/mixed_statics.hpp"
#include "parameterizations/rotation_vector.hpp"
#include "tests/cases/catalog_model.hpp"

namespace rotbeam::test {

struct ReleasedRun {
    std::vector<double> tip_z;  // tip u_z [m] at the output times (the start included)
    std::vector<double> steps;  // the accepted step sizes, in order
    DaeOutcome outcome;
    double cpu_seconds = 0.0;  // process CPU time of the integration
    bool timed_out = false;    // stopped by a ScopedTimeLimit of the caller (then: no outcome)
};

// `tolerance` > 0: adaptive steps with that time tolerance (first step `dt`); 0: fixed steps dt.
// `mode_amplitude` > 0: released from the first mode with that tip u_z; 0: from the deflection.
// Outputs every `output_interval` to `end`; the Newton tolerance of the stage equations `newton`.
// Loads are evaluated from t = 1e-9 s (the runner's 1e-6 of the case's Δt = 1e-3): the release
// is complete at every stage of the first step.
inline ReleasedRun released_cantilever_run(double tolerance, double dt, double end,
                                           double output_interval, double newton,
                                           double mode_amplitude = 0.0) {
    using P = param::RotationVector;
    const Model model =
        catalog_model("free-vibration", {"discretization.formulation=mixed",
                                         "discretization.rotation=rotation-vector",
                                         "discretization.order=1", "members.beam.elements=8"});
    form::MixedDynamics<P> dyn(model, end, 1e-9);
    form::MixedStatics<P> statics(model);
    statics.set_load_factor(mode_amplitude > 0.0 ? 0.0 : 1.0);
    if (!solve_newton(statics, NewtonSettings{}).converged) {
        throw std::runtime_error("the static state of the free-vibration case did not converge");
    }
    VecX x = dyn.from_static_state(statics.state_vector());
    if (mode_amplitude > 0.0) {
        // The mode's displacement-type part (its momentum part is imaginary: dropped, released
        // from rest), normalized by its tip u_z.
        VecX r;
        SparseMatrix A, B;
        dyn.evaluate(0.0, x, VecX::Zero(dyn.size()), r, &A, &B);
        const form::DaeModalSolution m = form::solve_dae_modal(A, B, 1);
        const VecXc phi = m.shapes[0] / m.shapes[0][dyn.node_column(1) + 2];
        x += mode_amplitude * phi.real();
        const form::MixedNumbering& nb = dyn.numbering();
        for (int e = 0; e < nb.element_count; ++e)
            x.segment<6>(nb.element_column(e) + nb.P()).setZero();
    }
    VecX xdot = VecX::Zero(dyn.size());
    DaeSettings s;
    s.end_time = end;
    s.time_step = dt;
    s.output_interval = output_interval;
    s.time_tolerance = tolerance;
    s.newton.residual_tolerance = newton;
    s.newton.increment_tolerance = newton;
    ReleasedRun run;
    double last = 0.0;
    struct Recorder {
        ReleasedRun& run;
        double& last;
    } recorder{run, last};
    const ScopedStepObserver observe(
        [](void* c, const StepProgress& p) {
            auto& r = *static_cast<Recorder*>(c);
            r.run.steps.push_back(p.time - r.last);
            r.last = p.time;
        },
        &recorder);
    const std::clock_t start = std::clock();
    try {
        run.outcome =
            integrate_radau_iia(dyn, x, xdot, s, [&](double t, const VecX& xs, const VecX&, int) {
                run.tip_z.push_back(dyn.point_state(xs, t, 1).displacement.z());
            });
    } catch (const TimeLimitReached&) {
        run.timed_out = true;
    }
    run.cpu_seconds = static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
    return run;
}

// max_k |a_k − b_k| over the common output times (the same grid).
inline double max_difference(const std::vector<double>& a, const std::vector<double>& b) {
    double d = 0.0;
    for (std::size_t k = 0; k < std::min(a.size(), b.size()); ++k)
        d = std::max(d, std::abs(a[k] - b[k]));
    return d;
}

}  // namespace rotbeam::test
