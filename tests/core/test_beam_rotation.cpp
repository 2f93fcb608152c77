// The rotation angle continued along the beam (core/beam_rotation.hpp) and the kinematic check of
// the mixed elements (core/kinematic_check.hpp), on stations built from known rotation fields.
#include <boost/test/unit_test.hpp>
#include <cmath>

#include "core/beam_rotation.hpp"
#include "core/kinematic_check.hpp"
#include "core/so3.hpp"

using namespace rotbeam;
using Station = StaticProblem::RotationStation;

namespace {

// A cantilever root → tip, clamped at the root.
Model cantilever() {
    Model m;
    m.points = {{"root", Vec3::Zero()}, {"tip", Vec3(1, 0, 0)}};
    Member beam;
    beam.name = "beam";
    beam.start_point = 0;
    beam.end_point = 1;
    m.members = {beam};
    Constraint c;
    c.point = 0;
    m.constraints = {c};
    return m;
}

// n + 1 node stations of R(s) = exp(s ψ_tip) on member 0, s = 0 … 1.
std::vector<Station> fixed_axis(const Vec3& psi_tip, int n) {
    std::vector<Station> out;
    for (int k = 0; k <= n; ++k) out.push_back({0, true, so3::exp_map(psi_tip * k / n)});
    return out;
}

// R(s) = exp(α(s) e1) exp(β(s) e3): an axis that varies along the beam, turning 2.5π about e1.
Mat3 precessing(double s) {
    return so3::exp_map(Vec3(2.5 * kPi * s, 0, 0)) *
           so3::exp_map(Vec3(0, 0, 0.8 * std::sin(kPi * s)));
}

}  // namespace

BOOST_AUTO_TEST_SUITE(beam_rotation)

// About a fixed axis the continued angle is the exact total turn: 2π and 4π, not 0 — the
// definition a one-step roll-up needs. Stations π/8 and π/4 apart (16 elements to λ = 2, 4).
BOOST_AUTO_TEST_CASE(a_fixed_axis_reports_the_whole_turn) {
    const Model m = cantilever();
    const std::vector<PointState> states(2);
    for (double turns : {1.0, 2.0}) {
        const Vec3 psi(0, -2.0 * kPi * turns, 0);
        const std::vector<Vec3> v = rotation_vectors_along_beam(m, fixed_axis(psi, 16), states);
        BOOST_TEST((v[1] - psi).norm() < 1e-12);
        BOOST_TEST(v[0].norm() == 0.0);
        BOOST_TEST(std::abs(largest_continued_angle(m, fixed_axis(psi, 16)) - psi.norm()) < 1e-12);
    }
}

// The walk starts at the supported point whichever end of the member it is, and passes a joint
// on to the next member: root clamped at the END of member "a", a runs tip-ward backwards.
BOOST_AUTO_TEST_CASE(the_walk_starts_at_the_support_and_crosses_joints) {
    Model m;
    m.points = {{"joint", Vec3(1, 0, 0)}, {"root", Vec3::Zero()}, {"tip", Vec3(2, 0, 0)}};
    Member a, b;
    a.name = "a";
    a.start_point = 0;  // joint → root: stations run from the joint to the root
    a.end_point = 1;
    b.name = "b";
    b.start_point = 0;
    b.end_point = 2;
    m.members = {a, b};
    Constraint c;
    c.point = 1;
    m.constraints = {c};
    const Vec3 axis = Vec3(0.6, 0, 0.8);
    std::vector<Station> st;
    for (int k = 8; k >= 0; --k) st.push_back({0, true, so3::exp_map(axis * (1.5 * kPi * k / 8))});
    for (int k = 8; k <= 16; ++k) st.push_back({1, true, so3::exp_map(axis * (1.5 * kPi * k / 8))});
    const std::vector<Vec3> v = rotation_vectors_along_beam(m, st, std::vector<PointState>(3));
    BOOST_TEST(v[1].norm() == 0.0);
    BOOST_TEST((v[0] - 1.5 * kPi * axis).norm() < 1e-12);
    BOOST_TEST((v[2] - 3.0 * kPi * axis).norm() < 1e-12);
}

// About a varying axis the result is the continuous lift of R(s): the same from 64 stations as
// from 4096 (the lift is unique while stations are a fraction of a turn apart).
BOOST_AUTO_TEST_CASE(a_varying_axis_gives_the_continuous_lift) {
    const Model m = cantilever();
    auto sampled = [&](int n) {
        std::vector<Station> st;
        for (int k = 0; k <= n; ++k) st.push_back({0, true, precessing(double(k) / n)});
        return rotation_vectors_along_beam(m, st, std::vector<PointState>(2))[1];
    };
    const Vec3 coarse = sampled(64), fine = sampled(4096);
    BOOST_TEST((coarse - fine).norm() < 1e-12);
    BOOST_TEST(so3::rotation_angle(so3::exp_map(fine).transpose() * precessing(1.0)) < 1e-12);
    BOOST_TEST(fine.norm() > kPi);  // past the principal range
}

// Elements whose nodes are exactly exp(turn) apart pass; one whose end node misses its turn by
// more than a tenth of it is named, with its index in the member.
BOOST_AUTO_TEST_CASE(the_kinematic_check_names_the_element_that_misses_its_turn) {
    std::vector<Station> st;
    Mat3 R = Mat3::Identity();
    st.push_back({0, true, R});
    for (int e = 0; e < 8; ++e) {
        const Vec3 turn(0.3, 0.2 * e, -0.1);
        st.push_back({0, false, R * so3::exp_map(0.5 * turn), turn});
        R = R * so3::exp_map(turn);
        st.push_back({0, true, R});
    }
    std::optional<KinematicDefect> d = worst_kinematic_defect(st);
    BOOST_TEST_REQUIRE(d.has_value());
    BOOST_TEST(within_kinematic_bound(*d));
    BOOST_TEST(d->defect < 1e-14);
    // Element 5 (stations 8, 9, 10): its end node, and everything beyond, turned by a further
    // 0.2 |turn| about the end node's e3. Only element 5's relative rotation changes.
    const double extra = 0.2 * st[9].turn.norm();
    const Mat3 Rb = st[10].rotation;
    const Mat3 X = Rb * so3::exp_map(Vec3(0, 0, extra)) * Rb.transpose();
    for (std::size_t k = 10; k < st.size(); ++k) st[k].rotation = X * st[k].rotation;
    d = worst_kinematic_defect(st);
    BOOST_TEST_REQUIRE(d.has_value());
    BOOST_TEST(!within_kinematic_bound(*d));
    BOOST_TEST(d->element == 5);
    BOOST_TEST(std::abs(d->defect - extra) < 1e-12);
}

BOOST_AUTO_TEST_SUITE_END()
