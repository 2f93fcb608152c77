// Models of the benchmarks (docs/benchmarks.md §1, §2) and of a strongly deformed test structure,
// built in code for the mixed-formulation tests.
#pragma once

#include <cmath>
#include <sstream>
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
    return catalog_model("cantilever-moment",
                         {"discretization.formulation=mixed", "discretization.order=1",
                          "members.beam.elements=" + std::to_string(elements)});
}

// §2: the 45° bend (the catalog's bend-45), R = 100, E = 1e7, ν = 0, dead tip force P e_z at load
// factor P, with the given shear factor and torsion constant J.
inline Model bend_model(int elements, double shear_factor = 5.0 / 6.0, double J = 0.140577) {
    auto number = [](double v) {
        std::ostringstream s;
        s.precision(17);
        s << v;
        return s.str();
    };
    return catalog_model("bend-45", {"discretization.formulation=mixed", "discretization.order=1",
                                     "members.beam.elements=" + std::to_string(elements),
                                     "sections.square.isotropic.k2=" + number(shear_factor),
                                     "sections.square.isotropic.k3=" + number(shear_factor),
                                     "sections.square.isotropic.J=" + number(J)});
}

}  // namespace rotbeam::test
