// Models of the benchmarks (docs/benchmarks.md §1, §2) and of a strongly deformed test structure,
// built in code for the mixed-formulation tests.
#pragma once

#include <cmath>
#include <string>

#include "core/model.hpp"
#include "tests/displacement/models.hpp"

namespace rotbeam::test {

// Diagonal section [EA, GA2, GA3, GJ, EI2, EI3] as compliance and stiffness.
inline Section diagonal_section(const Vec6& stiffness) {
    Section s;
    s.stiffness = Mat6(stiffness.asDiagonal());
    s.compliance = Mat6(stiffness.cwiseInverse().asDiagonal());
    return s;
}

inline Member member(const std::string& name, int start, int end, const Section& section, int n) {
    Member m;
    m.name = name;
    m.start_point = start;
    m.end_point = end;
    m.sections = {SectionStation{0.0, section}};
    m.elements = n;
    return m;
}

// §1: L = 12, EI = 2.5e6 (kRollupL, kRollupEI, rollup_exact_tip: tests/displacement/models.hpp),
// tip moment −λ π EI / L e_y at load factor λ.
inline constexpr double kRollupLength = kRollupL;

inline Model rollup_model(int elements) {
    Model m;
    m.name = "rollup";
    m.points = {{"root", Vec3::Zero()}, {"tip", Vec3(kRollupLength, 0, 0)}};
    const double E = 30e6, G = E / 2.6, A = 1.0, I = 1.0 / 12.0;
    // Torsion: St-Venant constant of the unit square (it does not enter the answer).
    const Vec6 k =
        (Vec6() << E * A, 5.0 / 6.0 * G * A, 5.0 / 6.0 * G * A, G * 0.140577, E * I, E * I)
            .finished();
    m.members = {member("beam", 0, 1, diagonal_section(k), elements)};
    m.constraints = {Constraint{0, Constraint::Kind::clamped, Vec3::Zero(), Vec3::Zero(), {}}};
    PointLoad load;
    load.point = 1;
    load.moment = Vec3(0, -kPi * kRollupEI / kRollupLength, 0);
    m.point_loads = {load};
    return m;
}

// §2: the 45° bend, R = 100, E = 1e7, ν = 0, J = 0.140577, shear factor 5/6; dead tip force
// P e_z at load factor P.
inline Model bend_model(int elements, double shear_factor = 5.0 / 6.0, double J = 0.140577) {
    Model m;
    m.name = "bend45";
    const double R = 100.0;
    m.points = {{"root", Vec3::Zero()},
                {"tip", Vec3(R * std::sin(kPi / 4), R * (1 - std::cos(kPi / 4)), 0)}};
    const double E = 1e7, G = 5e6, I = 1.0 / 12.0;
    const Vec6 k =
        (Vec6() << E, shear_factor * G, shear_factor * G, G * J, E * I, E * I).finished();
    Member beam = member("beam", 0, 1, diagonal_section(k), elements);
    beam.line.kind = LineKind::arc;
    beam.line.center = Vec3(0, R, 0);
    m.members = {beam};
    m.constraints = {Constraint{0, Constraint::Kind::clamped, Vec3::Zero(), Vec3::Zero(), {}}};
    PointLoad load;
    load.point = 1;
    load.force = Vec3(0, 0, 1.0);
    m.point_loads = {load};
    return m;
}

}  // namespace rotbeam::test
