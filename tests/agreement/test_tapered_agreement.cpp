// The two formulations discretize one model of a member whose sections change between stations:
// a cantilever with two stations (root and tip), each formulation refined, agree at convergence.
// Stiffness and mass are linear between stations in both (formulations/displacement/mesh.cpp,
// formulations/mixed/mixed_layout.cpp), as in BeamDyn (docs/beamdyn-import.md); a linear
// compliance or a station's mass held up to the next station is a different beam, which these
// tests tell apart (docs/mixed-formulation.md, "Sections between stations").
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

#include "cases/loader/case_loader.hpp"
#include "tests/agreement/agreement_runs.hpp"

using namespace rotbeam;
using namespace rotbeam::test;

namespace {

// A 6×6 diagonal matrix in the case file's row-list form.
std::string diagonal_matrix(const Vec6& d) {
    std::ostringstream out;
    out << std::setprecision(17) << '[';
    for (int i = 0; i < 6; ++i) {
        out << (i == 0 ? "[" : ", [");
        for (int j = 0; j < 6; ++j) out << (j == 0 ? "" : ",") << (i == j ? d(i) : 0.0);
        out << ']';
    }
    out << ']';
    return out.str();
}

// A 1 m cantilever along x, clamped at the root, with a root station and a tip station: the tip
// station's stiffness is `tip_stiffness` times the root one's (EA, GA₂, GA₃, GJ, EI₂, EI₃ =
// 1e7, 4e6, 4e6, 500, 800, 800), its mass per length `tip_mass` (root: 4 kg/m); `load` is the
// case's loads or gravity block.
std::string tapered_case(double tip_stiffness, double tip_mass, const std::string& load) {
    Vec6 stiffness;
    stiffness << 1e7, 4e6, 4e6, 500.0, 800.0, 800.0;
    Vec6 root_mass, tip_mass_matrix;
    root_mass << 4.0, 4.0, 4.0, 2e-3, 1e-3, 1e-3;
    tip_mass_matrix << tip_mass, tip_mass, tip_mass, 5e-4, 2.5e-4, 2.5e-4;
    return "name: tapered\nunits: \"m, N, kg\"\npoints:\n  root: [0, 0, 0]\n  tip: [1, 0, 0]\n"
           "sections:\n  thick:\n    stiffness: " +
           diagonal_matrix(stiffness) + "\n    mass: " + diagonal_matrix(root_mass) +
           "\n  thin:\n    stiffness: " + diagonal_matrix(tip_stiffness * stiffness) +
           "\n    mass: " + diagonal_matrix(tip_mass_matrix) +
           "\nmembers:\n  beam:\n    from: root\n    to: tip\n    elements: 8\n    sections:\n"
           "      - {at: 0, section: thick}\n      - {at: 1, section: thin}\n"
           "constraints:\n  root: clamped\n" +
           load +
           "analysis:\n  type: static\n  load_factors: [1.0]\n"
           "discretization:\n  formulation: displacement\n  rotation: quaternion\n  order: 2\n"
           "  quadrature: full\n";
}

struct Refined {
    Vec3 fine;        // tip displacement on the finest mesh
    double estimate;  // |fine − previous|: bounds the fine mesh's error when the order is ≥ 1
    double order;     // observed from the three meshes
};

// Three meshes N, 2N, 4N of one formulation. The error of the finest run is r/(1 − r) times its
// difference from the previous one, r = 2^−order the ratio of successive errors: at most that
// difference when r ≤ 1/2 (observed order ≥ 1, required).
template <class Run>
Refined refine(const std::string& text, const std::vector<std::string>& formulation, int n,
               Run run) {
    std::vector<Vec3> tips;
    for (int e : {n, 2 * n, 4 * n}) {
        std::vector<std::string> set = formulation;
        set.push_back("members.beam.elements=" + std::to_string(e));
        tips.push_back(run(load_case_text(text, "tapered.yaml", set)).tips.back());
    }
    Refined r;
    r.fine = tips[2];
    r.estimate = (tips[2] - tips[1]).norm();
    r.order = std::log2((tips[1] - tips[0]).norm() / (tips[2] - tips[1]).norm());
    return r;
}

// Mixed (Wiener–Milenković, second order in h) against displacement (quaternion, order 2), each on
// three meshes: the difference of the finest runs is within the sum of their error bounds.
void check_agreement(const std::string& text) {
    const Refined d = refine(text, {}, 8, run_displacement);
    const Refined m = refine(
        text, {"discretization.formulation=mixed", "discretization.rotation=wiener-milenkovic"}, 32,
        run_mixed);
    const double gap = (m.fine - d.fine).norm();
    BOOST_TEST_MESSAGE("displacement tip "
                       << d.fine.transpose() << " ± " << d.estimate << " (order " << d.order
                       << "); mixed tip " << m.fine.transpose() << " ± " << m.estimate << " (order "
                       << m.order << "); gap " << gap);
    BOOST_TEST(d.order >= 1.0);
    BOOST_TEST(m.order >= 1.0);
    BOOST_TEST(gap <= d.estimate + m.estimate);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(sections_between_stations)

// The tip station 1/8 as stiff as the root one (every component), a small tip force: between the
// stations the inverse of a linear stiffness and a linear compliance differ by up to
// (1 + 8)² / (4 · 8) = 2.5 times.
BOOST_AUTO_TEST_CASE(tapered_stiffness_under_a_tip_force) {
    check_agreement(tapered_case(
        0.125, 4.0, "loads:\n  tip-force: {point: tip, force: [0, 0, 2.0], frame: dead}\n"));
}

// Uniform stiffness, mass per length from 4 kg/m at the root to 1 kg/m at the tip, gravity.
BOOST_AUTO_TEST_CASE(tapered_mass_under_gravity) {
    check_agreement(tapered_case(1.0, 1.0, "gravity: [0, 0, -9.81]\n"));
}

BOOST_AUTO_TEST_SUITE_END()
