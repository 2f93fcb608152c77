// A start of the mixed dynamics far from consistency made consistent twice, for the tests that
// compare the two: by the shared Newton on the initial-condition unknowns (core/dae_driver.hpp)
// and by IDA's start (one IDA step of 1e-3 with tolerances 1e-10, its state at t₀ recorded; IDA
// starts from that Newton's state, core/dae_ida.cpp, so the two must be the same).
#pragma once

#include <boost/test/unit_test.hpp>

#include "core/dae_driver.hpp"

namespace rotbeam::test {

struct TwoInitialConditions {
    double r0 = 0.0;    // max scaled residual at the start
    double r_ic = 0.0;  // the same at IDA's start
    double dx = 0.0;    // max |X_ida − X_newton| in units of the state scale
    double dxd = 0.0;   // max |Ẋ_ida − Ẋ_newton| / max |Ẋ_newton|
    VecX x_newton, xd_newton, x_ic, xd_ic;
};

template <class Dynamics>
TwoInitialConditions consistent_twice(Dynamics& dyn, double t0, const VecX& x0, const VecX& xd0) {
    TwoInitialConditions c;
    VecX r;
    dyn.evaluate(t0, x0, xd0, r, nullptr, nullptr);
    c.r0 = (r.array() / dyn.residual_scale().array()).abs().maxCoeff();
    c.x_newton = x0;
    c.xd_newton = xd0;
    const NewtonOutcome newton = consistent_initial_conditions(dyn, t0, c.x_newton, c.xd_newton,
                                                               time_step_newton_settings(), 1e-3);
    BOOST_REQUIRE(newton.converged);
    VecX xi = x0, xdi = xd0;
    DaeSettings s;
    s.start_time = t0;
    s.end_time = t0 + 1e-3;
    s.time_step = 1e-3;
    s.relative_tolerance = 1e-10;
    s.absolute_tolerance = 1e-10;
    const DaeOutcome out =
        integrate_ida(dyn, xi, xdi, s, [&](double t, const VecX& x, const VecX& xd, int) {
            if (t == t0) {
                c.x_ic = x;
                c.xd_ic = xd;
            }
        });
    BOOST_REQUIRE(out.status == SolveStatus::converged);
    BOOST_REQUIRE(c.x_ic.size() == dyn.size());
    dyn.evaluate(t0, c.x_ic, c.xd_ic, r, nullptr, nullptr);
    c.r_ic = (r.array() / dyn.residual_scale().array()).abs().maxCoeff();
    c.dx = ((c.x_ic - c.x_newton).array() / dyn.state_scale().array()).abs().maxCoeff();
    c.dxd = (c.xd_ic - c.xd_newton).cwiseAbs().maxCoeff() / c.xd_newton.cwiseAbs().maxCoeff();
    return c;
}

}  // namespace rotbeam::test
