// A strongly deformed, moving test structure for the mixed dynamics (issue 9): two members with
// fully populated sections (compliance and 6×6 mass with offsets) meeting at a joint, follower and
// dead point and distributed loads with time functions.
#pragma once

#include <cmath>

#include "core/model.hpp"
#include "tests/mixed/models.hpp"

namespace rotbeam::test {

// Symmetric positive definite 6×6 with unit-order entries (seeded by `seed`).
inline Mat6 coupled_spd(double seed) {
    Mat6 B;
    for (int i = 0; i < 6; ++i) {
        for (int j = 0; j < 6; ++j) B(i, j) = 0.3 * std::sin(seed + 3.0 * i + 7.0 * j);
    }
    return B * B.transpose() + Mat6::Identity();
}

// A section mass [m I, m ξ̃ᵀ; m ξ̃, ρ] with mass-centre offset ξ and a full inertia ρ.
inline Mat6 offset_mass(double m, const Vec3& xi, const Mat3& rho) {
    Mat6 I = Mat6::Zero();
    Mat3 xt;
    xt << 0, -xi.z(), xi.y(), xi.z(), 0, -xi.x(), -xi.y(), xi.x(), 0;
    I.topLeftCorner<3, 3>() = m * Mat3::Identity();
    I.topRightCorner<3, 3>() = m * xt.transpose();
    I.bottomLeftCorner<3, 3>() = m * xt;
    I.bottomRightCorner<3, 3>() = rho;
    return I;
}

inline Model dynamic_test_model() {
    Model m;
    m.points = {{"root", Vec3::Zero()}, {"joint", Vec3(2, 2, 0)}, {"tip", Vec3(2, 3.5, 0.8)}};
    Section arc_section = diagonal_section((Vec6() << 50, 20, 30, 2, 3, 4).finished());
    Mat3 rho;
    rho << 0.9, 0.1, -0.05, 0.1, 0.5, 0.02, -0.05, 0.02, 0.6;
    arc_section.mass = offset_mass(1.3, Vec3(0, 0.1, -0.05), rho);
    Section coupled;
    coupled.compliance = coupled_spd(1.0);
    coupled.mass = offset_mass(0.8, Vec3(0, -0.07, 0.12), 0.8 * rho);
    Member arc = member("arc", 0, 1, arc_section, 3);
    arc.line.kind = LineKind::arc;
    arc.line.center = Vec3(0, 2, 0);
    Member straight = member("straight", 1, 2, coupled, 3);
    straight.twist_end = 0.7;
    m.members = {arc, straight};
    m.constraints = {Constraint{0, Constraint::Kind::clamped, Vec3::Zero(), Vec3::Zero(), {}}};
    TimeFunction sine;
    sine.kind = TimeFunction::Kind::sine;
    sine.value = 1.0;
    sine.omega = 3.0;
    sine.phase = 0.4;
    PointLoad follower;
    follower.point = 2;
    follower.force = Vec3(0.3, -0.5, 0.9);
    follower.moment = Vec3(-0.4, 0.2, 0.6);
    follower.frame = LoadFrame::follower;
    follower.time = sine;
    PointLoad dead;
    dead.point = 1;
    dead.force = Vec3(0.2, 0.1, -0.7);
    DistributedLoad fd;
    fd.member = 0;
    fd.force = Vec3(0.1, 0.4, -0.3);
    fd.moment = Vec3(0.2, -0.1, 0.3);
    fd.frame = LoadFrame::follower;
    fd.time = sine;
    DistributedLoad dd;
    dd.member = 1;
    dd.force = Vec3(-0.2, 0.1, 0.5);
    dd.moment = Vec3(0.1, 0.1, -0.2);
    m.point_loads = {follower, dead};
    m.distributed_loads = {fd, dd};
    return m;
}

}  // namespace rotbeam::test
