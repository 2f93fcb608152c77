// The displacement dynamics run as `rotbeam run` runs it (runs/run_displacement_dynamics.cpp),
// for the time-integration tests: a static start at the loads of t = 0 when the case asks for it,
// then generalized-α or Gauss–Legendre collocation to the end, and the tip state at the end; and
// the first mode of the unloaded model at rest, to start a motion in it.
#pragma once

#include <boost/test/unit_test.hpp>
#include <string>
#include <vector>

#include "core/gauss_collocation_predictor.hpp"
#include "core/generalized_alpha.hpp"
#include "core/so3.hpp"
#include "core/static_driver.hpp"
#include "formulations/displacement/displacement_dynamics.hpp"
#include "formulations/displacement/displacement_modal.hpp"

namespace rotbeam::test {

struct TipHistory {
    Vec3 u = Vec3::Zero();
    Mat3 R = Mat3::Identity();
    std::vector<double> energy;  // total energy at every output (when recorded)
    long newton_iterations = 0;  // Newton or stage iterations, summed over the steps
    std::string message;         // the run's
};

// The time scheme: `stages` > 0 the Gauss–Legendre collocation with that many stages, else
// generalized-α with `rho_infinity`; `stage_predictor` and `keep_matrices` as
// run_gauss_collocation's GaussOptions (core/gauss_collocation_predictor.hpp).
struct TimeScheme {
    int stages = 0;
    double rho_infinity = 1.0;
    bool stage_predictor = true;
    bool keep_matrices = true;
};

// Outputs every `output` (0: every step); the energy recorded at each when `record_energy`.
template <class P>
TipHistory simulate(const Model& model, TimeScheme scheme, double dt, double end, double output,
                    bool record_energy) {
    form::DisplacementDynamics<P> d(model);
    const NewtonSettings newton = newton_settings_from(model.solver, model.analysis.statics);
    if (model.analysis.dynamics.initial_state == InitialState::static_equilibrium) {
        d.statics().set_time(0.0);
        const StaticOutcome s = run_static(d.statics(), {1.0}, newton, {});
        BOOST_TEST_REQUIRE(has_solution(s.status));
        d.adopt_static_state();
    }
    TimeIntegrationSettings ts;
    ts.time_step = dt;
    ts.end_time = end;
    ts.output_interval = output;
    ts.rho_infinity = scheme.rho_infinity;
    TipHistory h;
    const auto on_output = [&](const TimeStepRecord&) {
        if (record_energy) h.energy.push_back(d.energy().total());
    };
    const DynamicOutcome out =
        scheme.stages > 0
            ? run_gauss_collocation(d, scheme.stages, ts, newton, on_output,
                                    GaussOptions{scheme.stage_predictor, scheme.keep_matrices})
            : run_generalized_alpha(d, ts, newton, on_output);
    BOOST_TEST_REQUIRE(has_solution(out.status), out.message);
    const int tip = model.point_index("tip");
    h.u = d.point_state(tip).displacement;
    h.R = d.point_state(tip).rotation;
    h.newton_iterations = out.newton_iterations;
    h.message = out.message;
    return h;
}

// The first mode of the unloaded model in its reference configuration (rotations the identity).
inline form::ModalSolution first_mode_at_rest(
    const Model& m, form::DisplacementDynamics<param::RotationVector>& d) {
    VecX r;
    SparseMatrix K;
    d.statics().evaluate(r, &K);
    const SparseMatrix M = form::assemble_mass_matrix(m, form::build_mass_mesh(m),
                                                      [](int) { return Mat3::Identity(); });
    return form::solve_modal(K, M, 1);
}

}  // namespace rotbeam::test
