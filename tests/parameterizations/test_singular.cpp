// Defined behaviour at the singular set: every function refuses non-finite
// input and inputs at or beyond the singular set with a SingularityError naming the
// parameterization, the function and the angle; nothing returns NaN or Inf silently.
#include <boost/test/unit_test.hpp>

#include "samples.hpp"

namespace rotbeam::test {
namespace {

// Calls f, requires a SingularityError from `function` of P, and returns its angle.
template <class P, class F>
double refusal_angle(const F& f, const std::string& function) {
    try {
        f();
    } catch (const SingularityError& e) {
        BOOST_TEST(e.parameterization() == std::string(P::kName));
        BOOST_TEST(e.function() == function);
        return e.angle();
    }
    BOOST_ERROR(P::kName << "::" << function << " did not throw");
    return 0.0;
}

template <class P>
typename P::P non_finite() {
    typename P::P p = P::identity();
    p[1] = std::numeric_limits<double>::quiet_NaN();
    return p;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(parameterization_singular_set)

BOOST_AUTO_TEST_CASE_TEMPLATE(every_function_refuses_non_finite_input, P,
                              AllParameterizationTypes) {
    using V = typename P::P;
    const V bad = non_finite<P>();
    const V good = P::from_rotation_vector(0.3 * generic_axis());
    const Vec3 inf_vec(std::numeric_limits<double>::infinity(), 0.0, 0.0);
    BOOST_CHECK_THROW(P::matrix(bad), SingularityError);
    BOOST_CHECK_THROW(P::compose(bad, good), SingularityError);
    BOOST_CHECK_THROW(P::compose(good, bad), SingularityError);
    BOOST_CHECK_THROW(P::inverse(bad), SingularityError);
    BOOST_CHECK_THROW(P::spatial_tangent(bad), SingularityError);
    BOOST_CHECK_THROW(P::material_tangent(bad), SingularityError);
    BOOST_CHECK_THROW(P::spatial_tangent_inverse(bad), SingularityError);
    BOOST_CHECK_THROW(P::material_tangent_inverse(bad), SingularityError);
    BOOST_CHECK_THROW(P::spatial_tangent_derivative(bad, good), SingularityError);
    BOOST_CHECK_THROW(P::material_tangent_derivative(good, bad), SingularityError);
    BOOST_CHECK_THROW(P::spatial_tangent_inverse_derivative(bad, Vec3::Ones()), SingularityError);
    BOOST_CHECK_THROW(P::material_tangent_inverse_derivative(good, inf_vec), SingularityError);
    BOOST_CHECK_THROW(P::angle(bad), SingularityError);
    BOOST_CHECK_THROW(P::rescale(bad, good), SingularityError);
    BOOST_CHECK_THROW(P::rescale(good, bad), SingularityError);
    BOOST_CHECK_THROW(P::from_rotation_vector(inf_vec), SingularityError);
    BOOST_CHECK_THROW(P::to_rotation_vector(bad), SingularityError);
    BOOST_CHECK_THROW(P::from_matrix(Mat3::Constant(std::nan(""))), SingularityError);
    const double angle = refusal_angle<P>([&] { P::matrix(bad); }, "matrix");
    BOOST_TEST(std::isnan(angle));
}

BOOST_AUTO_TEST_CASE(wiener_milenkovic_refuses_2pi_and_beyond) {
    using WM = param::WienerMilenkovic;
    const Vec3 n = generic_axis();
    const double phi =
        refusal_angle<WM>([&] { WM::from_rotation_vector(2.0 * kPi * n); }, "from_rotation_vector");
    BOOST_TEST(phi == 2.0 * kPi);
    BOOST_CHECK_THROW(WM::from_rotation_vector(3.0 * kPi * n), SingularityError);
    // |c| = 1e14 is within the guard of 2π (2π − φ = 16/|c| = 1.6e-13).
    const Vec3 huge = 1e14 * n;
    const double at = refusal_angle<WM>([&] { WM::matrix(huge); }, "matrix");
    BOOST_TEST(at == 2.0 * kPi, boost::test_tools::tolerance(1e-12));
    BOOST_CHECK_THROW(WM::material_tangent(huge), SingularityError);
    BOOST_CHECK_THROW(WM::material_tangent_inverse(huge), SingularityError);
    // Two half turns about one axis compose to 2π exactly.
    const Vec3 half = WM::from_rotation_vector(kPi * n);
    refusal_angle<WM>([&] { WM::compose(half, half); }, "compose");
    // Just inside the chart everything is finite.
    const Vec3 inside = WM::from_rotation_vector((2.0 * kPi - 1e-6) * n);
    BOOST_TEST(WM::matrix(inside).allFinite());
    BOOST_TEST(WM::material_tangent_inverse(inside).allFinite());
    const Vec3 edge = WM::from_rotation_vector((2.0 * kPi - 2e-12) * n);
    BOOST_TEST(WM::material_tangent_inverse(edge).allFinite());
    BOOST_CHECK_THROW(WM::from_rotation_vector((2.0 * kPi - 0.5e-12) * n), SingularityError);
}

BOOST_AUTO_TEST_CASE(rodrigues_refuses_pi_and_beyond) {
    using Rod = param::Rodrigues;
    const Vec3 n = generic_axis();
    const double phi =
        refusal_angle<Rod>([&] { Rod::from_rotation_vector(kPi * n); }, "from_rotation_vector");
    BOOST_TEST(phi == kPi);
    BOOST_CHECK_THROW(Rod::from_rotation_vector((kPi + 1e-6) * n), SingularityError);
    BOOST_CHECK_THROW(Rod::matrix(Vec3(1e13 * n)), SingularityError);
    BOOST_CHECK_THROW(Rod::from_matrix(so3::exp_map(kPi * n)), SingularityError);
    // π/2 + 0.6 and π/2 about one axis compose past π.
    const Vec3 a = Rod::from_rotation_vector((0.5 * kPi + 0.6) * n);
    const Vec3 b = Rod::from_rotation_vector(0.5 * kPi * n);
    refusal_angle<Rod>([&] { Rod::compose(a, b); }, "compose");
    BOOST_TEST(Rod::matrix(Rod::from_rotation_vector((kPi - 1e-6) * n)).allFinite());
    // The guard is 1e-12 rad, consistently for rotation vectors and parameters.
    const Vec3 edge = Rod::from_rotation_vector((kPi - 2e-12) * n);
    BOOST_TEST(Rod::material_tangent_inverse(edge).allFinite());
    BOOST_CHECK_THROW(Rod::from_rotation_vector((kPi - 0.5e-12) * n), SingularityError);
}

BOOST_AUTO_TEST_CASE(rotation_vector_tangents_refuse_full_turns_but_its_matrix_does_not) {
    using RV = param::RotationVector;
    const Vec3 n = generic_axis();
    for (int k = 1; k <= 3; ++k) {
        const Vec3 psi = 2.0 * kPi * k * n;
        BOOST_TEST_CONTEXT("at 2π·" << k) {
            BOOST_TEST((RV::matrix(psi) - Mat3::Identity()).norm() <= 16.0 * kEps * k);
            const double phi =
                refusal_angle<RV>([&] { RV::spatial_tangent(psi); }, "spatial_tangent");
            BOOST_TEST(phi == 2.0 * kPi * k, boost::test_tools::tolerance(1e-14));
            BOOST_CHECK_THROW(RV::material_tangent(psi), SingularityError);
            BOOST_CHECK_THROW(RV::spatial_tangent_inverse(psi), SingularityError);
            BOOST_CHECK_THROW(RV::material_tangent_inverse(psi), SingularityError);
            BOOST_CHECK_THROW(RV::spatial_tangent_derivative(psi, n), SingularityError);
            BOOST_CHECK_THROW(RV::material_tangent_inverse_derivative(psi, n), SingularityError);
        }
    }
    // Between full turns the tangents are defined again.
    BOOST_TEST(RV::spatial_tangent_inverse(3.0 * kPi * n).allFinite());
}

BOOST_AUTO_TEST_CASE(euler_angles_tangents_refuse_gimbal_lock_but_their_matrix_does_not) {
    using E = param::EulerAngles;
    for (double a2 : {0.5 * kPi, -0.5 * kPi, 1.5 * kPi}) {
        const Vec3 p(0.3, a2, -0.2);
        BOOST_TEST_CONTEXT("at a2 = " << a2) {
            const Mat3 R = E::matrix(p);
            BOOST_TEST((R.transpose() * R - Mat3::Identity()).norm() <= 8.0 * kEps);
            // At lock only a1 ∓ a3 is determined; from_matrix picks a split with the same R.
            BOOST_TEST((E::matrix(E::from_matrix(R)) - R).norm() <= 8.0 * kEps);
            const double phi = refusal_angle<E>([&] { E::spatial_tangent(p); }, "spatial_tangent");
            BOOST_TEST(phi == so3::rotation_angle(R), boost::test_tools::tolerance(1e-14));
            BOOST_CHECK_THROW(E::material_tangent(p), SingularityError);
            BOOST_CHECK_THROW(E::spatial_tangent_inverse(p), SingularityError);
            BOOST_CHECK_THROW(E::material_tangent_inverse(p), SingularityError);
            BOOST_CHECK_THROW(E::spatial_tangent_derivative(p, p), SingularityError);
            BOOST_CHECK_THROW(E::material_tangent_derivative(p, p), SingularityError);
            BOOST_CHECK_THROW(E::spatial_tangent_inverse_derivative(p, p), SingularityError);
            BOOST_CHECK_THROW(E::material_tangent_inverse_derivative(p, p), SingularityError);
            BOOST_TEST(E::gimbal_distance(p) <= 2.0 * kEps * std::abs(a2));
        }
    }
    // On the roll-up (a bend about the middle axis y) lock is a quarter turn: singular_angle().
    const Vec3 quarter = E::from_rotation_vector(Vec3(0.0, 0.5 * kPi, 0.0));
    BOOST_TEST(E::gimbal_distance(quarter) <= 1e-15);
    BOOST_TEST(E::singular_angle() == 0.5 * kPi);
    BOOST_CHECK_THROW(E::material_tangent_inverse(quarter), SingularityError);
    // A quarter turn about x or z is nowhere near lock.
    BOOST_TEST(E::gimbal_distance(E::from_rotation_vector(Vec3(0.5 * kPi, 0.0, 0.0))) == 0.5 * kPi);
    BOOST_TEST(E::gimbal_distance(E::from_rotation_vector(Vec3(0.0, 0.0, 0.5 * kPi))) == 0.5 * kPi);
    // The guard is 1e-12 rad of the middle angle.
    BOOST_TEST(E::material_tangent_inverse(Vec3(0.3, 0.5 * kPi - 2e-12, -0.2)).allFinite());
    BOOST_CHECK_THROW(E::material_tangent_inverse(Vec3(0.3, 0.5 * kPi - 0.5e-12, -0.2)),
                      SingularityError);
}

BOOST_AUTO_TEST_CASE(euler_angles_rescale_switches_branch_and_full_turns) {
    // (a1 + π, π − a2, a3 + π) is the same rotation (R3(π) R2(π − a2) R1(π) = R2(a2)).
    using E = param::EulerAngles;
    const Vec3 p(2.9, 0.5 * kPi + 0.3, -3.0);
    const Vec3 other(2.9 - kPi, 0.5 * kPi - 0.3, -3.0 + kPi);  // the branch nearest 0
    BOOST_TEST((E::matrix(other) - E::matrix(p)).norm() <= 8.0 * kEps);
    BOOST_TEST((E::rescale(p, Vec3::Zero()) - other).norm() <= 8.0 * kEps);
    BOOST_TEST((E::rescale(p, p) - p).norm() == 0.0);
    const Vec3 turned(0.4 + 4.0 * kPi, 0.1 - 2.0 * kPi, -0.2);
    BOOST_TEST((E::rescale(turned, Vec3::Zero()) - Vec3(0.4, 0.1, -0.2)).norm() <= 32.0 * kEps);
}

BOOST_AUTO_TEST_CASE(quaternion_refuses_zero_and_has_no_singular_angle) {
    using Q = param::Quaternion;
    refusal_angle<Q>([] { Q::matrix(Vec4::Zero()); }, "matrix");
    BOOST_CHECK_THROW(Q::spatial_tangent_inverse(Vec4::Zero()), SingularityError);
    BOOST_CHECK_THROW(Q::inverse(Vec4::Zero()), SingularityError);
    BOOST_TEST(std::isinf(Q::singular_angle()));
    for (double phi : {kPi, 2.0 * kPi, 4.0 * kPi, 7.0}) {
        const Vec4 q = Q::from_rotation_vector(phi * generic_axis());
        BOOST_TEST(Q::matrix(q).allFinite());
        BOOST_TEST(Q::spatial_tangent_inverse(q).allFinite());
    }
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace rotbeam::test
