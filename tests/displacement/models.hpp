// Models shared by the displacement-formulation tests (docs/benchmarks.md definitions).
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "core/model.hpp"
#include "tests/cases/catalog_model.hpp"

namespace rotbeam::test {

// Diagonal section stiffness [EA, GA2, GA3, GJ, EI2, EI3] with its compliance.
Section diagonal_section(double EA, double GA2, double GA3, double GJ, double EI2, double EI3);

// The section of stiffness C, its compliance C⁻¹.
Section full_section(const Mat6& C);

// One member from point "root" to point "tip"; root clamped.
Model cantilever(const Vec3& tip, const Section& section, int elements, int order);

// docs/benchmarks.md §1, the catalog's cantilever-moment: L = 12, E = 30e6, 1×1 square
// (EI = 2.5e6), ν = 0.3, shear factor 5/6; tip moment −π EI / L e_y at load factor λ = 1.
inline constexpr double kRollupL = 12.0;
inline constexpr double kRollupEI = 2.5e6;
inline Model rollup(int elements, int order) {
    return catalog_model("cantilever-moment", {"members.beam.elements=" + std::to_string(elements),
                                               "discretization.order=" + std::to_string(order)});
}

// Exact roll-up tip displacement (u1, u2, u3) at λ.
inline Vec3 rollup_exact_tip(double lambda) {
    const double rho = kRollupL / (lambda * kPi);
    return Vec3(rho * std::sin(lambda * kPi) - kRollupL, 0.0, rho * (1.0 - std::cos(lambda * kPi)));
}

// docs/benchmarks.md §2, the catalog's bend-45: 45° arc of radius 100 in the x–y plane, centre
// (0, 100, 0), E = 1e7, ν = 0, 1×1 square, shear factor 5/6, dead tip force P e_z (P = load
// factor); the torsion constant J = 0.140577 of the tests' references instead of the catalog's
// 1/6.
inline Model bend45(int elements, int order) {
    return catalog_model("bend-45", {"members.beam.elements=" + std::to_string(elements),
                                     "discretization.order=" + std::to_string(order),
                                     "sections.square.isotropic.J=0.140577"});
}

}  // namespace rotbeam::test
