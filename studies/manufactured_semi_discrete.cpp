#include "manufactured_semi_discrete.hpp"

#include <cmath>
#include <sstream>

#include "core/gauss_collocation.hpp"
#include "parameterizations/registry.hpp"
#include "study_math.hpp"

namespace rotbeam::cli {

SemiDiscreteSeries semi_discrete_series(const MotionRunSpec& spec) {
    SemiDiscreteSeries s;
    if (spec.formulation == Formulation::mixed) {
        s.steps = {0.05, 0.025, 0.0125};
        s.order = spec.integrator == Integrator::radau_iia_3 ? 5 : 2;
        if (s.order == 5 && spec.rotation == param::id_of<param::Rodrigues>()) {
            // Its slower motion (0 → 2 rad) is pre-asymptotic at 0.05 (F: 6.15 over 0.05/0.025);
            // at 0.00625 the errors (6e-12 in u) need the tighter Newton tolerance.
            s.steps = {0.025, 0.0125, 0.00625};
            s.newton_tolerance = 1e-14;
        }
        return s;
    }
    const int stages = gauss_legendre_stages(spec.integrator);
    if (stages == 0) {
        s.steps = {0.025, 0.0125, 0.00625};
        s.order = 2;
    } else if (stages == 2) {
        s.steps = {0.05, 0.025, 0.0125};
        s.order = 4;
    } else {
        s.steps = {0.1, 0.05, 0.025, 0.0125};
        s.newton_tolerance = 1e-14;
        s.order = 6;
    }
    return s;
}

SemiDiscreteResult run_semi_discrete_series(MotionRunSpec spec) {
    const SemiDiscreteSeries series = semi_discrete_series(spec);
    spec.semi_discrete = true;
    spec.newton_tolerance = series.newton_tolerance;
    SemiDiscreteResult out;
    for (double dt : series.steps) {
        spec.dt = dt;
        const MotionRunResult r = run_manufactured_motion(spec);
        out.steps += r.steps;
        if (!r.ok()) {
            std::ostringstream s;
            s << "Δt " << dt << " " << r.status << ": " << r.message.substr(0, 80) << "; ";
            out.note += s.str();
            continue;
        }
        out.dt.push_back(dt);
        out.error.push_back(r.semi_discrete_error);
    }
    // fit_order takes sizes n with error ∝ n^−q; a step is 1/n.
    std::vector<double> inv;
    for (double dt : out.dt) inv.push_back(1.0 / dt);
    for (int k = 0; k < kMotionComponents; ++k) {
        std::vector<double> e;
        for (ComponentDifferences& d : out.error) e.push_back(component(d, k));
        component(out.order, k) = fit_order(inv, e);
    }
    for (size_t i = 1; i < out.error.size(); ++i) {
        ComponentDifferences p;
        for (int k = 0; k < kMotionComponents; ++k) {
            component(p, k) =
                std::log2(component(out.error[i - 1], k) / component(out.error[i], k)) /
                std::log2(out.dt[i - 1] / out.dt[i]);
        }
        out.pair.push_back(p);
    }
    return out;
}

}  // namespace rotbeam::cli
