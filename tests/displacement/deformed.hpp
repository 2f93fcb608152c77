// The strongly deformed state on which the exact Jacobian is checked: a curved
// (quarter circle, radius 5, in a tilted plane) and twisted (0 → 1 rad) member, a fully populated
// coupled 6×6 section, follower tip force and moment, a follower distributed force, a dead
// distributed moment and gravity with an offset centre of mass, and a state whose tip rotation
// is 2.6 rad reached through the retraction.
#pragma once

#include "formulations/displacement/mesh.hpp"
#include "core/so3.hpp"
#include "models.hpp"

namespace rotbeam::test {

inline Mat6 coupled_section() {
    Mat6 C;
    C << 1.0e4, 120, -80, 30, -40, 25,
         120, 5.0e3, 60, -20, 15, -35,
         -80, 60, 4.0e3, 10, -25, 45,
         30, -20, 10, 60, 4, -6,
         -40, 15, -25, 4, 100, 8,
         25, -35, 45, -6, 8, 140;
    return C;
}

inline Model curved_twisted(int elements, int order, bool follower, bool gravity) {
    const Vec3 n = Vec3(0.2, -0.3, 1.0).normalized();
    const Vec3 a = Vec3(1.0, 0.4, 0.0).normalized().cross(n).normalized().cross(n);  // ⊥ n
    const Vec3 center = Vec3(1.0, 2.0, 0.5);
    const Vec3 start = center + 5.0 * a;
    const Vec3 end = center + 5.0 * n.cross(a);
    Model m = cantilever(end, full_section(coupled_section()), elements, order);
    m.points[0].position = start;
    m.points[1].position = end;
    m.members[0].line.kind = LineKind::arc;
    m.members[0].line.center = center;
    m.members[0].line.normal = n;
    m.members[0].twist_end = 1.0;
    Mat6 M = Mat6::Zero();
    M.topLeftCorner<3, 3>() = 2.0 * Mat3::Identity();
    const Mat3 eta_t = so3::skew(Vec3(0.0, 0.05, -0.03));
    M.block<3, 3>(3, 0) = 2.0 * eta_t;
    M.block<3, 3>(0, 3) = 2.0 * eta_t.transpose();
    M.bottomRightCorner<3, 3>() = Vec3(0.3, 0.1, 0.2).asDiagonal();
    m.members[0].sections[0].section.mass = M;
    PointLoad tip;
    tip.point = 1;
    tip.force = Vec3(10.0, -20.0, 30.0);
    tip.moment = Vec3(5.0, -3.0, 8.0);
    tip.frame = follower ? LoadFrame::follower : LoadFrame::dead;
    DistributedLoad q;
    q.member = 0;
    q.force = Vec3(1.0, 2.0, -1.0);
    q.frame = follower ? LoadFrame::follower : LoadFrame::dead;
    DistributedLoad qm;
    qm.member = 0;
    qm.moment = Vec3(-0.5, 0.2, 0.7);
    m.point_loads = {tip};
    m.distributed_loads = {q, qm};
    if (gravity) m.gravity = Vec3(0.0, 0.0, -9.81);
    return m;
}

// Retraction increment taking the reference configuration to the deformed state: rotations
// growing along the member to 2.6 rad about a tilted axis plus a bending wobble, displacements a
// smooth non-linear field.
inline VecX deforming_increment(const form::Mesh& mesh) {
    VecX dx = VecX::Zero(mesh.unknowns);
    const Vec3 x_root = mesh.nodes[mesh.point_node[0]].x0;
    for (const form::MeshNode& node : mesh.nodes) {
        if (node.dof < 0) continue;
        const double t = (node.x0 - x_root).norm() / 7.0710678118654755;  // chord 5√2
        dx.segment<3>(node.dof) = Vec3(0.8 * t * t, -1.1 * t + 0.3 * std::sin(3 * t), 0.6 * t);
        dx.segment<3>(node.dof + 3) =
            2.6 * t * Vec3(0.48, 0.6, 0.64) + 0.3 * std::sin(4 * t) * Vec3(0.0, 0.8, -0.6);
    }
    return dx;
}

}  // namespace rotbeam::test
