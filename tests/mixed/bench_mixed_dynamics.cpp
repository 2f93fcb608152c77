// Cost vs accuracy of the mixed dynamics' two integrators on the joined beam (docs/benchmarks.md
// §3: dead joint force 1e5 sin(20 t) N from rest, 10 WM elements per member, 486 unknowns) over
// 0–T (T = 0.5 s by default, argv[1]): IDA (BDF ≤ 2) at several tolerances and the fixed-step
// trapezoidal scheme at several Δt. Accuracy: the joint displacement at every 0.01 s against a
// self-converged reference (Richardson extrapolation of the fixed-step runs at Δt = 1e-3/16 and
// 1e-3/32, order 2), as max ‖Δu‖ over the outputs divided by the largest ‖u‖. Wall time per run.
// A benchmark, not a test: run it on an idle machine.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "core/dae_driver.hpp"
#include "formulations/mixed/mixed_dynamics.hpp"
#include "parameterizations/wiener_milenkovic.hpp"
#include "tests/mixed/models.hpp"

using namespace rotbeam;

namespace {

Model joined_beam_dead(int n) {
    Model m;
    m.points = {{"root1", Vec3(0, -0.5, 0)}, {"root2", Vec3(0, 0.5, 0)}, {"joint", Vec3(1, 0, 0)}};
    const double E = 70e9, G = E / 2.7, b = 0.1, h = 0.05, A = b * h, k = 5.0 / 6.0, rho = 2700;
    const double I2 = b * h * h * h / 12.0, I3 = h * b * b * b / 12.0, J = 0.229 * b * h * h * h;
    Section s = test::diagonal_section(
        (Vec6() << E * A, k * G * A, k * G * A, G * J, E * I2, E * I3).finished());
    s.mass = Mat6((Vec6() << rho * A, rho * A, rho * A, rho * (I2 + I3), rho * I2, rho * I3)
                      .finished()
                      .asDiagonal());
    m.members = {test::member("m1", 0, 2, s, n), test::member("m2", 1, 2, s, n)};
    m.constraints = {Constraint{0, Constraint::Kind::clamped, Vec3::Zero(), Vec3::Zero(), {}},
                     Constraint{1, Constraint::Kind::clamped, Vec3::Zero(), Vec3::Zero(), {}}};
    PointLoad f;
    f.point = 2;
    f.force = Vec3(0, 0, 1e5);
    f.time.kind = TimeFunction::Kind::sine;
    f.time.omega = 20.0;
    m.point_loads = {f};
    return m;
}

struct Run {
    std::vector<Vec3> joint;  // every 0.01 s
    double seconds = 0.0;
    long steps = 0;
    bool ok = false;
};

Run run(bool ida, double parameter, double end) {
    const Model model = joined_beam_dead(10);
    form::MixedDynamics<param::WienerMilenkovic> dyn(model, end);
    VecX x = VecX::Zero(dyn.size()), xdot = VecX::Zero(dyn.size());
    DaeSettings s;
    s.end_time = end;
    s.output_interval = 0.01;
    s.time_step = ida ? 0.01 : parameter;
    s.relative_tolerance = parameter;
    s.absolute_tolerance = parameter;
    Run r;
    const auto start = std::chrono::steady_clock::now();
    const DaeOutcome out = (ida ? integrate_ida : integrate_trapezoidal)(
        dyn, x, xdot, s, [&](double t, const VecX& xs, const VecX&, int) {
            r.joint.push_back(dyn.point_state(xs, t, 2).displacement);
        });
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    r.steps = out.steps;
    r.ok = out.status == SolveStatus::converged;
    if (!r.ok) std::printf("  failed: %s\n", out.message.c_str());
    return r;
}

double relative_error(const Run& r, const std::vector<Vec3>& reference) {
    double err = 0.0, peak = 0.0;
    for (std::size_t i = 0; i < reference.size(); ++i) {
        err = std::max(err, (r.joint[i] - reference[i]).norm());
        peak = std::max(peak, reference[i].norm());
    }
    return err / peak;
}

}  // namespace

int main(int argc, char** argv) {
    const double end = argc > 1 ? std::atof(argv[1]) : 0.5;
    std::printf("joined beam (dead), 10 WM elements per member, 0–%g s\n", end);
    const Run fine = run(false, 1e-3 / 32, end);
    const Run coarse = run(false, 1e-3 / 16, end);
    if (!fine.ok || !coarse.ok) return 1;
    std::vector<Vec3> reference(fine.joint.size());
    for (std::size_t i = 0; i < reference.size(); ++i) {
        reference[i] = fine.joint[i] + (fine.joint[i] - coarse.joint[i]) / 3.0;
    }
    std::printf("reference: Richardson of Δt = 3.125e-5 and 6.25e-5 (their difference %.3e)\n",
                relative_error(coarse, fine.joint));
    std::printf("%-12s %10s %10s %10s %12s\n", "integrator", "parameter", "steps", "wall [s]",
                "rel. error");
    for (const double tol : {1e-3, 1e-4, 1e-5, 1e-6, 1e-7}) {
        const Run r = run(true, tol, end);
        if (r.ok) {
            std::printf("%-12s %10.0e %10ld %10.3f %12.3e\n", "ida", tol, r.steps, r.seconds,
                        relative_error(r, reference));
        }
    }
    for (const double dt : {4e-3, 2e-3, 1e-3, 5e-4, 2.5e-4}) {
        const Run r = run(false, dt, end);
        if (r.ok) {
            std::printf("%-12s %10.2e %10ld %10.3f %12.3e\n", "trapezoidal", dt, r.steps, r.seconds,
                        relative_error(r, reference));
        }
    }
    return 0;
}
