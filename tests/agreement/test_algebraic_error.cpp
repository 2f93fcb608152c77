// The algebraic error a Newton acceptance leaves (docs/solver-convergence.md): catalog cases solved
// with residual_tolerance = increment_tolerance = 1e-2, 1e-4, …, 1e-10 are compared, step by
// step, with the same mesh solved at 1e-13. The error is measured in the norm the bound speaks
// of: the scaled max norm of the state difference over every unknown (displacements by the length
// scale, rotation increments log(R Rₒᵀ) by 1, mixed unknowns by their increment scales).
//
// Asserted for every reported step: (1) the error is within the step's reported bound plus the
// reference step's (the reference is itself only known to its bound) plus the states' rounding;
// (2) the step's bound is within increment_tolerance, so no accepted result exceeds the
// documented bound. Measured (printed): at 1e-2 errors 1e-8 … 2e-6 against bounds 5e-4 … 1e-2;
// the final correction leaves far less than its own size.
#include <boost/test/unit_test.hpp>
#include <cstdio>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "cases/loader/case_loader.hpp"
#include "core/so3.hpp"
#include "core/static_driver.hpp"
#include "formulations/displacement/displacement_statics.hpp"
#include "formulations/mixed/mixed_statics_of.hpp"

using namespace rotbeam;

namespace {

// One reported step: its record and the state snapshot the error is measured on.
struct Snapshot {
    StepRecord record;
    std::vector<Vec3> u;  // displacement formulation: free-node displacements
    std::vector<Mat3> R;  // ... and rotations
    VecX x;               // mixed formulation: the state vector
};

struct Run {
    StaticOutcome outcome;
    std::vector<Snapshot> steps;
    std::function<double(const Snapshot&, const Snapshot&)> error;  // scaled max norm
};

Model catalog(const std::string& name, double tolerance) {
    Model m = load_case(std::string(ROTBEAM_SOURCE_DIR) + "/cases/" + name + ".yaml");
    m.solver.residual_tolerance = tolerance;
    m.solver.increment_tolerance = tolerance;
    return m;
}

template <class P>
Run displacement_run(const Model& m) {
    form::DisplacementStatics<P> problem(m);
    Run run;
    const form::Mesh& mesh = problem.mesh();
    run.outcome =
        run_static(problem, m.analysis.statics.load_factors,
                   newton_settings_from(m.solver, m.analysis.statics), [&](const StepRecord& r) {
                       Snapshot s{r, {}, {}, {}};
                       for (size_t i = 0; i < mesh.nodes.size(); ++i) {
                           if (mesh.nodes[i].dof < 0) continue;
                           const int n = static_cast<int>(i);
                           s.u.push_back(problem.node_displacement(n));
                           s.R.push_back(P::matrix(problem.node_rotation(n)));
                       }
                       run.steps.push_back(s);
                   });
    const double L = problem.length_scale();
    run.error = [L](const Snapshot& a, const Snapshot& b) {
        double e = 0.0;
        for (size_t i = 0; i < a.u.size(); ++i) {
            e = std::max(e, (a.u[i] - b.u[i]).cwiseAbs().maxCoeff() / L);
            e = std::max(e, so3::log_map(a.R[i] * b.R[i].transpose()).cwiseAbs().maxCoeff());
        }
        return e;
    };
    return run;
}

template <class P>
Run mixed_run(const Model& m) {
    form::MixedStaticsOf<P> problem(m);
    Run run;
    run.outcome =
        run_static(problem, m.analysis.statics.load_factors,
                   newton_settings_from(m.solver, m.analysis.statics), [&](const StepRecord& r) {
                       run.steps.push_back({r, {}, {}, problem.state_vector()});
                   });
    const VecX scale = problem.increment_scale();
    run.error = [scale](const Snapshot& a, const Snapshot& b) {
        return ((a.x - b.x).array() / scale.array()).abs().maxCoeff();
    };
    return run;
}

using Runner = std::function<Run(const Model&)>;

// Two floating-point states of the same solution differ by their rounding: displacements of the
// length scale and rotation matrices rounded entry by entry to ε, whose product's log carries a few
// ε. 64 ε = 1.4e-14 covers the largest difference measured between states both accepted at their
// round-off floor (7.5e-15, roll-up, rotation vector) twice.
constexpr double kStateRoundOff = 64.0 * std::numeric_limits<double>::epsilon();

// The assertions of the file comment, for one combination on one catalog case.
void check_error_within_bound(const std::string& label, const std::string& name,
                              const Runner& runner) {
    const Run reference = runner(catalog(name, 1e-13));
    BOOST_TEST_REQUIRE(has_solution(reference.outcome.status), reference.outcome.message);
    BOOST_TEST_REQUIRE(reference.steps.size() ==
                       catalog(name, 1e-13).analysis.statics.load_factors.size());
    for (double tolerance = 1e-2; tolerance >= 1e-10; tolerance *= 1e-2) {
        const Run run = runner(catalog(name, tolerance));
        BOOST_TEST_REQUIRE(has_solution(run.outcome.status), label << ": " << run.outcome.message);
        BOOST_TEST_REQUIRE(run.steps.size() == reference.steps.size());
        double worst = 0.0, worst_bound = 0.0;
        for (size_t k = 0; k < run.steps.size(); ++k) {
            const StepRecord& r = run.steps[k].record;
            const double error = run.error(run.steps[k], reference.steps[k]);
            const double allowed =
                r.error_bound + reference.steps[k].record.error_bound + kStateRoundOff;
            BOOST_TEST(error <= allowed, label << " " << name << " tol " << tolerance << " step "
                                               << k + 1 << " (" << to_string(r.criterion)
                                               << "): error " << error << " > bound " << allowed);
            BOOST_TEST(r.error_bound <= tolerance, label << " " << name << " tol " << tolerance
                                                         << " step " << k + 1 << ": bound "
                                                         << r.error_bound);
            worst = std::max(worst, error);
            worst_bound = std::max(worst_bound, r.error_bound);
        }
        std::printf("%-24s %-18s tol %.0e: %-21s max error %.2e, max bound %.2e\n", label.c_str(),
                    name.c_str(), tolerance, to_string(run.outcome.status), worst, worst_bound);
    }
}

}  // namespace

BOOST_AUTO_TEST_SUITE(algebraic_error)

// The 45° bend (16 × p2, ten sub-steps per reported load) and the roll-up to λ = 2 (16 × p4, a
// full turn at the tip), catalog meshes and load paths.
BOOST_AUTO_TEST_CASE(displacement_formulation_error_is_within_the_reported_bound) {
    for (const char* name : {"bend-45", "cantilever-moment"}) {
        check_error_within_bound("displacement quaternion", name, [](const Model& m) {
            return displacement_run<param::Quaternion>(m);
        });
        check_error_within_bound("displacement rotation-vector", name, [](const Model& m) {
            return displacement_run<param::RotationVector>(m);
        });
    }
}

// Mixed: the quaternion on both cases; Wiener–Milenković on the bend only (with 16 elements its
// plain map has no solution on the roll-up past λ ≈ 1.87, docs/mixed-formulation.md).
BOOST_AUTO_TEST_CASE(mixed_formulation_error_is_within_the_reported_bound) {
    for (const char* name : {"bend-45", "cantilever-moment"}) {
        check_error_within_bound("mixed quaternion", name,
                                 [](const Model& m) { return mixed_run<param::Quaternion>(m); });
    }
    check_error_within_bound("mixed wiener-milenkovic", "bend-45",
                             [](const Model& m) { return mixed_run<param::WienerMilenkovic>(m); });
}

BOOST_AUTO_TEST_SUITE_END()
