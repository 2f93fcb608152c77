// The iteration matrix of the displacement dynamics (static part, inertia, damping, the exp
// tangent T and the generalized-α slopes) against central differences through the step's
// retraction Δ ⊕ δ, at a deformed (2.6 rad), moving (non-zero v, v˙) state, for every
// parameterization × {relative, direct}, with and without damping.
#include <boost/mpl/list.hpp>
#include <boost/test/unit_test.hpp>
#include <iostream>

#include "core/finite_difference.hpp"
#include "dynamic_state.hpp"

using namespace rotbeam;

namespace {

constexpr int kBase = NonlinearSystem::kStepSlot;

template <class D>
VecX residual_at(D& d, const VecX& dx) {
    d.restore_state(kBase);
    d.retract(dx);
    VecX r;
    d.evaluate(r, nullptr);
    d.restore_state(kBase);
    return r;
}

// Worst column error relative to the column's (or 1e-3 × the matrix's) largest entry, unknowns
// scaled by increment_scale so one step h = ∛ε suits every column. The estimate of
// test_jacobian.cpp applies: truncation ~h² ≈ 4e-11, round-off ~ε/h × (largest cancelling term /
// column size) ≲ 1e-8 here, where the inertia slope c_a = (1 − α_m)/((1 − α_f) β h²) ~ 1e4 mixes
// with stiffness ~1e4. 1e-7 keeps a margin of 10; a wrong block (a sign in G^I, a missing T or
// A_b map) errs by 1e-3 or more.
template <class D>
double max_column_error(D& d) {
    VecX r;
    SparseMatrix J;
    d.evaluate(r, &J);
    const MatX Jd(J);
    const VecX& xs = d.increment_scale();
    const MatX Jfd = central_difference_jacobian_retraction(
        [&](const VecX& u) { return residual_at(d, u.cwiseProduct(xs)); }, d.size());
    const double jmax = Jd.cwiseAbs().maxCoeff();
    double worst = 0.0;
    for (int k = 0; k < d.size(); ++k) {
        const VecX col = Jd.col(k) * xs[k];
        const double err = (Jfd.col(k) - col).cwiseAbs().maxCoeff();
        worst = std::max(worst, err / std::max(col.cwiseAbs().maxCoeff(), 1e-3 * jmax));
    }
    return worst;
}

using AllParams = boost::mpl::list<param::Quaternion, param::WienerMilenkovic, param::Rodrigues,
                                   param::RotationVector>;

}  // namespace

BOOST_AUTO_TEST_SUITE(displacement_dynamics_jacobian)

BOOST_AUTO_TEST_CASE_TEMPLATE(iteration_matrix_matches_central_differences_at_a_moving_state, P,
                              AllParams) {
    for (const char* interpolation : {"relative", "direct"}) {
        for (bool damping : {false, true}) {
            Model m = test::moving_model(2, 3, damping);
            m.discretization.interpolation = interpolation;
            form::DisplacementDynamics<P> d(m);
            test::set_moving_state(d);
            d.save_state(kBase);
            const double worst = max_column_error(d);
            const AssemblyCounters c = d.counters();
            std::cout << P::kName << " " << interpolation << (damping ? ", damped" : ", undamped")
                      << ": tip rotation " << d.statics().max_rotation_angle()
                      << " rad, worst column error " << worst << ", inertial terms "
                      << c.inertial_terms << ", damping terms " << c.damping_terms << "\n";
            BOOST_TEST(worst < 1e-7);
            BOOST_TEST(c.inertial_terms > 0);
            // Damping is assembled only when a section has damping (DESIGN.md quality bars).
            BOOST_TEST((c.damping_terms > 0) == damping);
        }
    }
}

// The slopes: Δ → v, v˙ of the generalized-α relations are checked through the residual above;
// here the scheme's parameters for ρ∞ = 1 are the trapezoidal rule and for ρ∞ = 0 the
// asymptotically annihilating one (Chung & Hulbert 1993, Eqs. 25, 17).
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
