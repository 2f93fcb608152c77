// The continuum tests' models that are not catalog cases, built in code: the elastica, the
// Timoshenko and linear-theory checks, the refused and unreachable models, the twisted roll-up and
// the ring segment are variants made to isolate one property, with no YAML of their own. The
// catalog's benchmarks (roll-up, helix, precessing helix, 45° bend) are read from cases/*.yaml
// (tests/cases/catalog_model.hpp).
#pragma once

#include <vector>

#include "core/model.hpp"
#include "core/types.hpp"

namespace rotbeam::test {

// Diagonal compliance of EA, GA₂, GA₃, GJ, EI₂, EI₃; a zero stiffness entry means rigid (the
// compliance row is zero).
inline Mat6 diagonal_compliance(const Vec6& stiffness) {
    Mat6 C = Mat6::Zero();
    for (int i = 0; i < 6; ++i) C(i, i) = stiffness[i] > 0.0 ? 1.0 / stiffness[i] : 0.0;
    return C;
}

// Cantilever from `root` (clamped) to `tip` with a unit load (force, moment) at the tip scaled
// by the load factors.
inline Model cantilever(const Vec3& tip, const Mat6& compliance, const Vec3& force,
                        const Vec3& moment, LoadFrame frame, const std::vector<double>& factors) {
    Model model;
    model.name = "continuum-test";
    model.points = {{"root", Vec3::Zero()}, {"tip", tip}};
    Member member;
    member.name = "beam";
    member.start_point = 0;
    member.end_point = 1;
    SectionStation station;
    station.section.compliance = compliance;
    member.sections.push_back(station);
    model.members.push_back(member);
    Constraint clamp;
    clamp.point = 0;
    model.constraints.push_back(clamp);
    PointLoad load;
    load.point = 1;
    load.force = force;
    load.moment = moment;
    load.frame = frame;
    model.point_loads.push_back(load);
    model.analysis.statics.load_factors = factors;
    return model;
}

}  // namespace rotbeam::test
