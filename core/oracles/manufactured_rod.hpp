// The straight rod both manufactured solutions are posed on (manufactured.cpp, in space;
// manufactured_motion.cpp, in space and time): length L along x in four members of equal length,
// points root, q1, mid, q3, tip at quarters, one constant section, and per member a load field
// made by `field(member, s0)` with s0 the member's start along the rod.
#pragma once
#include <string>

#include "core/model.hpp"
#include "core/types.hpp"

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

// The spatial section resultants n, m and their arc-length derivatives n′, m′ at a point of the
// rod with rotation R, spatial curvature k = axial(R′Rᵀ) and its derivative k′, and position
// derivatives x′, x″, for the material stiffness C*. Material strains Γ = Rᵀx′ − e₁, K = Rᵀk and,
// since (Rᵀ)′ = −K̃ Rᵀ, Γ′ = −K × Rᵀx′ + Rᵀx″ and K′ = −K × K + Rᵀk′ = Rᵀk′; [N; M] = C*[Γ; K];
// spatial resultants and their derivatives by (R v)′ = k × (R v) + R v′.
struct SpatialResultants {
    Vec3 n, m, n1, m1;
};

inline SpatialResultants spatial_resultants(const Mat3& R, const Vec3& k, const Vec3& k1,
                                            const Vec3& x1, const Vec3& x2, const Mat6& stiffness) {
    const Vec3 K = R.transpose() * k;
    const Vec3 Rx1 = R.transpose() * x1;
    Vec6 strain, strain1;
    strain << Rx1 - Vec3::UnitX(), K;
    strain1 << -K.cross(Rx1) + R.transpose() * x2, R.transpose() * k1;
    const Vec6 NM = stiffness * strain;
    const Vec6 NM1 = stiffness * strain1;
    SpatialResultants out;
    out.n = R * NM.head<3>();
    out.m = R * NM.tail<3>();
    out.n1 = k.cross(out.n) + R * NM1.head<3>();
    out.m1 = k.cross(out.m) + R * NM1.tail<3>();
    return out;
}

}  // namespace rotbeam::oracle
