// A strongly deformed, moving test structure for the mixed dynamics: the two-member
// structure of the statics' Jacobian tests with 6×6 section masses (offsets, full inertia) and
// time functions on its follower loads.
#pragma once

#include <cmath>

#include "core/model.hpp"
#include "tests/mixed/deformed_model.hpp"
#include "tests/mixed/models.hpp"

namespace rotbeam::test {

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

// deformed_test_model() (the statics' Jacobian structure) with a 6×6 mass with offsets on both
// members and a sine time function on the follower point load and the follower distributed load.
inline Model dynamic_test_model() {
    Model m = deformed_test_model();
    Mat3 rho;
    rho << 0.9, 0.1, -0.05, 0.1, 0.5, 0.02, -0.05, 0.02, 0.6;
    m.members[0].sections.at(0).section.mass = offset_mass(1.3, Vec3(0, 0.1, -0.05), rho);
    m.members[1].sections.at(0).section.mass = offset_mass(0.8, Vec3(0, -0.07, 0.12), 0.8 * rho);
    TimeFunction sine;
    sine.kind = TimeFunction::Kind::sine;
    sine.value = 1.0;
    sine.omega = 3.0;
    sine.phase = 0.4;
    m.point_loads.at(0).time = sine;        // the follower point load
    m.distributed_loads.at(0).time = sine;  // the follower distributed load
    return m;
}

// dynamic_test_model with its tip also supported: a prescribed displacement and rotation moving
// with a sine in time, so the tip's rotation is ρ times the given one with ρ an unknown.
inline Model two_support_dynamic_model() {
    Model m = dynamic_test_model();
    TimeFunction sine;
    sine.kind = TimeFunction::Kind::sine;
    sine.value = 1.0;
    sine.omega = 2.0;
    sine.phase = 0.7;
    m.constraints.push_back(Constraint{2, Constraint::Kind::prescribed, Vec3(0.1, 0.2, -0.1),
                                       Vec3(0.3, -0.2, 0.5), sine});
    return m;
}

}  // namespace rotbeam::test
