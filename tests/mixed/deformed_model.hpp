// A strongly curved, coupled, loaded test structure shared by the mixed Jacobian tests (three and
// four rotation parameters): a quarter-circle arc and a twisted straight member with a fully
// populated compliance meeting at a joint, follower and dead point and distributed loads.
#pragma once

#include <cmath>

#include "core/model.hpp"
#include "tests/mixed/models.hpp"

namespace rotbeam::test {

// A fully populated, symmetric positive definite compliance of unit order (coupled section).
inline Mat6 coupled_compliance() {
    Mat6 B;
    for (int i = 0; i < 6; ++i) {
        for (int j = 0; j < 6; ++j) B(i, j) = 0.3 * std::sin(1.0 + 3.0 * i + 7.0 * j);
    }
    return B * B.transpose() + Mat6::Identity();
}

// Two members meeting at a joint: a quarter-circle arc (radius 2, clamped root) and a twisted
// straight member with a coupled section; follower and dead point and distributed loads.
inline Model deformed_test_model() {
    Model m;
    m.points = {{"root", Vec3::Zero()}, {"joint", Vec3(2, 2, 0)}, {"tip", Vec3(2, 3.5, 0.8)}};
    Section coupled;
    coupled.compliance = coupled_compliance();
    Member arc =
        member("arc", 0, 1, diagonal_section((Vec6() << 50, 20, 30, 2, 3, 4).finished()), 3);
    arc.line.kind = LineKind::arc;
    arc.line.center = Vec3(0, 2, 0);
    Member straight = member("straight", 1, 2, coupled, 3);
    straight.twist_end = 0.7;
    m.members = {arc, straight};
    m.constraints = {Constraint{0, Constraint::Kind::clamped, Vec3::Zero(), Vec3::Zero(), {}}};
    PointLoad follower;
    follower.point = 2;
    follower.force = Vec3(0.3, -0.5, 0.9);
    follower.moment = Vec3(-0.4, 0.2, 0.6);
    follower.frame = LoadFrame::follower;
    PointLoad dead;
    dead.point = 1;
    dead.force = Vec3(0.2, 0.1, -0.7);
    DistributedLoad fd;
    fd.member = 0;
    fd.force = Vec3(0.1, 0.4, -0.3);
    fd.moment = Vec3(0.2, -0.1, 0.3);
    fd.frame = LoadFrame::follower;
    DistributedLoad dd;
    dd.member = 1;
    dd.force = Vec3(-0.2, 0.1, 0.5);
    dd.moment = Vec3(0.1, 0.1, -0.2);
    m.point_loads = {follower, dead};
    m.distributed_loads = {fd, dd};
    return m;
}

// deformed_test_model with its tip also supported: a prescribed displacement and rotation
// (scaled by the load factor), so the tip's rotation is ρ times the given one with ρ an unknown
// (the quaternion's closure; mixed_layout.hpp).
inline Model two_support_model() {
    Model m = deformed_test_model();
    m.constraints.push_back(Constraint{
        2, Constraint::Kind::prescribed, Vec3(0.1, 0.2, -0.1), Vec3(0.3, -0.2, 0.5), {}});
    return m;
}

}  // namespace rotbeam::test
