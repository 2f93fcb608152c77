// Algebraic identities of every parameterization on the shared hard sample set.
#include <boost/test/unit_test.hpp>

#include "tests/harness/coverage.hpp"
#include "tests/parameterizations/samples.hpp"

namespace rotbeam::test {
namespace {

// R(p) for the sample φ about the generic axis, or false when P's chart does not contain it.
template <class P>
bool sample_parameters(const Sample& s, typename P::P& p) {
    if (!chart_contains<P>(s.angle)) return false;
    p = P::from_rotation_vector(s.angle * generic_axis());
    checked("identity", P::kName, s.label);
    return true;
}

// The rotation angle of the rotation taking ψ's chart continuation: φ of the product quaternion
// (in [0, 2π], the quaternion tracks angles past π on its w < 0 hemisphere).
double composite_quaternion_angle(const Vec3& a, const Vec3& b) {
    using Q = param::Quaternion;
    return Q::angle(Q::compose(Q::from_rotation_vector(a), Q::from_rotation_vector(b)));
}

}  // namespace

BOOST_AUTO_TEST_SUITE(parameterization_identities)

BOOST_AUTO_TEST_CASE_TEMPLATE(matrix_is_orthogonal_unimodular_and_equals_exp, P,
                              AllParameterizationTypes) {
    for (const Sample& s : hard_samples()) {
        typename P::P p;
        if (!sample_parameters<P>(s, p)) continue;
        BOOST_TEST_CONTEXT(P::kName << " at " << s.label) {
            const Mat3 R = P::matrix(p);
            BOOST_TEST((R.transpose() * R - Mat3::Identity()).norm() <= 1e-14);
            BOOST_TEST(std::abs(R.determinant() - 1.0) <= 1e-14);
            // Same rotation as Rodrigues' formula of ψ (so3::exp_map); both round φ·n to ε.
            const Mat3 R_exp = so3::exp_map(s.angle * generic_axis());
            BOOST_TEST((R - R_exp).norm() <= 4.0 * kEps * (1.0 + s.angle));
        }
    }
}

BOOST_AUTO_TEST_CASE_TEMPLATE(compose_multiplies_matrices_or_refuses_past_the_singular_angle, P,
                              AllParameterizationTypes) {
    const std::vector<Vec3> others = {0.4 * other_axis(), 1e-3 * other_axis(), -1.2 * other_axis()};
    for (const Sample& s : hard_samples()) {
        typename P::P a;
        if (!sample_parameters<P>(s, a)) continue;
        for (const Vec3& psi_b : others) {
            BOOST_TEST_CONTEXT(P::kName << " at " << s.label << ", b = " << psi_b.transpose()) {
                const typename P::P b = P::from_rotation_vector(psi_b);
                const Vec3 psi_a = s.angle * generic_axis();
                for (int order = 0; order < 2; ++order) {
                    const typename P::P& x = order == 0 ? a : b;
                    const typename P::P& y = order == 0 ? b : a;
                    try {
                        const Mat3 R = P::matrix(P::compose(x, y));
                        BOOST_TEST((R - P::matrix(x) * P::matrix(y)).norm() <=
                                   8.0 * kEps * (1.0 + s.angle));
                    } catch (const SingularityError& e) {
                        // Refusal is right only when the composite passes the singular angle.
                        const double phi = order == 0 ? composite_quaternion_angle(psi_a, psi_b)
                                                      : composite_quaternion_angle(psi_b, psi_a);
                        BOOST_TEST(phi >= P::singular_angle() - 1e-9, e.what());
                    }
                }
            }
        }
    }
}

BOOST_AUTO_TEST_CASE_TEMPLATE(compose_with_inverse_is_identity, P, AllParameterizationTypes) {
    for (const Sample& s : hard_samples()) {
        typename P::P p;
        if (!sample_parameters<P>(s, p)) continue;
        BOOST_TEST_CONTEXT(P::kName << " at " << s.label) {
            const typename P::P e1 = P::compose(p, P::inverse(p));
            const typename P::P e2 = P::compose(P::inverse(p), p);
            BOOST_TEST((e1 - P::identity()).norm() <= 4.0 * kEps * (1.0 + s.angle));
            BOOST_TEST((e2 - P::identity()).norm() <= 4.0 * kEps * (1.0 + s.angle));
            BOOST_TEST((P::matrix(P::identity()) - Mat3::Identity()).norm() == 0.0);
        }
    }
}

BOOST_AUTO_TEST_CASE_TEMPLATE(rescale_keeps_the_rotation_and_shortens_the_angle, P,
                              AllParameterizationTypes) {
    for (const Sample& s : hard_samples()) {
        typename P::P p;
        if (!sample_parameters<P>(s, p)) continue;
        BOOST_TEST_CONTEXT(P::kName << " at " << s.label) {
            const typename P::P r = P::rescale(p, P::identity());
            BOOST_TEST((P::matrix(r) - P::matrix(p)).norm() <= 8.0 * kEps * (1.0 + s.angle));
            if constexpr (P::kCanRescale) {
                BOOST_TEST(P::angle(r) <= kPi + 1e-9);
                // Rescaling relative to the parameters themselves changes nothing but the norm
                // (the quaternion is normalized).
                const typename P::P same = P::rescale(p, p);
                BOOST_TEST((P::matrix(same) - P::matrix(p)).norm() <= 8.0 * kEps * (1.0 + s.angle));
                BOOST_TEST(std::abs(P::angle(same) - P::angle(p)) <= 8.0 * kEps * (1.0 + s.angle));
            } else {
                BOOST_TEST((r - p).norm() == 0.0);  // Rodrigues: no second chart
            }
        }
    }
}

BOOST_AUTO_TEST_CASE_TEMPLATE(rotation_vector_round_trip_error_grows_like_eps_over_distance, P,
                              AllParameterizationTypes) {
    // Tolerance 8 ε (1 + φ) / min(1, δ), δ = distance of φ to where the conversion loses the
    // axis or the angle (conversion_distance): the axis or the scale of p is then known only to
    // ε/δ relative.
    for (const Sample& s : hard_samples()) {
        typename P::P p;
        if (!sample_parameters<P>(s, p)) continue;
        BOOST_TEST_CONTEXT(P::kName << " at " << s.label) {
            const Vec3 psi = s.angle * generic_axis();
            const Vec3 back = param::RotationVector::rescale(P::to_rotation_vector(p), psi);
            const double delta = std::min(1.0, conversion_distance<P>(s.angle));
            BOOST_TEST((back - psi).norm() <= 8.0 * kEps * s.angle / delta);
        }
    }
}

BOOST_AUTO_TEST_CASE_TEMPLATE(from_matrix_recovers_the_rotation, P, AllParameterizationTypes) {
    for (const Sample& s : hard_samples()) {
        typename P::P p;
        // Rodrigues refuses matrices within the guard of π; every sample it contains is farther.
        if (!sample_parameters<P>(s, p)) continue;
        BOOST_TEST_CONTEXT(P::kName << " at " << s.label) {
            const Mat3 R = P::matrix(p);
            const Mat3 back = P::matrix(P::from_matrix(R));
            const double delta = std::min(1.0, tangent_distance<P>(s.angle));
            BOOST_TEST((back - R).norm() <= 8.0 * kEps * (1.0 + s.angle) / delta);
        }
    }
}

BOOST_AUTO_TEST_CASE_TEMPLATE(small_angle_matrix_and_tangent_are_accurate_to_1e15, P,
                              AllParameterizationTypes) {
    // At φ = 1e-9 every second-order term is symmetric and ~1e-18, so the skew parts must be
    // exactly first order: axial(R) = sin φ n = ψ (1 − φ²/6) and axial(H_s) = ψ/2 (1 + O(φ²)),
    // to 1e-15 relative. This catches a series branch with a wrong coefficient or a cancellation.
    const Vec3 psi = 1e-9 * generic_axis();
    const typename P::P p = P::from_rotation_vector(psi);
    const Mat3 R = P::matrix(p);
    BOOST_TEST((so3::axial(R) - psi).norm() <= 1e-15 * psi.norm());
    BOOST_TEST((R.diagonal() - Vec3::Ones()).norm() <= 2.0 * kEps);
    const param::Tangent<P::kSize> Hs = P::spatial_tangent(p);
    const param::Tangent<P::kSize> Hm = P::material_tangent(p);
    if constexpr (std::is_same_v<P, param::EulerAngles>) {
        // Euler angles have no series branch, and their H is not I ± ψ̃/2 to first order: with
        // p = (a1, a2, a3), H_s = I + [0 −a3 0; a3 0 0; −a2 0 0] + O(φ²) and
        // H_m = I + [0 0 −a2; 0 0 a1; 0 −a1 0] + O(φ²) (euler_angles.hpp, E2 and E3), whose
        // skew parts are (0, a2/2, a3) and (−a1, −a2/2, 0), to 1e-15 relative at φ = 1e-9.
        BOOST_TEST((so3::axial(Hs) - Vec3(0.0, 0.5 * p[1], p[2])).norm() <= 1e-15 * psi.norm());
        BOOST_TEST((so3::axial(Hm) - Vec3(-p[0], -0.5 * p[1], 0.0)).norm() <= 1e-15 * psi.norm());
        return;
    }
    Mat3 Bs, Bm;  // the 3×3 block that multiplies the vector part
    if constexpr (P::kSize == 4) {
        // q = (cos φ/2, sin φ/2 n): H = 2 E(q), block = I ± ψ̃ (1 + O(φ²)), column 0 = −ψ.
        BOOST_TEST((Hs.col(0) + psi).norm() <= 1e-15 * psi.norm());
        Bs = 0.5 * Hs.template rightCols<3>();
        Bm = 0.5 * Hm.template rightCols<3>();
    } else {
        Bs = Hs;
        Bm = Hm;
    }
    const double scale = P::kSize == 4 ? 2.0 : 1.0;  // quaternion block: ψ̃/2 · 2 / 2
    BOOST_TEST((scale * so3::axial(Bs) - 0.5 * scale * psi).norm() <= 1e-15 * psi.norm());
    BOOST_TEST((scale * so3::axial(Bm) + 0.5 * scale * psi).norm() <= 1e-15 * psi.norm());
}

BOOST_AUTO_TEST_CASE(quaternion_and_rotation_vector_give_the_same_matrix) {
    for (const Sample& s : hard_samples()) {
        BOOST_TEST_CONTEXT("at " << s.label) {
            const Vec3 psi = s.angle * generic_axis();
            const Mat3 Rq = param::Quaternion::matrix(param::Quaternion::from_rotation_vector(psi));
            const Mat3 Rv = param::RotationVector::matrix(psi);
            BOOST_TEST((Rq - Rv).norm() <= 4.0 * kEps * (1.0 + s.angle));
        }
    }
}

BOOST_AUTO_TEST_CASE(quaternion_matrix_is_homogeneous_off_the_unit_sphere) {
    const Vec4 q = param::Quaternion::from_rotation_vector(2.0 * generic_axis());
    for (double scale : {1e-3, 0.5, 7.0, -3.0}) {
        const Vec4 qs = scale * q;
        BOOST_TEST((param::Quaternion::matrix(qs) - param::Quaternion::matrix(q)).norm() <=
                   8.0 * kEps);
    }
}

BOOST_AUTO_TEST_CASE(wiener_milenkovic_matches_seed_002_as_printed) {
    // Eq. 14 (C = Rᵀ), Eq. 24 (Q = H_m, the material tangent) and Eq. 25 (Q⁻¹), written out
    // literally; the finite-difference tests prove that this Q satisfies Rᵀ δR = (Q δc)~.
    using WM = param::WienerMilenkovic;
    const Vec3 c = WM::from_rotation_vector(2.2 * generic_axis());
    const double c0 = 2.0 - c.squaredNorm() / 8.0;
    const double d = (4.0 - c0) * (4.0 - c0);
    const double c1 = c[0], c2 = c[1], c3 = c[2];
    Mat3 C;
    C << c0 * c0 + c1 * c1 - c2 * c2 - c3 * c3, 2 * (c1 * c2 + c0 * c3), 2 * (c1 * c3 - c0 * c2),
        2 * (c1 * c2 - c0 * c3), c0 * c0 - c1 * c1 + c2 * c2 - c3 * c3, 2 * (c2 * c3 + c0 * c1),
        2 * (c1 * c3 + c0 * c2), 2 * (c2 * c3 - c0 * c1), c0 * c0 - c1 * c1 - c2 * c2 + c3 * c3;
    C /= d;
    const Mat3 Q = ((4.0 - c.squaredNorm() / 4.0) * Mat3::Identity() - 2.0 * so3::skew(c) +
                    0.5 * c * c.transpose()) /
                   d;
    const Mat3 Q_inverse = (1.0 - c.squaredNorm() / 16.0) * Mat3::Identity() + 0.5 * so3::skew(c) +
                           0.125 * c * c.transpose();
    BOOST_TEST((WM::matrix(c) - C.transpose()).norm() <= 8.0 * kEps);
    BOOST_TEST((WM::material_tangent(c) - Q).norm() <= 8.0 * kEps);
    BOOST_TEST((WM::material_tangent_inverse(c) - Q_inverse).norm() <=
               8.0 * kEps * Q_inverse.norm());
}

BOOST_AUTO_TEST_CASE(rodrigues_matches_the_gebt_formulas) {
    // Rᵀ = [(1 − pᵀp/4) I − p̃ + p pᵀ/2]/(1 + pᵀp/4), Q = (I − p̃/2)/(1 + pᵀp/4),
    // Q⁻¹ = I + p̃/2 + p pᵀ/4 (docs/parameterizations.md).
    using Rod = param::Rodrigues;
    const Vec3 p = Rod::from_rotation_vector(2.2 * generic_axis());
    const double s = p.squaredNorm();
    const Mat3 Rt = ((1.0 - s / 4.0) * Mat3::Identity() - so3::skew(p) + 0.5 * p * p.transpose()) /
                    (1.0 + s / 4.0);
    const Mat3 Q = (Mat3::Identity() - 0.5 * so3::skew(p)) / (1.0 + s / 4.0);
    const Mat3 Q_inverse = Mat3::Identity() + 0.5 * so3::skew(p) + 0.25 * p * p.transpose();
    BOOST_TEST((Rod::matrix(p).transpose() - Rt).norm() <= 8.0 * kEps);
    BOOST_TEST((Rod::material_tangent(p) - Q).norm() <= 8.0 * kEps);
    BOOST_TEST((Rod::material_tangent_inverse(p) - Q_inverse).norm() <=
               8.0 * kEps * Q_inverse.norm());
}

BOOST_AUTO_TEST_CASE(wiener_milenkovic_rescale_uses_the_complementary_parameters) {
    // Past π: c' = 4 tan((φ − 2π)/4) n (docs/parameterizations.md), the same R.
    using WM = param::WienerMilenkovic;
    const double phi = 1.5 * kPi;
    const Vec3 c = WM::from_rotation_vector(phi * generic_axis());
    const Vec3 expected = 4.0 * std::tan(0.25 * (phi - 2.0 * kPi)) * generic_axis();
    BOOST_TEST((WM::rescale(c, Vec3::Zero()) - expected).norm() <= 8.0 * kEps);
    // Relative to a reference on the long chart, the long chart is kept.
    BOOST_TEST((WM::rescale(c, c) - c).norm() == 0.0);
}

BOOST_AUTO_TEST_CASE(quaternion_rescale_picks_the_reference_hemisphere) {
    using Q = param::Quaternion;
    const Vec4 q = Q::from_rotation_vector(1.8 * kPi * generic_axis());  // w < 0
    const Vec4 r = Q::rescale(2.0 * q, Q::identity());
    BOOST_TEST(r[0] > 0.0);
    BOOST_TEST(std::abs(r.norm() - 1.0) <= 2.0 * kEps);
    BOOST_TEST((Q::rescale(2.0 * q, q) - q).norm() <= 4.0 * kEps);
}

BOOST_AUTO_TEST_CASE(rotation_vector_rescale_reduces_by_full_turns) {
    using RV = param::RotationVector;
    const Vec3 n = generic_axis();
    BOOST_TEST((RV::rescale(3.0 * kPi * n, Vec3::Zero()).norm() - kPi) <= 8.0 * kEps);
    BOOST_TEST((RV::rescale(1.5 * kPi * n, Vec3::Zero()) + 0.5 * kPi * n).norm() <= 8.0 * kEps);
    BOOST_TEST((RV::rescale(0.5 * kPi * n, 4.0 * kPi * n) - 4.5 * kPi * n).norm() <= 32.0 * kEps);
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace rotbeam::test
