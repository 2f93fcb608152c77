// The joined beam's modes about a follower-loaded static state (joint force 1e5 N along e_z in
// the joint's frame, tip deflection 0.26 m): the mixed formulation's frequencies, extrapolated in
// h by Richardson, against the displacement formulation at convergence (order 4 and 6, 10
// elements per member) — two independent discretizations of the same continuum, each through its
// own statics, tangent and mass. Modes are paired by their shapes (MAC on the stations of
// runs/mode_matching.hpp), not by sort order. The follower load makes both tangents
// non-symmetric (QZ in the displacement formulation).
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <vector>

#include "core/static_driver.hpp"
#include "formulations/displacement/displacement_modal.hpp"
#include "formulations/displacement/displacement_statics.hpp"
#include "formulations/mixed/mixed_dynamics.hpp"
#include "formulations/mixed/mixed_modal.hpp"
#include "formulations/mixed/mixed_statics.hpp"
#include "parameterizations/quaternion.hpp"
#include "parameterizations/wiener_milenkovic.hpp"
#include "runs/mode_matching.hpp"
#include "tests/agreement/agreement_runs.hpp"
#include "tests/displacement/modal_state.hpp"
#include "tests/mixed/modal_state.hpp"

using namespace rotbeam;

namespace {

constexpr int kModes = 5;
constexpr int kComputed = 8;  // spares for the shape matching

struct Modes {
    std::vector<double> hz;
    std::vector<std::vector<double>> stations;
};

Model loaded_joined_beam(int elements, const std::string& formulation, int order) {
    Model m = test::catalog_case("joined-beam", {"discretization.formulation=" + formulation,
                                                 "discretization.order=" + std::to_string(order),
                                                 "discretization.mass_rule=consistent"});
    for (Member& member : m.members) member.elements = elements;
    PointLoad f;
    f.point = 2;  // joint
    f.force = Vec3(0, 0, 1e5);
    f.frame = LoadFrame::follower;
    m.point_loads = {f};
    return m;
}

Modes displacement_modes(int order) {
    const Model model = loaded_joined_beam(10, "displacement", order);
    form::DisplacementStatics<param::Quaternion> problem(model);
    SparseMatrix M;
    const SparseMatrix K =
        test::tangent_and_mass_at_equilibrium(model, problem, {0.25, 0.5, 0.75, 1.0}, M);
    const form::ModalSolution s = form::solve_modal(K, M, kComputed);
    BOOST_TEST(!s.symmetric);
    BOOST_TEST(s.accepted());
    Modes out;
    for (size_t i = 0; i < s.pairs.size(); ++i) {
        out.hz.push_back(s.pairs[i].frequency_hz);
        std::vector<NodeDisplacement> nodes;
        for (const form::MeshNode& n : problem.mesh().nodes) {
            nodes.push_back({n.x0, n.dof < 0 ? Vec3::Zero() : Vec3(s.shapes[i].segment<3>(n.dof))});
        }
        out.stations.push_back(station_displacements(model, nodes));
    }
    return out;
}

Modes mixed_modes(int elements) {
    using P = param::WienerMilenkovic;
    const Model model = loaded_joined_beam(elements, "mixed", 1);
    form::MixedDynamics<P> dyn(form::frozen_loads(model, 1.0), 1.0);
    VecX r;
    SparseMatrix A, B;
    test::linearize_about_static_equilibrium(model, dyn, r, A, B);
    const form::DaeModalSolution s = form::solve_dae_modal(A, B, kComputed);
    BOOST_TEST(s.accepted());
    Modes out;
    for (size_t i = 0; i < s.shapes.size(); ++i) {
        out.hz.push_back(s.frequencies_hz[i]);
        std::complex<double> peak = 0.0;
        for (int n = 0; n < dyn.node_count(); ++n) {
            for (int k = 0; k < 3 && !dyn.supported(n); ++k) {
                const std::complex<double> v = s.shapes[i][dyn.node_column(n) + k];
                if (std::abs(v) > std::abs(peak)) peak = v;
            }
        }
        std::vector<NodeDisplacement> nodes;
        for (int n = 0; n < dyn.node_count(); ++n) {
            Vec3 d = Vec3::Zero();
            for (int k = 0; k < 3 && !dyn.supported(n); ++k) {
                d[k] = (s.shapes[i][dyn.node_column(n) + k] / peak).real();
            }
            nodes.push_back({dyn.layout().nodes[static_cast<size_t>(n)].reference, d});
        }
        out.stations.push_back(station_displacements(model, nodes));
    }
    return out;
}

// The frequencies of `m` in the order of `reference`'s first kModes modes, by shape.
std::vector<double> matched(const Modes& reference, const Modes& m) {
    const std::vector<std::vector<double>> ref(reference.stations.begin(),
                                               reference.stations.begin() + kModes);
    const std::vector<int> index = match_modes(ref, m.stations, kMatchMac);
    std::vector<double> f;
    for (int k = 0; k < kModes; ++k) {
        BOOST_TEST_REQUIRE(index[static_cast<size_t>(k)] >= 0);
        f.push_back(m.hz[static_cast<size_t>(index[static_cast<size_t>(k)])]);
    }
    return f;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(modal_agreement)

BOOST_AUTO_TEST_CASE(follower_loaded_mixed_frequencies_extrapolate_to_the_displacement_ones) {
    const Modes d4 = displacement_modes(4);
    const Modes d6 = displacement_modes(6);
    const std::vector<double> f4 = matched(d6, d4), f6 = matched(d6, d6);
    std::vector<std::vector<double>> mixed;
    for (int n : {10, 20, 40}) mixed.push_back(matched(d6, mixed_modes(n)));
    for (int k = 0; k < kModes; ++k) {
        const double f10 = mixed[0][k], f20 = mixed[1][k], f40 = mixed[2][k];
        const double ratio = (f10 - f20) / (f20 - f40);  // 4 at order 2
        const double richardson = f40 + (f40 - f20) / 3.0;
        const double previous = f20 + (f20 - f10) / 3.0;  // the same from 10, 20
        BOOST_TEST_MESSAGE("mode " << k + 1 << ": displacement p4 " << f4[k] << ", p6 " << f6[k]
                                   << " Hz; mixed 10/20/40 " << f10 << " " << f20 << " " << f40
                                   << " (ratio " << ratio << "), Richardson " << richardson
                                   << " (from 10/20: " << previous << "), difference "
                                   << (richardson - f6[k]) / f6[k]);
        // The displacement formulation is converged: orders 4 and 6 agree to 1e-6 (measured: to
        // the printed digits), so its value serves as the reference.
        BOOST_TEST(std::abs(f4[k] - f6[k]) <= 1e-6 * f6[k]);
        // Tolerance: the Richardson value's own remainder. The difference ratios are 4.0–4.1
        // (order 2, next term of order 4), so the remainder left after eliminating the h² term
        // shrinks ≥ 4× per halving, and the change of the extrapolation from the (10, 20) to the
        // (20, 40) meshes bounds the remainder of the latter by a third of that change (measured
        // 3e-6 … 2.7e-4 relative; the differences from the displacement value are 5e-8 … 1.7e-5,
        // 5–60× inside). A wrong frequency in either formulation, a mode paired with the wrong
        // one, or a stiffness term missing about the loaded state is far outside.
        const double remainder = std::abs(richardson - previous) / 3.0;
        BOOST_TEST(std::abs(richardson - f6[k]) <= remainder + 1e-6 * f6[k]);
    }
}

BOOST_AUTO_TEST_SUITE_END()
