// Lagrange basis on GLL nodes: partition of unity, derivatives sum to zero, exactness.
#include <boost/test/unit_test.hpp>

#include <cmath>

#include "core/lagrange.hpp"
#include "core/quadrature.hpp"

using namespace rotbeam;

BOOST_AUTO_TEST_SUITE(lagrange_basis)

BOOST_AUTO_TEST_CASE(partition_of_unity_and_zero_derivative_sum_to_order_24) {
    for (int p = 1; p <= 24; ++p) {
        const LagrangeBasis basis(gauss_lobatto_legendre(p + 1).points);
        VecX N(p + 1), dN(p + 1);
        for (double x : {-1.0, -0.77, -0.1, 0.0, 0.333, 0.9, 1.0}) {
            basis.values(x, N);
            basis.derivatives(x, dN);
            BOOST_TEST(std::abs(N.sum() - 1.0) < 1e-13, "p " << p << " x " << x);
            BOOST_TEST(std::abs(dN.sum()) < 1e-11 * p * p, "p " << p << " x " << x);
        }
    }
}

BOOST_AUTO_TEST_CASE(interpolation_is_exact_on_polynomials_of_the_order) {
    for (int p = 1; p <= 20; ++p) {
        const std::vector<double> nodes = gauss_lobatto_legendre(p + 1).points;
        const LagrangeBasis basis(nodes);
        // f(x) = Σ_k c_k x^k with degree p; interpolate value and derivative.
        auto f = [p](double x) { double s = 0; for (int k = 0; k <= p; ++k) s += std::pow(x, k) / (k + 1.0); return s; };
        auto df = [p](double x) { double s = 0; for (int k = 1; k <= p; ++k) s += k * std::pow(x, k - 1) / (k + 1.0); return s; };
        VecX values(p + 1);
        for (int i = 0; i <= p; ++i) values[i] = f(nodes[i]);
        VecX N(p + 1), dN(p + 1);
        for (double x : {-0.95, -0.3, 0.41, 0.99}) {
            basis.values(x, N);
            basis.derivatives(x, dN);
            BOOST_TEST(std::abs(N.dot(values) - f(x)) < 1e-12, "p " << p);
            BOOST_TEST(std::abs(dN.dot(values) - df(x)) < 1e-10 * p, "p " << p);
        }
        // At the nodes the basis is the Kronecker delta and derivatives use the exact rows.
        basis.values(nodes[p / 2], N);
        BOOST_TEST(N[p / 2] == 1.0);
        basis.derivatives(nodes[p / 2], dN);
        BOOST_TEST(std::abs(dN.dot(values) - df(nodes[p / 2])) < 1e-10 * p);
    }
}

BOOST_AUTO_TEST_SUITE_END()
