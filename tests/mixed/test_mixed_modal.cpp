// Modal analysis of the mixed formulation: the shift-invert Arnoldi iteration
// against a dense eigen-decomposition, independence of the parameterization at the undeformed
// state, and the mesh convergence of a slender cantilever's bending frequencies to beam theory.
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <tuple>

#include "core/errors.hpp"
#include "core/static_driver.hpp"
#include "formulations/mixed/mixed_dynamics.hpp"
#include "formulations/mixed/mixed_modal.hpp"
#include "formulations/mixed/mixed_statics.hpp"
#include "parameterizations/quaternion.hpp"
#include "parameterizations/rodrigues.hpp"
#include "parameterizations/rotation_vector.hpp"
#include "parameterizations/wiener_milenkovic.hpp"
#include "parameterizations/wiener_milenkovic_continuous.hpp"
#include "tests/harness/type_lists.hpp"
#include "tests/mixed/modal_state.hpp"
#include "tests/mixed/models.hpp"

using namespace rotbeam;
using Parameterizations = test::MixedParameterizationTypes<>;

namespace {

// A rectangular isotropic section with its diagonal mass (docs/benchmarks.md §3, §8).
Section isotropic(double E, double nu, double b, double h, double J, double rho) {
    const double G = E / (2.0 * (1.0 + nu)), A = b * h, k = 5.0 / 6.0;
    const double I2 = b * h * h * h / 12.0, I3 = h * b * b * b / 12.0;
    Section s = test::diagonal_section(
        (Vec6() << E * A, k * G * A, k * G * A, G * J, E * I2, E * I3).finished());
    s.mass = Mat6((Vec6() << rho * A, rho * A, rho * A, rho * (I2 + I3), rho * I2, rho * I3)
                      .finished()
                      .asDiagonal());
    return s;
}

// docs/benchmarks.md §3: the joined beam, N elements per member.
Model joined_beam(int n) {
    Model m;
    m.points = {{"root1", Vec3(0, -0.5, 0)}, {"root2", Vec3(0, 0.5, 0)}, {"joint", Vec3(1, 0, 0)}};
    const Section s = isotropic(70e9, 0.35, 0.1, 0.05, 0.229 * 0.1 * std::pow(0.05, 3), 2700);
    m.members = {test::member("m1", 0, 2, s, n), test::member("m2", 1, 2, s, n)};
    m.constraints = {Constraint{0, Constraint::Kind::clamped, Vec3::Zero(), Vec3::Zero(), {}},
                     Constraint{1, Constraint::Kind::clamped, Vec3::Zero(), Vec3::Zero(), {}}};
    return m;
}

// The modes about the reference configuration (the statics' initial state: identity rotations,
// ρ = 1 at a further support of the quaternion), at rest.
template <class P>
form::DaeModalSolution modes_of(const Model& model, int count, bool dense = false) {
    form::MixedDynamics<P> dyn(model, 1.0);
    const VecX x0 = dyn.from_static_state(form::MixedStatics<P>(model).state_vector());
    VecX r;
    SparseMatrix A, B;
    dyn.evaluate(0.0, x0, VecX::Zero(dyn.size()), r, &A, &B);
    return dense ? form::solve_dae_modal_dense(A, B, count) : form::solve_dae_modal(A, B, count);
}

// The quaternion's A, B about a static state of its statics (the reference one by default).
void quaternion_operators(const Model& model, const VecX& static_state, SparseMatrix& A,
                          SparseMatrix& B) {
    form::MixedDynamics<param::Quaternion> dyn(model, 1.0);
    const VecX x0 = dyn.from_static_state(static_state);
    VecX r;
    dyn.evaluate(0.0, x0, VecX::Zero(dyn.size()), r, &A, &B);
    BOOST_TEST((r.array() / dyn.residual_scale().array()).abs().maxCoeff() < 1e-10);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(mixed_modal)

// The quaternion's modes of the joined beam at rest (Table III's setting: 10 elements per member,
// midpoint inertia) equal WM's: about the reference state the linearized four-component
// kinematics are the three-parameter ones in other coordinates (δq = H_m⁺ δψ, and the radial
// direction is an infinite eigenvalue), so the discrete frequencies agree to the eigensolver's
// accuracy (1e-8 as above) and Table III's GEBT column, gated by `rotbeam verify` on WM, holds for
// the quaternion too. Arnoldi = dense for the quaternion's operator as well.
BOOST_AUTO_TEST_CASE(quaternion_modes_of_the_joined_beam_equal_the_three_parameter_ones) {
    const Model model = joined_beam(10);
    SparseMatrix A, B;
    quaternion_operators(model, form::MixedStatics<param::Quaternion>(model).state_vector(), A, B);
    const form::DaeModalSolution q = form::solve_dae_modal(A, B, 8);
    const form::DaeModalSolution qd = form::solve_dae_modal_dense(A, B, 8);
    const form::DaeModalSolution w = modes_of<param::WienerMilenkovic>(model, 8);
    for (int i = 0; i < 8; ++i) {
        const auto k = static_cast<std::size_t>(i);
        BOOST_TEST_MESSAGE("quaternion mode " << i + 1 << ": " << q.frequencies_hz[k] << " Hz (WM "
                                              << w.frequencies_hz[k] << "), Re s "
                                              << q.growth_rates[k]);
        BOOST_TEST(std::abs(q.frequencies_hz[k] - w.frequencies_hz[k]) <
                   1e-8 * w.frequencies_hz[k]);
        BOOST_TEST(std::abs(q.frequencies_hz[k] - qd.frequencies_hz[k]) <
                   1e-8 * qd.frequencies_hz[k]);
        BOOST_TEST(std::abs(q.growth_rates[k]) < 1e-8 * 2 * kPi * q.frequencies_hz[k]);
    }
}

// Arnoldi on (A + σB)⁻¹B keeps the lowest modes of the dense decomposition of the same operator:
// both are backward stable on a matrix of norm ~1/ω₁², so the frequencies agree to ~1e-10
// relative; 1e-8 leaves a margin while a wrong shift inversion or a lost pair is O(1).
BOOST_AUTO_TEST_CASE_TEMPLATE(arnoldi_matches_the_dense_decomposition_on_the_joined_beam, P,
                              Parameterizations) {
    const Model model = joined_beam(10);
    const form::DaeModalSolution a = modes_of<P>(model, 8);
    const form::DaeModalSolution d = modes_of<P>(model, 8, true);
    for (int i = 0; i < 8; ++i) {
        const double fa = a.frequencies_hz[static_cast<std::size_t>(i)];
        const double fd = d.frequencies_hz[static_cast<std::size_t>(i)];
        BOOST_TEST_MESSAGE(P::kName << " mode " << i + 1 << ": Arnoldi " << fa << " Hz, dense "
                                    << fd << " Hz, Re s "
                                    << a.growth_rates[static_cast<std::size_t>(i)]);
        BOOST_TEST(std::abs(fa - fd) < 1e-8 * fd);
        // Undamped, no gyroscopic terms at rest: Re s is round-off of |s| ~ 2π f.
        BOOST_TEST(std::abs(a.growth_rates[static_cast<std::size_t>(i)]) < 1e-8 * 2 * kPi * fa);
    }
}

// Straight cantilever (docs/benchmarks.md §8: L = 1, h = 0.01, E = 2.1e11, ν = 0.3, ρ = 7850): the
// first two bending frequencies converge at order 2 to the Euler–Bernoulli values
// (β L)² √(EI/ρA L⁴)/2π, β₁L = 1.87510407, β₂L = 4.69409113. Shear and rotary inertia (Timoshenko)
// lower them by about ½(β r)²(1 + E/κG) ≈ 6e-5 (mode 1) and 4e-4 (mode 2), r = h/√12 the radius
// of gyration, E/κG = 3.12 (a simply-supported estimate; the clamped end changes the factor, not
// the order): the extrapolated limit must sit below beam theory by less than 1e-3, while the
// 8-element value must not be that close (so the test sees convergence, not a coincidence).
BOOST_AUTO_TEST_CASE(cantilever_bending_frequencies_converge_at_order_two_to_beam_theory) {
    const double E = 2.1e11, h = 0.01, rho = 7850;
    const double EI = E * h * h * h * h / 12.0, rhoA = rho * h * h;
    const double exact[2] = {std::pow(1.87510407, 2) * std::sqrt(EI / rhoA) / (2 * kPi),
                             std::pow(4.69409113, 2) * std::sqrt(EI / rhoA) / (2 * kPi)};
    double f[4][2];
    const int meshes[4] = {8, 16, 32, 64};
    for (int k = 0; k < 4; ++k) {
        Model m;
        m.points = {{"root", Vec3::Zero()}, {"tip", Vec3(1, 0, 0)}};
        m.members = {
            test::member("beam", 0, 1, isotropic(E, 0.3, h, h, 1.40577e-9, rho), meshes[k])};
        m.constraints = {Constraint{0, Constraint::Kind::clamped, Vec3::Zero(), Vec3::Zero(), {}}};
        // Both bending planes have the same frequencies: modes 1, 2 are mode 1 in each plane.
        const form::DaeModalSolution s = modes_of<param::WienerMilenkovic>(m, 4);
        f[k][0] = s.frequencies_hz[0];
        f[k][1] = s.frequencies_hz[2];
    }
    for (int mode = 0; mode < 2; ++mode) {
        for (int k = 0; k < 4; ++k) {
            BOOST_TEST_MESSAGE("cantilever mode " << mode + 1 << ", " << meshes[k]
                                                  << " elements: " << f[k][mode]
                                                  << " Hz (Euler–Bernoulli " << exact[mode] << ")");
        }
        const double ratio = (f[1][mode] - f[2][mode]) / (f[2][mode] - f[3][mode]);
        const double limit = f[3][mode] + (f[3][mode] - f[2][mode]) / 3.0;  // Richardson, p = 2
        BOOST_TEST_MESSAGE("  difference ratio " << ratio << ", extrapolated " << limit);
        BOOST_TEST(ratio > 3.8);  // order 2: ratio 4
        BOOST_TEST(ratio < 4.2);
        BOOST_TEST(limit < exact[mode]);
        BOOST_TEST(limit > exact[mode] * (1.0 - 1e-3));
        BOOST_TEST(std::abs(f[0][mode] - exact[mode]) > 1e-3 * exact[mode]);
    }
}

// About a loaded static state (the joined beam with a follower joint force 1e5 N e_z, tip
// deflection 0.26 m): the dynamic residual with the loads frozen at the static load factor
// vanishes at the static state mapped into the dynamic unknowns (so the modes are about an
// equilibrium), A is not symmetric (follower stiffness), and Arnoldi still agrees with the dense
// decomposition; the first frequency moves off the unloaded one.
BOOST_AUTO_TEST_CASE(modes_about_a_follower_loaded_static_state) {
    using P = param::WienerMilenkovic;
    Model model = joined_beam(10);
    PointLoad f;
    f.point = 2;
    f.force = Vec3(0, 0, 1e5);
    f.frame = LoadFrame::follower;
    model.point_loads = {f};
    form::MixedDynamics<P> dyn(form::frozen_loads(model, 1.0), 1.0);
    VecX r;
    SparseMatrix A, B;
    test::linearize_about_static_equilibrium(model, dyn, r, A, B);
    // The statics converged to 1e-12 of the scaled residual; the same rows here.
    BOOST_TEST((r.array() / dyn.residual_scale().array()).abs().maxCoeff() < 1e-10);
    const MatX Ad(A);
    const double asymmetry = (Ad - Ad.transpose()).cwiseAbs().maxCoeff() / Ad.cwiseAbs().maxCoeff();
    BOOST_TEST(asymmetry > 1e-3);
    const form::DaeModalSolution a = form::solve_dae_modal(A, B, 5);
    const form::DaeModalSolution d = form::solve_dae_modal_dense(A, B, 5);
    for (int i = 0; i < 5; ++i) {
        const double fa = a.frequencies_hz[static_cast<std::size_t>(i)];
        BOOST_TEST_MESSAGE("follower-loaded mode " << i + 1 << ": " << fa << " Hz, Re s "
                                                   << a.growth_rates[static_cast<std::size_t>(i)]);
        BOOST_TEST(std::abs(fa - d.frequencies_hz[static_cast<std::size_t>(i)]) < 1e-8 * fa);
    }
    // The load moves the first frequency (35.213 → 35.704 Hz, measured) far beyond the
    // eigensolver's 1e-8: against the unloaded structure on the same mesh. The loaded values
    // themselves are compared with an independent number (the displacement formulation at
    // convergence, the mixed one extrapolated in h) in tests/agreement/test_modal_agreement.cpp.
    const form::DaeModalSolution unloaded = modes_of<P>(joined_beam(10), 5);
    BOOST_TEST(std::abs(a.frequencies_hz[0] - unloaded.frequencies_hz[0]) >
               1e-4 * unloaded.frequencies_hz[0]);
    // The quaternion about its own static state: a different discretization of Eq. 48 (the
    // midpoint rule in four components), so close to WM's but not equal (the statics' tips differ
    // by O(ΔL²) at this deflection): within 1e-3, and Arnoldi = dense on its operator.
    form::MixedStatics<param::Quaternion> qs(model);
    qs.set_load_factor(1.0);
    BOOST_REQUIRE(solve_newton(qs, NewtonSettings{}).converged);
    SparseMatrix Aq, Bq;
    quaternion_operators(form::frozen_loads(model, 1.0), qs.state_vector(), Aq, Bq);
    const form::DaeModalSolution q = form::solve_dae_modal(Aq, Bq, 5);
    const form::DaeModalSolution qd = form::solve_dae_modal_dense(Aq, Bq, 5);
    for (int i = 0; i < 5; ++i) {
        const auto k = static_cast<std::size_t>(i);
        BOOST_TEST_MESSAGE("follower-loaded quaternion mode " << i + 1 << ": "
                                                              << q.frequencies_hz[k] << " Hz, Re s "
                                                              << q.growth_rates[k]);
        BOOST_TEST(std::abs(q.frequencies_hz[k] - qd.frequencies_hz[k]) <
                   1e-8 * q.frequencies_hz[k]);
        BOOST_TEST(std::abs(q.frequencies_hz[k] - a.frequencies_hz[k]) <
                   1e-3 * a.frequencies_hz[k]);
    }
}

BOOST_AUTO_TEST_SUITE_END()

// The index of the mixed DAE (docs/mixed-dynamics.md, "Index"): the consistent-initialization
// matrix (∂F/∂X in the algebraic columns, ∂F/∂Ẋ in the differential ones:
// consistent_initial_conditions' Newton matrix, every integrator's start) is regular for a
// cantilever (index 1) and loses exactly six ranks on the joined beam, whose two clamps close one
// kinematic loop (index 3: the closure constrains the differential u, c, the redundant reaction is
// its multiplier). Rows and columns scaled by the residual and state scales (rates by state scale /
// 1e-3 s), so the singular values are comparable.
template <class Dyn>
Eigen::VectorXd initial_condition_singular_values(Dyn& dyn, const VecX& x) {
    VecX r;
    SparseMatrix Jx, Jxd;
    const VecX xd = VecX::Zero(dyn.size());
    dyn.evaluate(0.0, x, xd, r, &Jx, &Jxd);
    const VecX d = dyn.initial_condition_differential(x);
    MatX G(dyn.size(), dyn.size());
    const MatX X(Jx), Xd(Jxd);
    for (int j = 0; j < dyn.size(); ++j) {
        G.col(j) = d[j] != 0.0 ? Xd.col(j) * (dyn.state_scale()[j] / 1e-3)
                               : X.col(j) * dyn.state_scale()[j];
    }
    G = dyn.residual_scale().cwiseInverse().asDiagonal() * G;
    return Eigen::JacobiSVD<MatX>(G).singularValues();  // descending
}

BOOST_AUTO_TEST_SUITE(mixed_index)

BOOST_AUTO_TEST_CASE(initial_condition_matrix_loses_six_ranks_on_the_closed_loop) {
    Model cantilever = joined_beam(3);
    cantilever.constraints.pop_back();  // root2 free: a tree with one support
    for (const bool loop : {false, true}) {
        const Model model = loop ? joined_beam(3) : cantilever;
        form::MixedDynamics<param::WienerMilenkovic> wm(model, 1.0);
        form::MixedDynamics<param::Quaternion> q(model, 1.0);
        const Eigen::VectorXd s_wm = initial_condition_singular_values(wm, VecX::Zero(wm.size()));
        const Eigen::VectorXd s_q = initial_condition_singular_values(
            q, q.from_static_state(form::MixedStatics<param::Quaternion>(model).state_vector()));
        for (const Eigen::VectorXd* s : {&s_wm, &s_q}) {
            const Eigen::Index n = s->size();
            BOOST_TEST_MESSAGE((s == &s_wm ? "WM" : "quaternion")
                               << (loop ? ", two clamps" : ", one clamp") << ": σ_max " << (*s)[0]
                               << ", smallest " << (*s)[n - 1] << ", σ_(n−6) " << (*s)[n - 6]
                               << ", σ_(n−7) " << (*s)[n - 7]);
            // The scaled matrix is ill-conditioned (σ_max/σ_min ≈ 5e11 with one clamp: stiff
            // sections against unit scales) but has no gap: its smallest singular value is within
            // a factor 10 of the seventh smallest. With two clamps six drop to round-off of σ_max
            // (≤ 1e-18 σ_max measured), ≥ 1e6 below the seventh.
            if (loop) {
                BOOST_TEST((*s)[n - 6] < 1e-15 * (*s)[0]);
                BOOST_TEST((*s)[n - 6] < 1e-5 * (*s)[n - 7]);
            } else {
                BOOST_TEST((*s)[n - 1] > 0.1 * (*s)[n - 7]);
            }
        }
    }
}

BOOST_AUTO_TEST_SUITE_END()

// discretization.mass_rule in the mixed element (docs/mixed-dynamics.md): `consistent` is the
// element average of the piecewise-linear section mass (the consistent mass of the element's
// constant momenta), `midpoint` its mid-length value, `lumped` refused. A station with a kink
// inside the first of two elements separates them: mass per length 1 → 4 → 1 at s/L = 0, 0.3, 1;
// element 1 spans [0, 0.5]: average (0.3·2.5 + 0.2·(4 + 22/7)/2)/0.5 = 2.9285714…, mid-length
// value 1 + 3·0.25/0.3 = 3.5. Element 2 has no station inside: both rules agree there.
BOOST_AUTO_TEST_SUITE(mixed_mass_rule)

BOOST_AUTO_TEST_CASE(consistent_averages_midpoint_samples_lumped_is_refused) {
    Model m;
    m.points = {{"root", Vec3::Zero()}, {"tip", Vec3(1, 0, 0)}};
    auto station = [](double f, double mu) {
        Section s = test::diagonal_section(Vec6::Ones());
        s.mass = Mat6(mu * Mat6::Identity());
        return SectionStation{f, s};
    };
    Member beam = test::member("beam", 0, 1, station(0.0, 1.0).section, 2);
    beam.sections = {station(0.0, 1.0), station(0.3, 4.0), station(1.0, 1.0)};
    m.members = {beam};
    const form::MixedLayout layout = form::build_mixed_layout(m);
    m.discretization.mixed.mass_rule = MassRule::consistent;
    const double consistent = form::mixed_element_mass(m, layout.elements[0])(0, 0);
    const double consistent2 = form::mixed_element_mass(m, layout.elements[1])(0, 0);
    m.discretization.mixed.mass_rule = MassRule::midpoint;
    const double midpoint = form::mixed_element_mass(m, layout.elements[0])(0, 0);
    const double midpoint2 = form::mixed_element_mass(m, layout.elements[1])(0, 0);
    BOOST_TEST(std::abs(consistent - (0.75 + 0.1 * (4.0 + 22.0 / 7.0)) / 0.5) < 1e-14);
    BOOST_TEST(std::abs(midpoint - 3.5) < 1e-14);
    BOOST_TEST(std::abs(consistent2 - midpoint2) < 1e-14);
    m.discretization.mixed.mass_rule = MassRule::lumped;
    BOOST_CHECK_THROW(form::mixed_element_mass(m, layout.elements[0]), InputError);
}

BOOST_AUTO_TEST_SUITE_END()
