// Models shared by the displacement-formulation tests (docs/benchmarks.md definitions).
#pragma once

#include <cmath>
#include <vector>

#include "core/model.hpp"

namespace rotbeam::test {

// Diagonal section stiffness [EA, GA2, GA3, GJ, EI2, EI3] with its compliance.
inline Section diagonal_section(double EA, double GA2, double GA3, double GJ, double EI2,
                                double EI3) {
    Section s;
    Vec6 d;
    d << EA, GA2, GA3, GJ, EI2, EI3;
    s.stiffness = Mat6(d.asDiagonal());
    s.compliance = Mat6(d.cwiseInverse().asDiagonal());
    return s;
}

inline Section full_section(const Mat6& C) {
    Section s;
    s.stiffness = C;
    s.compliance = C.inverse();
    return s;
}

// One member from point "root" to point "tip"; root clamped.
inline Model cantilever(const Vec3& tip, const Section& section, int elements, int order) {
    Model m;
    m.points = {{"root", Vec3::Zero()}, {"tip", tip}};
    Member mem;
    mem.name = "beam";
    mem.start_point = 0;
    mem.end_point = 1;
    mem.sections = {{0.0, section}};
    mem.elements = elements;
    m.members = {mem};
    Constraint c;
    c.point = 0;
    m.constraints = {c};
    m.discretization.order = order;
    return m;
}

// docs/benchmarks.md §1: L = 12, E = 30e6, 1×1 square (EI = 2.5e6), ν = 0.3, shear factor 5/6;
// tip moment −π EI / L e_y at load factor λ = 1.
inline constexpr double kRollupL = 12.0;
inline constexpr double kRollupEI = 2.5e6;
inline Model rollup(int elements, int order) {
    const double E = 30e6, G = E / 2.6, A = 1.0, I = 1.0 / 12.0;
    Model m = cantilever(Vec3(kRollupL, 0, 0),
                         diagonal_section(E * A, 5.0 / 6.0 * G * A, 5.0 / 6.0 * G * A,
                                          G * 0.140577, E * I, E * I),
                         elements, order);
    PointLoad l;
    l.point = 1;
    l.moment = Vec3(0.0, -kPi * kRollupEI / kRollupL, 0.0);
    m.point_loads = {l};
    return m;
}

// Exact roll-up tip displacement (u1, u2, u3) at λ.
inline Vec3 rollup_exact_tip(double lambda) {
    const double rho = kRollupL / (lambda * kPi);
    return Vec3(rho * std::sin(lambda * kPi) - kRollupL, 0.0, rho * (1.0 - std::cos(lambda * kPi)));
}

// docs/benchmarks.md §2: 45° arc of radius 100 in the x–y plane, centre (0, 100, 0), E = 1e7,
// ν = 0, 1×1 square, J = 0.140577, shear factor 5/6, dead tip force P e_z (P = load factor).
inline Model bend45(int elements, int order) {
    const double E = 1e7, G = 5e6, A = 1.0, I = 1.0 / 12.0;
    const double c = std::sqrt(0.5);
    Model m = cantilever(Vec3(100.0 * c, 100.0 * (1.0 - c), 0.0),
                         diagonal_section(E * A, 5.0 / 6.0 * G * A, 5.0 / 6.0 * G * A,
                                          G * 0.140577, E * I, E * I),
                         elements, order);
    m.members[0].line.kind = LineKind::arc;
    m.members[0].line.center = Vec3(0.0, 100.0, 0.0);
    PointLoad l;
    l.point = 1;
    l.force = Vec3(0.0, 0.0, 1.0);
    m.point_loads = {l};
    return m;
}

}  // namespace rotbeam::test
