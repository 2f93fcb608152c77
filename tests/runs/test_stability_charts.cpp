// The stability verdict of a deformed static equilibrium does not depend on the rotation
// parameterization (docs/solver-convergence.md, Stability of the equilibrium). The BeamDyn gravity
// cantilever (tests/data/beamdyn/bd_static_cantilever_beam: EI = 100 N m² about both axes,
// GJ = 200 N m², 1 kg/m, L = 10 m, one element of order 5) bends under its weight to a tip
// rotation of 1.54 rad about y — the Euler angles' middle angle 0.03 rad from gimbal lock. Its
// section is isotropic (EI equal about both axes), so no lateral-torsional buckling exists
// (Prandtl's critical load grows as 1/√(1 − EI_weak/EI_strong) → ∞) and the bent state is stable:
// the independent answer every parameterization must give. The energy the verdict reads
// interpolates the nodal rotations as quaternions in every parameterization
// (displacement_statics_energy.hpp); interpolated in the parameterization itself the Euler-angle
// energy read one negative eigenvalue here, the other four none.
#define BOOST_TEST_MODULE rotbeam stability charts
#include <Eigen/Dense>
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "cases/loader/case_loader.hpp"
#include "core/potential_hessian.hpp"
#include "core/static_driver.hpp"
#include "core/static_stability.hpp"
#include "formulations/displacement/displacement_statics.hpp"
#include "parameterizations/registry.hpp"
#include "runs/make_problem.hpp"
#include "runs/run_case.hpp"

using namespace rotbeam;

namespace {

std::string cantilever_deck() {
    return std::string(ROTBEAM_SOURCE_DIR) +
           "/tests/data/beamdyn/bd_static_cantilever_beam/bd_driver.inp";
}

// The nodal state of a solved problem: displacements and rotation matrices.
struct NodalState {
    std::vector<Vec3> u;
    std::vector<Mat3> R;
};

struct ChartMeasure {
    Eigen::MatrixXd S;  // D H D
    double scaled_error = 0.0;
    double energy = 0.0;
    int negative = 0;  // dense eigenvalues below −max(n ε, scaled_error)
};

// Solves the cantilever in P; with `state`, puts P's nodes at that state (the same rotations in
// P's chart) and measures there, otherwise measures at P's own equilibrium and returns it.
template <class P>
ChartMeasure measure_chart(NodalState& state, bool at_given_state) {
    const Model m =
        load_case(cantilever_deck(), {"discretization.rotation=" + std::string(P::kName)});
    std::unique_ptr<StaticProblem> problem = make_static_problem(m);
    auto& p = dynamic_cast<form::DisplacementStatics<P>&>(*problem);
    const StaticOutcome o = run_static(p, m.analysis.statics.load_factors, NewtonSettings{}, {});
    BOOST_TEST_REQUIRE(has_solution(o.status), o.message);
    const int nodes = static_cast<int>(p.mesh().nodes.size());
    if (at_given_state) {
        for (int i = 0; i < nodes; ++i) p.set_node_state(i, state.u[i], P::from_matrix(state.R[i]));
    } else {
        state = {};
        for (int i = 0; i < nodes; ++i) {
            state.u.push_back(p.node_displacement(i));
            state.R.push_back(P::matrix(p.node_rotation(i)));
        }
    }
    ChartMeasure c;
    c.energy = *p.potential_energy();
    const PotentialHessian H = p.potential_hessian();
    BOOST_TEST_REQUIRE(H.unavailable.empty(), H.unavailable);
    const VecX d = p.increment_scale();
    c.S = d.asDiagonal() * Eigen::MatrixXd(H.matrix) * d.asDiagonal();
    c.scaled_error = H.scaled_error;
    const Eigen::VectorXd ev = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(c.S).eigenvalues();
    const double tiny =
        std::max(static_cast<double>(ev.size()) * std::numeric_limits<double>::epsilon() *
                     c.S.cwiseAbs().maxCoeff(),
                 H.scaled_error);
    for (Eigen::Index i = 0; i < ev.size(); ++i) c.negative += ev(i) < -tiny ? 1 : 0;
    std::printf(
        "%-18s %s: energy %.14e, smallest scaled eigenvalues %.4e %.4e, largest %.4e, "
        "difference error %.1e\n",
        std::string(P::kName).c_str(),
        at_given_state ? "at the rotation-vector state" : "at its own equilibrium", c.energy, ev(0),
        ev(1), ev(ev.size() - 1), H.scaled_error);
    return c;
}

std::vector<std::string> every_rotation() {
    std::vector<std::string> names;
    for (const std::string& n : param::parameterization_names()) names.push_back(n);
    return names;
}

// Every step's (assessment, negative eigenvalues) of a run.
std::vector<std::pair<std::string, int>> verdicts(const std::string& path,
                                                  const std::vector<std::string>& set) {
    const nlohmann::json r = run_case(RunRequest{path, load_case(path, set)});
    std::vector<std::pair<std::string, int>> out;
    for (const auto& step : r["steps"]) {
        const auto& s = step["stability"];
        out.emplace_back(
            s["assessment"].get<std::string>(),
            s.contains("negative_eigenvalues") ? s["negative_eigenvalues"].get<int>() : -1);
    }
    return out;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(stability_charts)

// At one nodal state (the rotation-vector equilibrium, set into every parameterization's nodes)
// the energy and the scaled Hessian are the same function's in every parameterization: they may
// differ only by each Hessian's own difference error (its reported scaled_error, the inter-node
// asymmetry and the h/2h difference of its central differences) and the round-off of carrying
// the rotations through P's chart (P::from_matrix, then P::matrix: ~ε/cos a2 ≈ 1e-14 for the
// Euler angles here, which the central difference at h = ε^(1/3) ≈ 6e-6 divides by 2h: ~1e-9 of
// the entries at worst, below the 1e-8 relative tolerance; measured 1.0e-12 … 1.9e-12, while each
// parameterization's own energy moved the smallest eigenvalue by 7e-6 of the largest). The energies
// agree to 1e-12 relative (a sum of ~30 quadrature terms of mixed sign, each to a few ε). Before
// the energy interpolated as quaternions, the Euler angles' Hessian here had a negative eigenvalue
// the rotation vector's did not.
BOOST_AUTO_TEST_CASE(energy_and_hessian_are_chart_free_at_one_state) {
    NodalState state;
    const ChartMeasure reference = measure_chart<param::RotationVector>(state, false);
    BOOST_TEST(reference.negative == 0);
    const double norm = reference.S.cwiseAbs().maxCoeff();
    const std::vector<ChartMeasure> others = {measure_chart<param::Quaternion>(state, true),
                                              measure_chart<param::WienerMilenkovic>(state, true),
                                              measure_chart<param::Rodrigues>(state, true),
                                              measure_chart<param::EulerAngles>(state, true)};
    for (const ChartMeasure& c : others) {
        const double difference = (c.S - reference.S).cwiseAbs().maxCoeff() / norm;
        std::printf("  Hessian difference to the rotation vector's: %.2e of the largest entry\n",
                    difference);
        BOOST_TEST(std::abs(c.energy - reference.energy) <= 1e-12 * std::abs(reference.energy));
        BOOST_TEST(difference <= 1e-8 + (c.scaled_error + reference.scaled_error) / norm);
        BOOST_TEST(c.negative == reference.negative);
    }
}

// The run's verdict at every step, in every parameterization: `stable` with no negative
// eigenvalue (the isotropic section above). Before the energy interpolated as quaternions the
// Euler angles read `unstable-equilibrium`, 1 negative eigenvalue, at λ = 1. (`direct`
// interpolation is not compared: there the parameterizations reach different equilibria — the
// Euler angles' tip 1.4 m from the quaternion's, the rotation vector's a wrapped state with nodal
// angles of 14.9 rad — so a verdict on each is a verdict on a different state.)
BOOST_AUTO_TEST_CASE(gravity_cantilever_reads_stable_in_every_parameterization) {
    for (const std::string& rotation : every_rotation()) {
        BOOST_TEST_CONTEXT(rotation) {
            const auto v = verdicts(cantilever_deck(), {"discretization.rotation=" + rotation});
            BOOST_TEST_REQUIRE(!v.empty());
            for (const auto& [assessment, negative] : v) {
                BOOST_TEST(assessment == "stable");
                BOOST_TEST(negative == 0);
            }
        }
    }
}

// A strongly deformed state with an instability: Prandtl's deep strip (the case of
// test_potential_hessian.cpp: L = 1 m, 0.01 × 0.1 m steel, 8 quadratic elements, P_cr = 8535 N
// from Timoshenko & Gere §6.3 with the pre-buckling deflection factor) at 0.9 P_cr is stable and
// at 1.1 P_cr has exactly one unstable direction (the lateral-torsional mode; the next critical
// load is far above), in every parameterization; and the Bathe–Bolourchi 45° bend, a 3-D state
// with rotations of ~1 rad, is stable at every published load (it buckles at none) in every
// parameterization.
BOOST_AUTO_TEST_CASE(deformed_states_have_the_same_inertia_in_every_parameterization) {
    const std::string strip = std::string(ROTBEAM_SOURCE_DIR) + "/cases/tip-load-cantilever.yaml";
    const std::string bend = std::string(ROTBEAM_SOURCE_DIR) + "/cases/bend-45.yaml";
    for (const std::string& rotation : every_rotation()) {
        for (const auto& [load, negative] :
             {std::pair{0.9 * 8535.0, 0}, std::pair{1.1 * 8535.0, 1}}) {
            BOOST_TEST_CONTEXT(rotation << ", strip at " << load << " N") {
                const auto v = verdicts(
                    strip,
                    {"discretization.rotation=" + rotation, "sections.square.isotropic.A=1e-3",
                     "sections.square.isotropic.I2=8.333333333333333e-7",
                     "sections.square.isotropic.I3=8.333333333333333e-9",
                     "sections.square.isotropic.J=3.1233e-8", "discretization.quadrature=reduced",
                     "discretization.order=2", "members.beam.elements=8",
                     "loads.tip-force.force=[0,0," + std::to_string(load) + "]",
                     "analysis.load_factors=[0.5,1.0]"});
                BOOST_TEST_REQUIRE(v.size() == 2u);
                BOOST_TEST(v[0].first == "stable");
                BOOST_TEST(v[1].first == (negative == 0 ? "stable" : "unstable"));
                BOOST_TEST(v[1].second == negative);
            }
        }
        BOOST_TEST_CONTEXT(rotation << ", 45° bend") {
            const auto v = verdicts(bend, {"discretization.rotation=" + rotation});
            BOOST_TEST_REQUIRE(v.size() == 3u);
            for (const auto& [assessment, negative] : v) {
                BOOST_TEST(assessment == "stable");
                BOOST_TEST(negative == 0);
            }
        }
    }
}

BOOST_AUTO_TEST_SUITE_END()
