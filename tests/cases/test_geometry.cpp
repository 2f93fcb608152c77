// Reference geometry: exact arc end points and tangents, orthonormal frames, curvature equal to
// the finite-difference derivative of the frame, arc-length parameterization of key-point curves.
#include <boost/test/unit_test.hpp>
#include <cmath>

#include "core/errors.hpp"
#include "core/geometry.hpp"
#include "core/so3.hpp"
#include "tests/cases/catalog_model.hpp"

using namespace rotbeam;

namespace {

Model two_point_model(const Vec3& a, const Vec3& b) {
    Model m;
    m.points = {{"root", a}, {"tip", b}};
    Member member;
    member.name = "beam";
    member.start_point = 0;
    member.end_point = 1;
    m.members.push_back(member);
    return m;
}

// The 45° bend of docs/benchmarks.md §2 (cases/bend-45.yaml): radius 100, centre (0, 100, 0), tip
// at 45°. The other models here are geometry variants, not catalog cases.
Model bend45() { return test::catalog_model("bend-45", {}); }

// A genuinely three-dimensional key-point curve with twist.
Model spatial_curve() {
    Model m = two_point_model(Vec3::Zero(), Vec3(10.0, 2.0, 3.0));
    m.members[0].line.kind = LineKind::keypoints;
    m.members[0].line.keypoints = {Vec3(3.0, 1.5, 0.5), Vec3(7.0, 0.5, 2.5)};
    m.members[0].twist_start = 0.2;
    m.members[0].twist_end = -0.7;
    return m;
}

double orthonormality_error(const Mat3& R) {
    return (R.transpose() * R - Mat3::Identity()).norm() + std::abs(R.determinant() - 1.0);
}

// k = axial(Rᵀ R′) with R′ by central differences. Step h = ∛ε·L: truncation h²|R‴|/6 and
// round-off ε/h are both ≈ 1e-11·L⁻¹·(curvature scale), so 1e-8 absolute on |k| ≤ 1 is safe.
Vec3 fd_curvature(const ReferenceGeometry& g, double s) {
    const double h = std::cbrt(2.2e-16) * g.length();
    const Mat3 dR = (g.frame(s + h) - g.frame(s - h)) / (2.0 * h);
    const Mat3 K = g.frame(s).transpose() * dR;
    return so3::axial(0.5 * (K - K.transpose()));
}

void check_curvature_against_frames(const ReferenceGeometry& g) {
    const double L = g.length();
    for (double f : {0.13, 0.37, 0.5, 0.71, 0.94}) {
        const Vec3 k = g.curvature(f * L);
        BOOST_TEST((k - fd_curvature(g, f * L)).norm() < 1e-8 * std::max(1.0, k.norm()),
                   "at s/L = " << f << ": k = " << k.transpose()
                               << ", fd = " << fd_curvature(g, f * L).transpose());
        BOOST_TEST(orthonormality_error(g.frame(f * L)) < 1e-13);
    }
}

}  // namespace

BOOST_AUTO_TEST_SUITE(reference_geometry)

BOOST_AUTO_TEST_CASE(bend45_arc_ends_at_published_tip_with_45_degree_tangent) {
    const Model m = bend45();
    const ReferenceGeometry g(m, 0);
    // The catalog's tip is 100 (sin 45°, 1 − cos 45°) to 16 digits: length and tip to round-off
    // of lengths ~100 (1e-12).
    BOOST_TEST(std::abs(g.length() - 100.0 * kPi / 4.0) < 1e-12);
    const Vec3 tip = g.position(g.length());
    BOOST_TEST((tip - m.points[1].position).norm() < 1e-12);
    const double c = std::sqrt(0.5);
    BOOST_TEST((g.tangent(g.length()) - Vec3(c, c, 0.0)).norm() < 1e-7);
    BOOST_TEST((g.tangent(0.0) - Vec3::UnitX()).norm() < 1e-12);
    // Root frame: e1 = x, e2 toward the centre = y, e3 = normal = z.
    BOOST_TEST((g.frame(0.0) - Mat3::Identity()).norm() < 1e-12);
    // Mid-arc point lies on the circle.
    BOOST_TEST(std::abs((g.position(0.5 * g.length()) - m.members[0].line.center).norm() - 100.0) <
               1e-9);
}

BOOST_AUTO_TEST_CASE(arc_curvature_is_one_over_radius_about_e3) {
    const ReferenceGeometry g(bend45(), 0);
    for (double f : {0.0, 0.3, 1.0}) {
        BOOST_TEST((g.curvature(f * g.length()) - Vec3(0.0, 0.0, 0.01)).norm() < 1e-14);
    }
}

BOOST_AUTO_TEST_CASE(arc_with_normal_goes_the_long_way_round) {
    Model m = bend45();
    m.members[0].line.normal = Vec3(0.0, 0.0, -1.0);
    const ReferenceGeometry g(m, 0);
    BOOST_TEST(std::abs(g.length() - 100.0 * (2.0 * kPi - kPi / 4.0)) < 1e-12);
    // Starting clockwise about +z: the tangent at the root is −x.
    BOOST_TEST((g.tangent(0.0) + Vec3::UnitX()).norm() < 1e-12);
    BOOST_TEST((g.position(g.length()) - m.points[1].position).norm() < 1e-12);
    check_curvature_against_frames(g);
}

BOOST_AUTO_TEST_CASE(straight_beam_along_x_has_identity_frame_and_no_curvature) {
    const ReferenceGeometry g(two_point_model(Vec3(1.0, 2.0, 3.0), Vec3(13.0, 2.0, 3.0)), 0);
    BOOST_TEST(g.length() == 12.0);
    for (double s : {0.0, 4.0, 12.0}) {
        BOOST_TEST((g.frame(s) - Mat3::Identity()).norm() == 0.0);
        BOOST_TEST(g.curvature(s).norm() == 0.0);
    }
    BOOST_TEST((g.position(4.0) - Vec3(5.0, 2.0, 3.0)).norm() < 1e-15);
}

BOOST_AUTO_TEST_CASE(beam_along_z_uses_projected_y_for_e2) {
    const ReferenceGeometry g(two_point_model(Vec3::Zero(), Vec3(0.0, 0.0, 5.0)), 0);
    const Mat3 R = g.frame(1.0);
    BOOST_TEST((R.col(0) - Vec3::UnitZ()).norm() < 1e-15);
    BOOST_TEST((R.col(1) - Vec3::UnitY()).norm() < 1e-15);
    BOOST_TEST(orthonormality_error(R) < 1e-15);
}

BOOST_AUTO_TEST_CASE(twist_rotates_e2_e3_about_e1_and_adds_torsional_curvature) {
    Model m = two_point_model(Vec3::Zero(), Vec3(8.0, 0.0, 0.0));
    m.members[0].twist_end = kPi / 2.0;
    const ReferenceGeometry g(m, 0);
    const Mat3 R = g.frame(8.0);
    BOOST_TEST((R.col(1) - Vec3::UnitZ()).norm() < 1e-15);
    BOOST_TEST((R.col(2) + Vec3::UnitY()).norm() < 1e-15);
    BOOST_TEST((g.curvature(3.0) - Vec3(kPi / 16.0, 0.0, 0.0)).norm() < 1e-15);
    check_curvature_against_frames(g);
}

BOOST_AUTO_TEST_CASE(twisted_arc_curvature_matches_frame_derivative) {
    Model m = bend45();
    m.members[0].twist_start = -0.4;
    m.members[0].twist_end = 1.1;
    check_curvature_against_frames(ReferenceGeometry(m, 0));
}

BOOST_AUTO_TEST_CASE(keypoint_curve_interpolates_points_and_is_unit_speed_in_s) {
    const Model m = spatial_curve();
    const ReferenceGeometry g(m, 0);
    BOOST_TEST((g.position(0.0) - Vec3::Zero()).norm() < 1e-14);
    BOOST_TEST((g.position(g.length()) - Vec3(10.0, 2.0, 3.0)).norm() < 1e-10);
    // |dx/ds| = 1 everywhere (arc-length reparameterization), checked by central differences:
    // truncation h²|x‴|/6 ≈ 1e-11, inversion tolerance 1e-13·L / h ≈ 1e-9.
    const double h = 1e-5 * g.length();
    double min_distance = 1e300;
    for (int i = 1; i < 50; ++i) {
        const double s = g.length() * i / 50.0;
        const double speed = (g.position(s + h) - g.position(s - h)).norm() / (2.0 * h);
        BOOST_TEST(std::abs(speed - 1.0) < 1e-8, "speed " << speed << " at s = " << s);
        BOOST_TEST((g.tangent(s) - (g.position(s + h) - g.position(s - h)) / (2.0 * h)).norm() <
                   1e-8);
    }
    // The curve passes through the first key point: the distance function has a zero.
    for (int i = 0; i <= 4000; ++i) {
        const double s = g.length() * i / 4000.0;
        min_distance =
            std::min(min_distance, (g.position(s) - m.members[0].line.keypoints[0]).norm());
    }
    BOOST_TEST(min_distance < g.length() / 4000.0);
    check_curvature_against_frames(g);
}

BOOST_AUTO_TEST_CASE(collinear_keypoints_give_the_exact_straight_length) {
    Model m = two_point_model(Vec3::Zero(), Vec3(3.0, 4.0, 0.0));
    m.members[0].line.kind = LineKind::keypoints;
    m.members[0].line.keypoints = {Vec3(0.6, 0.8, 0.0), Vec3(2.4, 3.2, 0.0)};
    const ReferenceGeometry g(m, 0);
    BOOST_TEST(std::abs(g.length() - 5.0) < 1e-12);
    BOOST_TEST((g.position(2.5) - Vec3(1.5, 2.0, 0.0)).norm() < 1e-11);
    BOOST_TEST(g.curvature(1.0).norm() < 1e-10);
}

// A hairpin (found by fuzzing the BeamDyn import): key points on x = 4·9e7·τ(1 − τ), z = 10 τ,
// a 1.8e8-long curve whose ends are 10 apart. At the apex the tangent nearly vanishes in the
// chord parameter, so |x_t| has a near-kink inside a knot interval and pieces of it next to the
// apex are tiny. The length is split at the apex and each piece is measured to 1e-13 of its knot
// interval. Checked with the apex on a key point (512) and between two (511): the curve is
// accepted, passes through the apex, and has unit speed in s away from it, to 1e-6 (the
// inversion's absolute tolerance 1e-13·9e7 over h = 1e-3·L is ~1e-7).
BOOST_AUTO_TEST_CASE(hairpin_keypoint_curve_is_measured_through_its_apex) {
    for (const int intervals : {512, 511}) {
        Model m = two_point_model(Vec3::Zero(), Vec3(0.0, 0.0, 10.0));
        m.members[0].line.kind = LineKind::keypoints;
        for (int k = 1; k < intervals; ++k) {
            const double tau = static_cast<double>(k) / intervals;
            m.members[0].line.keypoints.emplace_back(9e7 * 4.0 * tau * (1.0 - tau), 0.0,
                                                     10.0 * tau);
        }
        const ReferenceGeometry g(m, 0);
        BOOST_TEST_CONTEXT(intervals << " key-point intervals, length " << g.length()) {
            BOOST_TEST(g.length() > 1.8e8);
            BOOST_TEST(std::abs(g.position(0.5 * g.length()).x() - 9e7) < 1e-3 * 9e7);
            const double h = 1e-3 * g.length();
            for (int i = 1; i < 20; ++i) {
                if (2 * i == 20) continue;  // the apex: x(s ± h) nearly coincide
                const double s = g.length() * i / 20.0;
                const double speed = (g.position(s + h) - g.position(s - h)).norm() / (2.0 * h);
                BOOST_TEST(std::abs(speed - 1.0) < 1e-6, "speed " << speed << " at s = " << s);
            }
        }
    }
}

BOOST_AUTO_TEST_CASE(invalid_geometry_is_refused_with_input_error) {
    BOOST_CHECK_THROW(ReferenceGeometry(two_point_model(Vec3::Ones(), Vec3::Ones()), 0),
                      InputError);
    Model off_radius = bend45();
    off_radius.points[1].position = Vec3(70.0, 29.0, 0.0);
    BOOST_CHECK_THROW(ReferenceGeometry(off_radius, 0), InputError);
    Model half_circle = two_point_model(Vec3::Zero(), Vec3(0.0, 200.0, 0.0));
    half_circle.members[0].line.kind = LineKind::arc;
    half_circle.members[0].line.center = Vec3(0.0, 100.0, 0.0);
    BOOST_CHECK_THROW(ReferenceGeometry(half_circle, 0), InputError);
    half_circle.members[0].line.normal = Vec3::UnitZ();
    BOOST_TEST(std::abs(ReferenceGeometry(half_circle, 0).length() - 100.0 * kPi) < 1e-12);
}

BOOST_AUTO_TEST_SUITE_END()
