// The generalized-α parameters of the displacement dynamics and its iteration matrix at rest (the
// check of the iteration matrix against central differences at a deformed, moving state, for
// every combination, is the generic harness's: tests/harness/test_jacobians.cpp).
#include <boost/test/unit_test.hpp>
#include <iostream>
#include <type_traits>

#include "dynamic_state.hpp"
#include "formulations/displacement/displacement_modal.hpp"
#include "formulations/displacement/gyroscopic_modal.hpp"
#include "tests/parameterizations/samples.hpp"

using namespace rotbeam;
using AllParams = test::AllParameterizationTypes;

BOOST_AUTO_TEST_SUITE(displacement_dynamics_jacobian)

// The slopes: Δ → v, v˙ of the generalized-α relations are checked through the iteration matrix
// (tests/harness/test_jacobians.cpp); here the scheme's parameters for ρ∞ = 1 are the trapezoidal
// rule and for ρ∞ = 0 the asymptotically annihilating one (Chung & Hulbert 1993, Eqs. 25, 17).
BOOST_AUTO_TEST_CASE(chung_hulbert_parameters) {
    const GeneralizedAlpha a = GeneralizedAlpha::from_rho_infinity(1.0);
    BOOST_TEST(a.alpha_m == 0.5);
    BOOST_TEST(a.alpha_f == 0.5);
    BOOST_TEST(a.gamma == 0.5);
    BOOST_TEST(a.beta == 0.25);
    const GeneralizedAlpha b = GeneralizedAlpha::from_rho_infinity(0.0);
    BOOST_TEST(b.alpha_m == -1.0);
    BOOST_TEST(b.alpha_f == 0.0);
    BOOST_TEST(b.gamma == 1.5);
    BOOST_TEST(b.beta == 1.0);
    BOOST_CHECK_THROW(GeneralizedAlpha::from_rho_infinity(1.5), InputError);
}

BOOST_AUTO_TEST_SUITE_END()

// At rest (v = v˙ = 0, Δ = 0) the iteration matrix is the static tangent plus c_a M: G^I, K^I and
// T(ψ) − I vanish. M must be the modal analysis's mass (displacement_modal_mass.hpp), which
// interpolates rotations as exp(Σ N_j log(R_0ᵀ R_j)) — the rotation vector's relative
// interpolation, so for it the two agree to round-off (1e-12 of max |M|: sums of ~10 products of
// O(1) terms). The other parameterizations interpolate other parameters; their difference is
// printed (the deformed state has 2.6 rad at the tip, up to ~0.7 rad inside one element).
BOOST_AUTO_TEST_CASE_TEMPLATE(iteration_matrix_at_rest_is_static_tangent_plus_modal_mass, P,
                              AllParams) {
    const Model m = test::moving_model(2, 3, false);
    form::DisplacementDynamics<P> d(m);
    d.statics().set_load_factor(1.0);
    d.statics().retract(test::deforming_increment(d.mesh()));
    d.adopt_static_state();
    const GeneralizedAlpha g = GeneralizedAlpha::from_rho_infinity(0.6);
    constexpr double kStep = 0.01;
    d.begin_step(0.01, kStep, g);
    VecX r;
    SparseMatrix J, Js;
    d.evaluate(r, &J);
    d.statics().evaluate(r, &Js);
    const MatX M_dyn = MatX(J - Js) / g.acceleration_slope(kStep);
    const SparseMatrix M_modal = form::assemble_mass_matrix(
        m, form::build_mass_mesh(m), [&](int node) { return P::matrix(d.node_rotation(node)); });
    const double diff =
        (M_dyn - MatX(M_modal)).cwiseAbs().maxCoeff() / MatX(M_modal).cwiseAbs().maxCoeff();
    std::cout << P::kName << ": (J - J_static)/c_a against the modal mass, max difference / max|M| "
              << diff << "\n";
    if constexpr (std::is_same_v<P, param::RotationVector>) {
        BOOST_TEST(diff <= 1e-12);  // measured 3e-16
    } else {
        // Same sectional mass rotated by another interpolated rotation: the two interpolations
        // differ by O(φ_e³/12) rad for an element rotation φ_e ≲ 0.5 rad here (≲ 1e-2), so M by
        // less than 1e-3 of max |M| (measured 7e-6 … 3e-5); and they do differ (> 1e-9), which
        // shows the comparison sees the interpolated rotation.
        BOOST_TEST(diff <= 1e-3);
        BOOST_TEST(diff > 1e-9);
    }
}

// At rest relative to a turning frame (v = 0 on every node) the velocity terms of the inertial
// force are linear in v but for ω_abs × ρ ω_abs and ω̃ω̃ m η, which are quadratic, so central
// differences of the dynamic residual in the nodal velocities have no truncation error; with a
// step h = 1e-2 their round-off is ε |r| / h ≈ 2e-16 × 1e4 / 1e-2 = 2e-10 (|r| ≲ 1e4: the elastic
// forces of the deformed state, stiffness 1e4), 2e-11 of max |G| = 12.9 (at h = 1e-4 it was
// 2.8e-9, measured). They must equal the gyroscopic matrix of the modal analysis about that state
// (gyroscopic_modal.hpp, from the modal mass matrix): Coriolis 2 M_u Ω̃, the frame's M_ω Ω̃ and
// G^I at ω = Ω. The curved, twisted member (coupled section, mass-centre offset, unequal rotary
// inertias) at its deformed state (tip rotation 2.6 rad), Ω = (0.7, −1.1, 2.3) about (0.3, −0.2,
// 0.1). As for the mass above, the rotation vector's interpolation is the modal matrices', so it
// agrees to 1e-9 of max |G| (fifty times the round-off); the other parameterizations interpolate
// other parameters and differ by the same O(φ_e³) (≤ 1e-3, and > 1e-9 so that the comparison
// sees the rotation).
BOOST_AUTO_TEST_CASE_TEMPLATE(gyroscopic_matrix_is_the_velocity_derivative_of_the_residual, P,
                              AllParams) {
    Model m = test::moving_model(2, 3, false);
    std::erase_if(m.distributed_loads,
                  [](const DistributedLoad& l) { return l.frame != LoadFrame::follower; });
    const Vec3 Omega(0.7, -1.1, 2.3);
    m.rotating_frame.angular_velocity = Omega;
    m.rotating_frame.center = Vec3(0.3, -0.2, 0.1);
    form::DisplacementDynamics<P> d(m);
    d.statics().set_load_factor(1.0);
    d.statics().retract(test::deforming_increment(d.mesh()));
    d.adopt_static_state();
    for (size_t i = 0; i < d.mesh().nodes.size(); ++i) {
        d.set_node_velocity(static_cast<int>(i), Vec6::Zero());
        d.set_node_acceleration(static_cast<int>(i), Vec6::Zero());
    }
    const SparseMatrix G = form::gyroscopic_matrix(
        form::assemble_mass_matrix(m, form::build_mass_mesh(m),
                                   [&](int node) { return P::matrix(d.node_rotation(node)); }),
        Omega);
    constexpr double kH = 1e-2;
    MatX G_fd = MatX::Zero(d.size(), d.size());
    VecX r_plus, r_minus;
    for (size_t i = 0; i < d.mesh().nodes.size(); ++i) {
        const int dof = d.mesh().nodes[i].dof;
        if (dof < 0) continue;
        for (int k = 0; k < 6; ++k) {
            const Vec6 e = kH * Vec6::Unit(k);
            d.set_node_velocity(static_cast<int>(i), e);
            d.evaluate(r_plus, nullptr);
            d.set_node_velocity(static_cast<int>(i), -e);
            d.evaluate(r_minus, nullptr);
            d.set_node_velocity(static_cast<int>(i), Vec6::Zero());
            G_fd.col(dof + k) = (r_plus - r_minus) / (2.0 * kH);
        }
    }
    const double scale = MatX(G).cwiseAbs().maxCoeff();
    const double diff = (G_fd - MatX(G)).cwiseAbs().maxCoeff() / scale;
    std::cout << P::kName << ": gyroscopic matrix against central differences in v, max difference"
              << " / max|G| " << diff << " (max|G| " << scale << ")\n";
    BOOST_TEST(scale > 1.0);  // Ω and the mass are of unit order: not vacuous
    if constexpr (std::is_same_v<P, param::RotationVector>) {
        BOOST_TEST(diff <= 1e-9);
    } else {
        BOOST_TEST(diff <= 1e-3);
        BOOST_TEST(diff > 1e-9);
    }
}

// The Gauss collocation's iteration-matrix parts K = ∂r/∂q dexp, C = ∂r/∂v, M = ∂r/∂v˙ from the
// displacement dynamics' stage_matrices (one evaluation, then the inertial and damping rate terms
// alone) against CollocationProblem's general rule (three evaluations at (c_v, c_a) = (0, 0),
// (1, 0), (0, 1) and differences), at a deformed, moving stage state of a damped member, at rest
// and in a rotating frame (Coriolis in C): K is the same evaluation (equal to the bit); C and M
// agree to the round-off of the differences (K + C) − K, a few ε max |K| per entry: 1e-13 of
// max |K|. A rate term missing from the override (the damping's ∂/∂v, the Coriolis term) differs
// by O(1e-2) of max |K| or more.
BOOST_AUTO_TEST_CASE_TEMPLATE(stage_matrices_are_the_three_evaluations_differences, P, AllParams) {
    for (const bool spinning : {false, true}) {
        Model m = test::moving_model(2, 3, true);
        if (spinning) {
            std::erase_if(m.distributed_loads,
                          [](const DistributedLoad& l) { return l.frame != LoadFrame::follower; });
            m.rotating_frame.angular_velocity = Vec3(0.7, -1.1, 2.3);
            m.rotating_frame.center = Vec3(0.3, -0.2, 0.1);
        }
        form::DisplacementDynamics<P> d(m);
        test::set_moving_state(d);
        VecX v, v_dot;
        d.start_rates(v, v_dot);
        VecX delta(d.size());
        for (int k = 0; k < d.size(); ++k) delta[k] = 1e-3 * std::sin(0.37 * k + 0.1);
        VecX r_fast, r_general;
        SparseMatrix K_fast, C_fast, M_fast, K_general, C_general, M_general;
        d.stage_matrices(delta, v, v_dot, 0.23, r_fast, K_fast, C_fast, M_fast);
        d.CollocationProblem::stage_matrices(delta, v, v_dot, 0.23, r_general, K_general, C_general,
                                             M_general);
        BOOST_TEST_REQUIRE(C_fast.nonZeros() == C_general.nonZeros());
        BOOST_TEST_REQUIRE(M_fast.nonZeros() == M_general.nonZeros());
        const double scale = MatX(K_general).cwiseAbs().maxCoeff();
        const double dK = MatX(K_fast - K_general).cwiseAbs().maxCoeff();
        const double dC = MatX(C_fast - C_general).cwiseAbs().maxCoeff() / scale;
        const double dM = MatX(M_fast - M_general).cwiseAbs().maxCoeff() / scale;
        std::cout << P::kName << (spinning ? ", rotating frame" : "")
                  << ": stage matrices against three evaluations, max |ΔC|, |ΔM| / max |K|: " << dC
                  << ", " << dM << " (max |C| " << MatX(C_general).cwiseAbs().maxCoeff()
                  << ", max |M| " << MatX(M_general).cwiseAbs().maxCoeff() << ", max |K| " << scale
                  << ")\n";
        BOOST_TEST(MatX(C_general).cwiseAbs().maxCoeff() > 1e-3 * scale);  // not vacuous
        BOOST_TEST(MatX(M_general).cwiseAbs().maxCoeff() > 0.0);
        BOOST_TEST(dK == 0.0);
        BOOST_TEST(dC <= 1e-13);
        BOOST_TEST(dM <= 1e-13);
        BOOST_TEST((r_fast - r_general).cwiseAbs().maxCoeff() == 0.0);
    }
}
