// Cost and accuracy of the displacement dynamics: the joined beam (docs/benchmarks.md
// §3, cases/joined-beam-dead.yaml) over 0–2 s at the case's Δt = 1 ms, for every
// parameterization, with the case's mesh (10 linear elements per member) and a p-refined one
// (10 elements of order 3 per member), and the p-refined one at Δt = 0.25 ms. Accuracy: max over
// the history of |u_joint − u_ref| over max |u_ref|, against quaternion, 10 elements of order 4 per
// member, Δt = 62.5 µs (at 1 ms the time error dominates: ~13 % of max |u|).
// A benchmark, not a test: built, not registered with CTest. Timings are only comparable on an
// otherwise idle machine.
#include <chrono>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "cases/loader/case_loader.hpp"
#include "core/generalized_alpha.hpp"
#include "formulations/displacement/displacement_dynamics.hpp"
#include "parameterizations/registry.hpp"

using namespace rotbeam;

namespace {

struct Run {
    std::vector<Vec3> joint;  // every 1 ms
    double seconds = 0.0;
    long newton = 0;
    int dofs = 0;
    std::string status;
};

template <class P>
Run simulate(Model m, int order, double dt) {
    m.discretization.order = order;
    Run run;
    const auto start = std::chrono::steady_clock::now();
    form::DisplacementDynamics<P> d(m);
    run.dofs = d.size();
    TimeIntegrationSettings ts;
    ts.time_step = dt;
    ts.end_time = m.analysis.dynamics.end_time;
    ts.output_interval = 1e-3;
    ts.rho_infinity = m.analysis.dynamics.rho_infinity;
    const int joint = m.point_index("joint");
    const DynamicOutcome out = run_generalized_alpha(
        d, ts, newton_settings_from(m.solver, m.analysis.statics),
        [&](const TimeStepRecord&) { run.joint.push_back(d.point_state(joint).displacement); });
    run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    run.newton = out.newton_iterations;
    run.status = to_string(out.status);
    return run;
}

double history_error(const Run& a, const Run& ref) {
    double err = 0.0, peak = 0.0;
    for (size_t k = 0; k < std::min(a.joint.size(), ref.joint.size()); ++k) {
        err = std::max(err, (a.joint[k] - ref.joint[k]).cwiseAbs().maxCoeff());
        peak = std::max(peak, ref.joint[k].cwiseAbs().maxCoeff());
    }
    return err / peak;
}

}  // namespace

int main() {
    const Model m = load_case(std::string(ROTBEAM_SOURCE_DIR) + "/cases/joined-beam-dead.yaml");
    std::printf(
        "joined beam, dead F_z = 1e5 sin(20 t) N, 0-2 s, generalized-alpha rho_inf = %.2f\n",
        m.analysis.dynamics.rho_infinity);
    const Run ref = simulate<param::Quaternion>(m, 4, 6.25e-5);
    std::printf("reference: quaternion, p = 4, dt = 62.5 us, %d unknowns, %.2f s (%s)\n", ref.dofs,
                ref.seconds, ref.status.c_str());
    std::printf("%-18s %3s %8s %6s %9s %8s %12s\n", "rotation", "p", "dt [ms]", "dofs", "wall [s]",
                "newton", "max|du|/max|u|");
    const double dt = m.analysis.dynamics.time_step;
    param::for_each_parameterization([&]<class P>() {
        for (const auto& [order, step] :
             {std::pair{1, dt}, std::pair{3, dt}, std::pair{3, dt / 4}}) {
            const Run r = simulate<P>(m, order, step);
            std::printf("%-18s %3d %8.3f %6d %9.3f %8ld %12.3e  %s\n",
                        std::string(P::kName).c_str(), order, 1e3 * step, r.dofs, r.seconds,
                        r.newton, history_error(r, ref), r.status.c_str());
            std::fflush(stdout);
        }
    });
    return 0;
}
