// Modal analysis of the displacement formulation (issue 6 point 3): a straight cantilever
// converges to the Timoshenko clamped–free frequencies (core/oracles/timoshenko.hpp, shear and
// rotary inertia included), for every mass rule, and a follower load makes K non-symmetric so the
// QZ path is taken. The joined beam's Table III (ANSYS column, 10 linear elements, one-point
// stiffness, consistent mass) is gated by `rotbeam verify`.
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <string>

#include "core/oracles/timoshenko.hpp"
#include "core/static_driver.hpp"
#include "formulations/displacement/displacement_modal.hpp"
#include "formulations/displacement/displacement_statics.hpp"
#include "parameterizations/quaternion.hpp"
#include "parameterizations/rotation_vector.hpp"
#include "tests/displacement/models.hpp"

using namespace rotbeam;

namespace {

// The §7/§8 steel cantilever: L = 1 m, square 0.01 m, E = 2.1e11, ν = 0.3, κ = 5/6, ρ = 7850.
constexpr double kE = 2.1e11, kG = 2.1e11 / 2.6, kA = 1e-4, kI = 1e-8 / 12.0, kRho = 7850.0;
constexpr double kKappa = 5.0 / 6.0;

Model steel_cantilever(int elements, int order, const std::string& mass_rule) {
    Section s = test::diagonal_section(kE * kA, kKappa * kG * kA, kKappa * kG * kA,
                                       kG * 0.140577e-8, kE * kI, kE * kI);
    Vec6 m;
    m << kRho * kA, kRho * kA, kRho * kA, 2.0 * kRho * kI, kRho * kI, kRho * kI;
    s.mass = Mat6(m.asDiagonal());
    Model model = test::cantilever(Vec3(1, 0, 0), s, elements, order);
    model.discretization.mass_rule = mass_rule;
    return model;
}

template <class P>
form::ModalSolution modes_of(const Model& model, int count) {
    form::DisplacementStatics<P> problem(model);
    VecX r;
    SparseMatrix K;
    problem.evaluate(r, &K);
    const SparseMatrix M = form::assemble_mass_matrix(
        model, form::build_mass_mesh(model),
        [&](int node) { return P::matrix(problem.node_rotation(node)); });
    return form::solve_modal(K, M, count);
}

std::vector<double> timoshenko_hz(int count) {
    oracle::TimoshenkoBeam b;
    b.length = 1.0;
    b.bending_stiffness = kE * kI;
    b.shear_stiffness = kKappa * kG * kA;
    b.mass_per_length = kRho * kA;
    b.rotary_inertia = kRho * kI;
    std::vector<double> f = oracle::timoshenko_cantilever_frequencies(b, count);
    for (double& x : f) x /= 2.0 * kPi;
    return f;
}

// Largest relative difference of the bending pairs (the square section doubles each frequency:
// modes 2k and 2k+1 bend in the two planes) from the oracle's first `count` frequencies.
double worst_pair_error(const form::ModalSolution& s, const std::vector<double>& oracle) {
    double worst = 0.0;
    for (size_t k = 0; k < oracle.size(); ++k) {
        for (size_t j : {2 * k, 2 * k + 1}) {
            worst = std::max(worst, std::abs(s.frequencies_hz[j] - oracle[k]) / oracle[k]);
        }
    }
    return worst;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(displacement_modal)

// The lowest four bending frequencies (8.35 … 287 Hz; torsion and extension start near 700 Hz),
// 8 elements, p-refinement with consistent and lumped (GLL) mass. Measured worst relative errors:
// p = 2 (reduced stiffness quadrature) 6.9e-3 / 3.7e-3, p = 4 2.7e-5, p = 6 1.0e-9 / 4.9e-9,
// p = 8 1.6e-8 / 6.5e-9 — the floor of the dense generalized eigensolver on a stiffness whose
// condition grows like (EA/EI)·(p²N)⁴. Asserted: p = 6 within 1e-7 for two parameterizations and
// both rules, and p-refinement from 2 to 4 gaining more than two orders.
BOOST_AUTO_TEST_CASE(cantilever_frequencies_match_timoshenko) {
    const std::vector<double> oracle = timoshenko_hz(4);
    for (int p : {2, 4, 6, 8}) {
        BOOST_TEST_MESSAGE("p = " << p << ": consistent "
                                  << worst_pair_error(modes_of<param::Quaternion>(
                                                          steel_cantilever(8, p, "consistent"), 8),
                                                      oracle)
                                  << ", lumped "
                                  << worst_pair_error(modes_of<param::Quaternion>(
                                                          steel_cantilever(8, p, "lumped"), 8),
                                                      oracle));
    }
    const form::ModalSolution q =
        modes_of<param::Quaternion>(steel_cantilever(8, 6, "consistent"), 8);
    const form::ModalSolution l = modes_of<param::Quaternion>(steel_cantilever(8, 6, "lumped"), 8);
    const form::ModalSolution v =
        modes_of<param::RotationVector>(steel_cantilever(8, 6, "consistent"), 8);
    BOOST_TEST_MESSAGE("oracle " << oracle[0] << " " << oracle[1] << " " << oracle[2] << " "
                                 << oracle[3] << " Hz");
    BOOST_TEST(q.symmetric);
    BOOST_TEST(worst_pair_error(q, oracle) <= 1e-7);
    BOOST_TEST(worst_pair_error(l, oracle) <= 1e-7);
    BOOST_TEST(worst_pair_error(v, oracle) <= 1e-7);
    const double p2 = worst_pair_error(
        modes_of<param::Quaternion>(steel_cantilever(8, 2, "consistent"), 8), oracle);
    const double p4 = worst_pair_error(
        modes_of<param::Quaternion>(steel_cantilever(8, 4, "consistent"), 8), oracle);
    BOOST_TEST(p2 / p4 > 100.0);
}

// Every mass rule converges to the same frequencies under h-refinement (linear elements,
// reduced stiffness quadrature): the error falls by ≥ 3.5 per halving (order 2) for each rule.
BOOST_AUTO_TEST_CASE(every_mass_rule_converges_at_order_two_with_linear_elements) {
    const std::vector<double> oracle = timoshenko_hz(2);
    for (const std::string rule : {"consistent", "midpoint", "lumped"}) {
        const double coarse =
            worst_pair_error(modes_of<param::Quaternion>(steel_cantilever(16, 1, rule), 4), oracle);
        const double fine =
            worst_pair_error(modes_of<param::Quaternion>(steel_cantilever(32, 1, rule), 4), oracle);
        BOOST_TEST_MESSAGE(rule << ": error 16 el " << coarse << ", 32 el " << fine);
        BOOST_TEST(coarse / fine >= 3.5);
        BOOST_TEST(fine <= 1e-2);
    }
}

// A follower tip force makes the tangent non-symmetric: the QZ solver is used, about the static
// equilibrium under the load.
BOOST_AUTO_TEST_CASE(follower_load_takes_the_non_symmetric_path) {
    Model model = steel_cantilever(8, 2, "consistent");
    PointLoad f;
    f.point = 1;
    f.force = Vec3(-50.0, 0.0, 0.0);
    f.frame = LoadFrame::follower;
    model.point_loads = {f};
    form::DisplacementStatics<param::Quaternion> problem(model);
    const StaticOutcome eq = run_static(problem, {1.0}, NewtonSettings{}, [](const StepRecord&) {});
    BOOST_TEST_REQUIRE(has_solution(eq.status));
    VecX r;
    SparseMatrix K;
    problem.evaluate(r, &K);
    const SparseMatrix M = form::assemble_mass_matrix(
        model, form::build_mass_mesh(model),
        [&](int node) { return param::Quaternion::matrix(problem.node_rotation(node)); });
    const form::ModalSolution s = form::solve_modal(K, M, 4);
    BOOST_TEST(!s.symmetric);
    BOOST_TEST(s.asymmetry > 1e-8);
    // Beck's column: a compressive follower force (here 50 N, ~2.5 % of the flutter load
    // 20.05 EI/L² = 3.5 kN) raises the first bending frequency and lowers the second, which
    // approach each other until they coalesce at flutter.
    const form::ModalSolution unloaded =
        modes_of<param::Quaternion>(steel_cantilever(8, 2, "consistent"), 4);
    BOOST_TEST_MESSAGE("Beck column, P L²/EI = 0.29: "
                       << unloaded.frequencies_hz[0] << " → " << s.frequencies_hz[0] << " Hz, "
                       << unloaded.frequencies_hz[2] << " → " << s.frequencies_hz[2] << " Hz");
    BOOST_TEST(s.frequencies_hz[0] > unloaded.frequencies_hz[0]);
    BOOST_TEST(s.frequencies_hz[2] < unloaded.frequencies_hz[2]);
}

BOOST_AUTO_TEST_SUITE_END()
