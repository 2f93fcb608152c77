// The exact consistent Jacobian of the displacement statics, checked column by column against
// central finite differences taken through the retraction (x ⊕ h e_k), and the linearization
// order check, at the strongly deformed state of deformed.hpp.
#include <boost/mpl/list.hpp>
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <iostream>

#include "combinations/registry.hpp"
#include "core/finite_difference.hpp"
#include "deformed.hpp"
#include "formulations/displacement/displacement_statics.hpp"
#include "parameterizations/euler_angles.hpp"
#include "parameterizations/rodrigues.hpp"
#include "parameterizations/rotation_vector.hpp"
#include "parameterizations/wiener_milenkovic.hpp"

using namespace rotbeam;
using Statics = form::DisplacementStatics<param::Quaternion>;

namespace {

constexpr int kBase = 0;  // checkpoint slot holding the deformed state

template <class S>
VecX residual_at(S& s, const VecX& dx) {
    s.restore_state(kBase);
    s.retract(dx);
    VecX r;
    s.evaluate(r, nullptr);
    s.restore_state(kBase);
    return r;
}

// Deformed problem at load factor 1 with its state saved in kBase.
template <class S>
void deform(S& s) {
    s.set_load_factor(1.0);
    s.retract(test::deforming_increment(s.mesh()));
    s.save_state(kBase);
}

// max_k ‖J_fd,k − J_k‖∞ / max(‖J_k‖∞, ‖J‖max) over the columns, in scaled variables.
// Unknowns are scaled by increment_scale (displacements by L, rotations by 1), so one step
// h = ∛ε ≈ 6e-6 suits every column. Central differences then err by ~h²|r‴| (truncation,
// ≈ 4e-11 relative for an O(1)-scaled smooth residual) plus ε|r|/h (round-off, ≈ 4e-11 × the
// largest cancelling term: the axial stiffness EA = 1e4 against bending terms ~1e2 gives a
// factor ~1e2). 1e-7 relative leaves a margin of ~20 over that estimate; a wrong Jacobian
// term (missing curvature map, a sign in a follower term) shows up at 1e-3 or larger.
template <class S>
double max_column_error(S& s, double& worst_abs) {
    const int n = s.size();
    VecX r;
    SparseMatrix J;
    s.evaluate(r, &J);
    const MatX Jd = MatX(J);
    const VecX& xs = s.increment_scale();
    const MatX Jfd = central_difference_jacobian_retraction(
        [&](const VecX& d) { return residual_at(s, d.cwiseProduct(xs)); }, n);
    const double jmax = Jd.cwiseAbs().maxCoeff() ;
    double worst = 0.0;
    worst_abs = 0.0;
    for (int k = 0; k < n; ++k) {
        const VecX col = Jd.col(k) * xs[k];
        const double err = (Jfd.col(k) - col).cwiseAbs().maxCoeff();
        worst = std::max(worst, err / std::max(col.cwiseAbs().maxCoeff(), 1e-3 * jmax));
        worst_abs = std::max(worst_abs, err / jmax);
    }
    return worst;
}

template <class P = param::Quaternion>
void check_jacobian(const Model& m, const char* label, double min_angle = 2.0) {
    form::DisplacementStatics<P> s(m);
    deform(s);
    BOOST_TEST_REQUIRE(s.max_rotation_angle() > min_angle);
    double worst_abs = 0.0;
    const double worst = max_column_error(s, worst_abs);
    std::cout << P::kName << " " << choice_name(m.discretization.displacement.interpolation) << ", "
              << label << ": tip rotation " << s.max_rotation_angle() << " rad, worst column error "
              << worst << " (relative to the column), " << worst_abs << " (relative to max |J|)\n";
    BOOST_TEST(worst < 1e-7);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(displacement_jacobian)

BOOST_AUTO_TEST_CASE(jacobian_matches_central_differences_through_retraction_follower_p4) {
    check_jacobian(test::curved_twisted(2, 4, true, true), "p=4, 2 elements, follower+gravity");
}

// Every parameterization × {relative, direct} at the curved, twisted, follower-loaded state.
using AllParams = boost::mpl::list<param::Quaternion, param::WienerMilenkovic, param::Rodrigues,
                                   param::RotationVector, param::EulerAngles>;
BOOST_AUTO_TEST_CASE_TEMPLATE(jacobian_matches_central_differences_every_parameterization_and_interpolation,
                              P, AllParams) {
    for (const Interpolation interpolation : comb::kDisplacementInterpolations) {
        Model m = test::curved_twisted(2, 4, true, true);
        m.discretization.displacement.interpolation = interpolation;
        check_jacobian<P>(m, "p=4, 2 elements, follower+gravity");
    }
}

// The additive update (Newton unknowns δp, p ← p + δp) of the three-parameter types: the same
// finite differences, now through the additive retraction, check J_ψ · H_s(p). The deforming
// increment then sets the parameters themselves, so the rotations are smaller for Rodrigues
// (1.8 rad) and WM (2.3 rad) than for the rotation vector (2.6 rad).
using ThreeParams = boost::mpl::list<param::WienerMilenkovic, param::Rodrigues,
                                     param::RotationVector, param::EulerAngles>;
BOOST_AUTO_TEST_CASE_TEMPLATE(additive_update_jacobian_matches_central_differences, P,
                              ThreeParams) {
    for (const Interpolation interpolation : comb::kDisplacementInterpolations) {
        Model m = test::curved_twisted(2, 4, true, true);
        m.discretization.displacement.interpolation = interpolation;
        m.discretization.displacement.update = Update::additive;
        check_jacobian<P>(m, "additive update, p=4, 2 elements, follower+gravity", 1.5);
    }
}

BOOST_AUTO_TEST_CASE(jacobian_matches_central_differences_reduced_quadrature_p2) {
    check_jacobian(test::curved_twisted(3, 2, true, false), "p=2 reduced, 3 elements, follower");
}

BOOST_AUTO_TEST_CASE(jacobian_matches_central_differences_gll_quadrature_p6_dead) {
    Model m = test::curved_twisted(1, 6, false, true);
    m.discretization.quadrature = Quadrature::gll;
    check_jacobian(m, "p=6 GLL, 1 element, dead+gravity");
}

// ‖r(x ⊕ h d) − r(x) − h J d‖ falls 4× when h halves (second-order remainder): the Jacobian is
// the derivative through the retraction, not an approximation of it.
BOOST_AUTO_TEST_CASE(linearization_remainder_is_second_order) {
    Statics s(test::curved_twisted(2, 4, true, true));
    deform(s);
    VecX r0;
    SparseMatrix J;
    s.evaluate(r0, &J);
    VecX d(s.size());
    for (int i = 0; i < s.size(); ++i) d[i] = std::sin(1.0 + 2.3 * i) * s.increment_scale()[i];
    const VecX Jd = J * d;
    double previous = 0.0;
    for (int k = 0; k < 5; ++k) {
        const double h = 1e-2 / std::pow(2.0, k);
        const double e = (residual_at(s, h * d) - r0 - h * Jd).norm();
        if (k > 0) {
            const double ratio = previous / e;
            std::cout << "h = " << h << ": remainder " << e << ", ratio " << ratio << '\n';
            BOOST_TEST(ratio > 3.6);
            BOOST_TEST(ratio < 4.4);
        }
        previous = e;
    }
}

BOOST_AUTO_TEST_SUITE_END()
