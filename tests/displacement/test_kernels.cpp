// Unit tests of the quadrature-point kernels of the displacement formulation.
#include <boost/mpl/list.hpp>
#include <boost/test/unit_test.hpp>
#include <cmath>

#include "core/finite_difference.hpp"
#include "core/so3.hpp"
#include "deformed.hpp"
#include "formulations/displacement/calculate_elastic_forces.hpp"
#include "formulations/displacement/calculate_stiffness_blocks.hpp"
#include "formulations/displacement/calculate_strain.hpp"
#include "formulations/displacement/displacement_statics.hpp"
#include "formulations/displacement/interpolate_rotation.hpp"
#include "formulations/displacement/rotate_section.hpp"
#include "tests/harness/type_lists.hpp"

using namespace rotbeam;

namespace {

// A non-trivial quadrature-point state: reference tangent/frame of a twisted curved line,
// a rotated and stretched current state.
struct PointState6 {
    Vec3 x0p = Vec3(0.6, 0.0, 0.8);
    Mat3 Rr = so3::exp_map(Vec3(0.0, -0.6435011087932844, 0.0)) * so3::exp_map(Vec3(0.4, 0, 0));
    Vec3 up = Vec3(0.05, -0.2, 0.1);
    Mat3 R = so3::exp_map(Vec3(0.9, -1.3, 0.7));
    Vec3 kappa = Vec3(0.2, -0.1, 0.35);
};

// [F^E1; F^E2] at (u′, R, κ) as a 9-vector.
Eigen::Matrix<double, 9, 1> forces(const PointState6& s, const Vec3& up, const Mat3& R,
                                   const Vec3& kappa) {
    const Vec3 xp = s.x0p + up;
    const Mat6 C = form::rotate_section(test::coupled_section(), R * s.Rr);
    const form::ElasticForces F =
        form::calculate_elastic_forces(C, form::calculate_strain(s.x0p, up, R, kappa), xp);
    Eigen::Matrix<double, 9, 1> out;
    out << F.FE1, F.FE2;
    return out;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(displacement_kernels)

BOOST_AUTO_TEST_CASE(strain_is_zero_in_the_reference_configuration) {
    const PointState6 s;
    const Vec6 e = form::calculate_strain(s.x0p, Vec3::Zero(), Mat3::Identity(), Vec3::Zero());
    BOOST_TEST(e.norm() == 0.0);
}

BOOST_AUTO_TEST_CASE(strain_of_a_rigid_rotation_is_zero) {
    // u′ = (R − I) x^r′ (rigid rotation of the tangent), κ = 0: ε = 0 to round-off.
    const PointState6 s;
    const Vec3 up = (s.R - Mat3::Identity()) * s.x0p;
    const Vec6 e = form::calculate_strain(s.x0p, up, s.R, Vec3::Zero());
    BOOST_TEST(e.norm() < 1e-15);
}

BOOST_AUTO_TEST_CASE(rotated_section_preserves_strain_energy) {
    const PointState6 s;
    const Mat3 Q = s.R * s.Rr;
    const Mat6 C = form::rotate_section(test::coupled_section(), Q);
    Vec6 e_star;
    e_star << 1e-3, -2e-3, 5e-4, 0.1, -0.3, 0.2;
    Vec6 e;
    e << Q * e_star.head<3>(), Q * e_star.tail<3>();
    const double w = e.dot(C * e), w_star = e_star.dot(test::coupled_section() * e_star);
    BOOST_TEST(std::abs(w - w_star) < 1e-13 * std::abs(w_star));
}

BOOST_AUTO_TEST_CASE(elastic_force_FE2_is_force_cross_tangent) {
    const PointState6 s;
    const Eigen::Matrix<double, 9, 1> f = forces(s, s.up, s.R, s.kappa);
    const Vec3 expected = f.head<3>().cross(s.x0p + s.up);
    BOOST_TEST((f.tail<3>() - expected).norm() < 1e-14 * expected.norm());
}

// The stiffness blocks against central differences in u′, in δψ (R ← exp(h ψ̃) R, κ held) and
// in κ. Step ∛ε: the error is ~ε^(2/3) ≈ 4e-11 relative to the force scale (EA ~ 1e4 times
// O(1) strains); 1e-8 of the largest entry leaves a margin of ~100 for cancellations.
BOOST_AUTO_TEST_CASE(stiffness_blocks_match_central_differences) {
    const PointState6 s;
    const Eigen::Matrix<double, 9, 1> f = forces(s, s.up, s.R, s.kappa);
    const Mat6 C = form::rotate_section(test::coupled_section(), s.R * s.Rr);
    const form::StiffnessBlocks B =
        form::calculate_stiffness_blocks(C, f.head<6>(), s.x0p + s.up, s.kappa);
    Eigen::Matrix<double, 9, 9> analytic = Eigen::Matrix<double, 9, 9>::Zero();
    analytic.block<6, 3>(0, 0) = C.leftCols<3>();
    analytic.block<6, 3>(0, 3) = B.O;
    analytic.block<6, 3>(0, 6) = C.rightCols<3>();
    analytic.block<3, 3>(6, 0) = B.Pu;
    analytic.block<3, 3>(6, 3) = B.Qp;
    analytic.block<3, 3>(6, 6) = B.Pk;
    const auto f_of = [&](const VecX& d) -> VecX {
        const Vec3 du = d.segment<3>(0), dpsi = d.segment<3>(3), dk = d.segment<3>(6);
        return forces(s, s.up + du, so3::exp_map(dpsi) * s.R, s.kappa + dk);
    };
    const MatX fd = central_difference_jacobian(f_of, VecX::Zero(9));
    const double scale = analytic.cwiseAbs().maxCoeff();
    BOOST_TEST((fd - analytic).cwiseAbs().maxCoeff() < 1e-8 * scale);
}

BOOST_AUTO_TEST_SUITE_END()

// The direct interpolation's nodal maps A_j (δψ) and K_j (δκ), for every parameterization,
// against central differences through the nodal retraction p_j ← exp(δψ_j) ⊗ p_j.
using AllParams = test::ParameterizationTypes<>;

BOOST_AUTO_TEST_SUITE(displacement_interpolation)

BOOST_AUTO_TEST_CASE_TEMPLATE(direct_interpolation_maps_match_central_differences, P, AllParams) {
    using Pr = param::Params<P::kSize>;
    constexpr int kNodes = 4;
    // Nodal rotations up to 1.4 rad (inside every chart), non-coaxial.
    std::array<Vec3, kNodes> psi = {Vec3(0.1, 0.0, 0.05), Vec3(0.5, -0.3, 0.2),
                                    Vec3(0.8, -0.7, 0.4), Vec3(0.9, -1.0, 0.5)};
    const double N[kNodes] = {-0.1, 0.45, 0.75, -0.1};
    const double dN[kNodes] = {-0.8, -1.3, 1.1, 1.0};
    const auto interpolate = [&](const std::array<Vec3, kNodes>& dpsi) {
        std::array<Pr, kNodes> p;
        Pr p0 = P::compose(P::from_rotation_vector(dpsi[0]), P::from_rotation_vector(psi[0]));
        for (int j = 0; j < kNodes; ++j) {
            p[j] = P::compose(P::from_rotation_vector(dpsi[j]), P::from_rotation_vector(psi[j]));
            p[j] *= form::chart_sign<P>(p[j], p0);
        }
        form::InterpolatedRotation<P> r;
        form::interpolate_rotation<P>(p.data(), N, dN, kNodes, r);
        return r;
    };
    std::array<Vec3, kNodes> zero;
    zero.fill(Vec3::Zero());  // Eigen does not zero-initialize
    const form::InterpolatedRotation<P> r0 = interpolate(zero);
    const param::Tangent<P::kSize> T = form::curvature_tangent<P>(r0);
    for (int j = 0; j < kNodes; ++j) {
        const Pr pj = P::from_rotation_vector(psi[j]);
        const param::TangentInverse<P::kSize> M = P::spatial_tangent_inverse(pj);
        Mat3 A, K;
        form::rotation_maps<P>(r0, T, M, N[j], dN[j], A, K);
        const auto f = [&](const VecX& d) -> VecX {
            std::array<Vec3, kNodes> dpsi = zero;
            dpsi[j] = d;
            const form::InterpolatedRotation<P> r = interpolate(dpsi);
            VecX out(6);
            out << so3::log_map(r.R * r0.R.transpose()), r.kappa;
            return out;
        };
        const MatX fd = central_difference_jacobian(f, VecX::Zero(3));
        // Smooth O(1) functions of O(1) arguments: ε^(2/3) ≈ 4e-11; 1e-8 leaves a wide margin
        // while a missing curvature-map term (the interpolated-spin approximation) errs by O(0.1).
        BOOST_TEST((fd.topRows(3) - A).cwiseAbs().maxCoeff() < 1e-8);
        BOOST_TEST((fd.bottomRows(3) - K).cwiseAbs().maxCoeff() < 1e-8);
    }
}

BOOST_AUTO_TEST_SUITE_END()

// Every quadrature point of a curved, twisted member is strain-free in the reference
// configuration (seed 000's equivalent strain): the unloaded residual vanishes to round-off.
BOOST_AUTO_TEST_CASE(reference_configuration_is_stress_free_on_curved_twisted_member) {
    for (int p : {1, 2, 5, 12}) {
        Model m = test::curved_twisted(3, p, true, false);
        form::DisplacementStatics<param::Quaternion> s(m);
        s.set_load_factor(0.0);
        VecX r;
        s.evaluate(r, nullptr);
        BOOST_TEST((r.array() / s.residual_scale().array()).abs().maxCoeff() < 1e-14);
    }
}
