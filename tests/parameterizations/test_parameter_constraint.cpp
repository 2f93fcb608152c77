// ParameterConstraint<P> (parameterizations/parameter_constraint.hpp) for every parameterization:
// the row count is the number of redundant parameters, and for the quaternion the unit-norm row
// vanishes on the unit sphere, its Jacobian matches central differences, the radial part of a
// rate is what no tangent sees, and the algebraic component leaves the best-conditioned chart.
#include <Eigen/LU>
#include <boost/test/unit_test.hpp>

#include "parameterizations/parameter_constraint.hpp"
#include "samples.hpp"

namespace rotbeam::test {

BOOST_AUTO_TEST_SUITE(parameter_constraint)

BOOST_AUTO_TEST_CASE_TEMPLATE(row_count_is_the_number_of_redundant_parameters, P,
                              AllParameterizationTypes) {
    BOOST_TEST(param::ParameterConstraint<P>::kRows == P::kSize - 3);
}

BOOST_AUTO_TEST_CASE(quaternion_norm_row_its_jacobian_radial_part_and_chart) {
    using Q = param::Quaternion;
    using C = param::ParameterConstraint<Q>;
    const Vec4 v(0.3, -1.1, 0.7, 2.0);  // a rate with a radial and a tangential part
    for (const Sample& s : hard_samples()) {
        BOOST_TEST_CONTEXT("angle " << s.label) {
            const Vec4 unit = Q::from_rotation_vector(s.angle * generic_axis());
            // On the sphere the row is round-off: |q|² − 1 of a normalized vector, ~ε.
            BOOST_TEST(std::abs(C::residual(unit)) <= 4.0 * kEps);
            const Vec4 q = 1.3 * unit;  // off the sphere, where Newton iterates live
            // ½|q|² is quadratic: central differences are exact up to round-off of ½|q|²/h ~ ε/h.
            const double h = 1e-4;
            for (int k = 0; k < 4; ++k) {
                const Vec4 dq = h * Vec4::Unit(k);
                const double fd = (C::residual(q + dq) - C::residual(q - dq)) / (2.0 * h);
                BOOST_TEST(std::abs(C::jacobian(q)(k) - fd) <= 1e-10);
            }
            // The radial part is invisible to both tangents (H q = 0) and the rest is tangential.
            const Vec4 radial = C::radial_part(q, v);
            BOOST_TEST((Q::material_tangent(q) * radial).norm() <= 1e-14 * v.norm());
            BOOST_TEST((Q::spatial_tangent(q) * radial).norm() <= 1e-14 * v.norm());
            BOOST_TEST(std::abs(q.dot(v - radial)) <= 1e-14 * q.norm() * v.norm());
            // Holding the algebraic component, the other three columns of H_m span R³: the chart
            // with the largest 3 × 3 minor, which is never small (|q_k| ≥ |q|/2 there).
            const param::Tangent<4> H = Q::material_tangent(q);
            double minors[4];
            for (int k = 0; k < 4; ++k) {
                Mat3 without_k;
                for (int j = 0, col = 0; j < 4; ++j) {
                    if (j != k) without_k.col(col++) = H.col(j);
                }
                minors[k] = std::abs(without_k.determinant());
            }
            const int k = C::algebraic_component(q);
            for (int j = 0; j < 4; ++j) BOOST_TEST(minors[k] >= minors[j] * (1.0 - 1e-12));
            BOOST_TEST(minors[k] > 0.1 * std::pow(H.norm() / 2.0, 3));
        }
    }
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace rotbeam::test
