// The straight rod both manufactured solutions are posed on (manufactured.cpp, in space;
// manufactured_motion.cpp, in space and time): length L along x in four members of equal length,
// points root, q1, mid, q3, tip at quarters, one constant section, and per member a load field
// made by `field(member, s0)` with s0 the member's start along the rod.
#pragma once
#include <string>

#include "core/model.hpp"

namespace rotbeam::oracle {

template <class MakeField>
void add_four_member_rod(Model& model, double length, const Section& section,
                         int elements_per_member, MakeField field) {
    const char* names[5] = {"root", "q1", "mid", "q3", "tip"};
    for (int i = 0; i < 5; ++i) model.points.push_back({names[i], Vec3(0.25 * i * length, 0, 0)});
    for (int i = 0; i < 4; ++i) {
        Member member;
        member.name = "part" + std::to_string(i + 1);
        member.start_point = i;
        member.end_point = i + 1;
        member.sections = {{0.0, section}};
        member.elements = elements_per_member;
        model.members.push_back(member);
        LoadField load = field(0.25 * i * length);
        load.member = i;
        model.load_fields.push_back(std::move(load));
    }
}

}  // namespace rotbeam::oracle
