// Manufactured solution (core/oracles/manufactured.hpp): a rod whose rotation
// passes 2π about an axis that varies along it, loaded by the distributed force and moment that
// make it exact. Both formulations are solved on it under h-refinement and their observed orders
// measured against the exact u(s), R(s) at s = L/4, L/2, 3L/4 (docs/reference-solutions.md
// §Manufactured solution has the tables).
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "core/oracles/manufactured.hpp"
#include "core/so3.hpp"
#include "core/static_driver.hpp"
#include "formulations/displacement/displacement_statics.hpp"
#include "formulations/mixed/mixed_statics_of.hpp"
#include "parameterizations/wiener_milenkovic_continuous.hpp"

using namespace rotbeam;

namespace {

oracle::ManufacturedRod rod() {
    oracle::ManufacturedRod r;
    r.stiffness = oracle::manufactured_section();
    return r;
}

struct Error {
    double u = 0.0;  // max over the interior points of ‖u_h − u‖ / L
    double R = 0.0;  // max over the interior points of the angle of R_hᵀ R
    bool converged = false;
    std::string message;
};

// Solves `model` with `problem` along its load factors and measures the error at the last one.
Error solve_and_measure(StaticProblem& problem, const Model& model) {
    const double lambda = model.analysis.statics.load_factors.back();
    const oracle::ManufacturedRod r = rod();
    const StaticOutcome out =
        run_static(problem, model.analysis.statics.load_factors,
                   newton_settings_from(model.solver, model.analysis.statics), nullptr);
    Error e;
    e.converged = has_solution(out.status);
    e.message = out.message;
    if (!e.converged) return e;
    for (const char* name : {"q1", "mid", "q3"}) {
        const int p = model.point_index(name);
        const PointState h = problem.point_state(p);
        const oracle::ManufacturedRod::State x = r.state(model.points[p].position.x(), lambda);
        e.u = std::max(e.u, (h.displacement - x.displacement).norm() / r.length);
        e.R = std::max(e.R, so3::log_map(h.rotation.transpose() * x.rotation).norm());
    }
    return e;
}

template <class P>
Error displacement(int elements, int order) {
    Model m = oracle::manufactured_model(rod(), elements, 20);
    m.discretization.order = order;
    form::DisplacementStatics<P> problem(m);
    return solve_and_measure(problem, m);
}

// The mixed formulation on the path λ = lambda_end/20 … lambda_end.
template <class P>
Error mixed(int elements, double lambda_end) {
    Model m = oracle::manufactured_model(rod(), elements, 20);
    for (double& l : m.analysis.statics.load_factors) l *= lambda_end;
    m.discretization.formulation = Formulation::mixed;
    form::MixedStaticsOf<P> problem(m);
    return solve_and_measure(problem, m);
}

// Observed orders between successive refinements (the element count doubles).
std::vector<double> orders(const std::vector<double>& e) {
    std::vector<double> out;
    for (size_t i = 1; i < e.size(); ++i) out.push_back(std::log2(e[i - 1] / e[i]));
    return out;
}

// Resultants n, m (spatial) at s from the oracle's state alone, with R′ and u′ by central
// differences: an evaluation that shares nothing with the oracle's analytic load formulas.
void resultants_by_differences(const oracle::ManufacturedRod& r, double s, double lambda, Vec3& n,
                               Vec3& m) {
    const double h = 1e-5;
    const auto a = r.state(s - h, lambda), b = r.state(s + h, lambda), c = r.state(s, lambda);
    const Mat3 dR = (b.rotation - a.rotation) / (2 * h);
    const Vec3 du = (b.displacement - a.displacement) / (2 * h);
    const Vec3 K = so3::axial(c.rotation.transpose() * dR);
    Vec6 strain;
    strain << c.rotation.transpose() * (Vec3::UnitX() + du) - Vec3::UnitX(), K;
    const Vec6 NM = r.stiffness * strain;
    n = c.rotation * NM.head<3>();
    m = c.rotation * NM.tail<3>();
}

}  // namespace

BOOST_AUTO_TEST_SUITE(manufactured_solution)

// f = −n′ and μ = −m′ − x′ × n against differences of n, m computed from the state alone.
// Nested central differences (h = 1e-5 inside, 1e-4 outside) are accurate to ~1e-7 relative
// here (truncation h² × third derivatives of order 10, round-off ε/h²·|n| ~ 1e-8); 1e-5 relative
// to the load's size leaves room and still fails on any wrong term (each is of order one).
BOOST_AUTO_TEST_CASE(loads_balance_the_resultants_of_the_prescribed_state) {
    const oracle::ManufacturedRod r = rod();
    const double h = 1e-4;
    for (double lambda : {0.3, 1.0}) {
        for (double s : {0.05, 0.3, 0.5, 0.77, 0.95}) {
            Vec3 na, ma, nb, mb, n, m, f, mu;
            resultants_by_differences(r, s - h, lambda, na, ma);
            resultants_by_differences(r, s + h, lambda, nb, mb);
            resultants_by_differences(r, s, lambda, n, m);
            r.loads(s, lambda, f, mu);
            const Vec3 x1 = Vec3::UnitX() + (r.state(s + 1e-6, lambda).displacement -
                                             r.state(s - 1e-6, lambda).displacement) /
                                                2e-6;
            const Vec3 f_fd = -(nb - na) / (2 * h);
            const Vec3 mu_fd = -(mb - ma) / (2 * h) - x1.cross(n);
            const double size = f.norm() + mu.norm();
            BOOST_TEST((f - f_fd).norm() / size < 1e-5, "s " << s << " λ " << lambda);
            BOOST_TEST((mu - mu_fd).norm() / size < 1e-5, "s " << s << " λ " << lambda);
        }
    }
}

BOOST_AUTO_TEST_CASE(the_rotation_passes_two_pi_about_a_varying_axis) {
    const oracle::ManufacturedRod r = rod();
    const Vec3 axis_mid = so3::log_map(r.state(0.5, 1.0).rotation).normalized();
    const Vec3 axis_q1 = so3::log_map(r.state(0.25, 1.0).rotation).normalized();
    BOOST_TEST(std::abs(axis_mid.dot(axis_q1)) < 0.99);         // the axis varies
    BOOST_TEST(r.a * (1.0 + 0.1 * std::sin(kPi)) > 2.0 * kPi);  // the tip turns past 2π
}

BOOST_AUTO_TEST_CASE(displacement_formulation_converges_at_its_order) {
    for (int order : {1, 2, 3}) {
        std::vector<double> eu, eR;
        for (int n : {2, 4, 8, 16}) {
            const Error e = displacement<param::Quaternion>(n, order);
            BOOST_TEST_REQUIRE(e.converged, e.message);
            std::printf("displacement p=%d N=%3d per member: |du|/L %.3e  rot %.3e\n", order, n,
                        e.u, e.R);
            eu.push_back(e.u);
            eR.push_back(e.R);
        }
        const auto ou = orders(eu), oR = orders(eR);
        std::printf("  orders u: %.2f %.2f %.2f   R: %.2f %.2f %.2f\n", ou[0], ou[1], ou[2], oR[0],
                    oR[1], oR[2]);
        // Nodal values of Legendre spectral elements converge like h^(2p) (superconvergence of
        // the Galerkin solution at the nodes, as on the roll-up: docs/displacement-formulation.md).
        // Measured last pair: 1.86 (p = 1, still approaching 2), 3.99 (p = 2), 5.99 (p = 3).
        BOOST_TEST(ou.back() > 2.0 * order - 0.2, "p = " << order);
        BOOST_TEST(oR.back() > 2.0 * order - 0.2, "p = " << order);
    }
}

// Orders of the mixed formulation: {last pair u, last pair R, whole range u, whole range R}
// (the whole range is the mean order from 4 to 64 elements per member).
template <class P>
std::vector<double> mixed_orders(double lambda_end) {
    std::vector<double> eu, eR;
    for (int n : {4, 8, 16, 32, 64}) {
        const Error e = mixed<P>(n, lambda_end);
        BOOST_TEST_REQUIRE(e.converged, e.message);
        std::printf("mixed %s λ = %.2f N=%3d per member: |du|/L %.3e  rot %.3e\n",
                    std::string(P::kName).c_str(), lambda_end, n, e.u, e.R);
        eu.push_back(e.u);
        eR.push_back(e.R);
    }
    const auto ou = orders(eu), oR = orders(eR);
    std::printf("  orders u: %.2f %.2f %.2f %.2f   R: %.2f %.2f %.2f %.2f\n", ou[0], ou[1], ou[2],
                ou[3], oR[0], oR[1], oR[2], oR[3]);
    return {ou.back(), oR.back(), std::log2(eu.front() / eu.back()) / 4.0,
            std::log2(eR.front() / eR.back()) / 4.0};
}

// The quaternion carries the rotation past 2π about the varying axis (λ = 1) at order 2. The
// three-parameter types cannot (docs/reference-solutions.md §Manufactured solution): past
// λ ≈ 0.78, where the twist reaches 2π inside the rod, the rotation vector converges to another
// solution of the discrete equations and the continuous WM map diverges.
BOOST_AUTO_TEST_CASE(mixed_quaternion_converges_at_second_order_past_two_pi) {
    const auto o = mixed_orders<param::Quaternion>(1.0);
    BOOST_TEST(o[0] > 1.9);
    BOOST_TEST(o[1] > 1.9);
}

// Below 2π (λ = 0.7: the twist reaches 1.75π) the rotation vector and plain WM converge at order
// 2 between every pair of meshes. GXBeam's continuous WM map converges at order 2 only on average
// (successive orders 1.7 … 2.2): at φ = π its map switches from c = θ to c = −θ + 8θ/|θ|, whose
// derivative across the axis flips sign (C¹ along θ only), so with an axis that varies the error
// does not fall smoothly.
BOOST_AUTO_TEST_CASE(mixed_three_parameter_types_converge_at_second_order_below_two_pi) {
    for (const auto& o :
         {mixed_orders<param::RotationVector>(0.7), mixed_orders<param::WienerMilenkovic>(0.7)}) {
        BOOST_TEST(o[0] > 1.9);
        BOOST_TEST(o[1] > 1.9);
    }
    const auto wm = mixed_orders<param::WienerMilenkovicContinuous>(0.7);
    BOOST_TEST(wm[2] > 1.9);
    BOOST_TEST(wm[3] > 1.9);
}

BOOST_AUTO_TEST_SUITE_END()
