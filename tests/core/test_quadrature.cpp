// Gauss–Legendre (GSL tables) and Gauss–Lobatto–Legendre rules: exactness on polynomials.
#include <boost/test/unit_test.hpp>

#include <cmath>

#include "core/quadrature.hpp"

using namespace rotbeam;

namespace {
double integrate(const QuadratureRule& rule, int degree) {
    double s = 0.0;
    for (size_t i = 0; i < rule.points.size(); ++i) s += rule.weights[i] * std::pow(rule.points[i], degree);
    return s;
}
double exact_monomial_integral(int degree) { return degree % 2 ? 0.0 : 2.0 / (degree + 1); }
}  // namespace

BOOST_AUTO_TEST_SUITE(quadrature_rules)

BOOST_AUTO_TEST_CASE(gauss_legendre_is_exact_to_degree_2n_minus_1) {
    for (int n = 1; n <= 64; ++n) {
        const QuadratureRule rule = gauss_legendre(n);
        BOOST_TEST_REQUIRE(rule.points.size() == static_cast<size_t>(n));
        // Monomials up to degree 2n−1 (bounded: high powers of points near ±1 stay O(1)).
        for (int d = 0; d <= std::min(2 * n - 1, 40); ++d) {
            BOOST_TEST(std::abs(integrate(rule, d) - exact_monomial_integral(d)) < 1e-13,
                       "n " << n << " degree " << d);
        }
        for (int i = 1; i < n; ++i) BOOST_TEST(rule.points[i] > rule.points[i - 1]);
    }
}

BOOST_AUTO_TEST_CASE(gauss_legendre_is_not_exact_at_degree_2n) {
    for (int n = 1; n <= 10; ++n) {
        BOOST_TEST(std::abs(integrate(gauss_legendre(n), 2 * n) - exact_monomial_integral(2 * n)) >
                   1e-6);
    }
}

BOOST_AUTO_TEST_CASE(gauss_lobatto_is_exact_to_degree_2n_minus_3_with_endpoints) {
    for (int n = 2; n <= 65; ++n) {
        const QuadratureRule rule = gauss_lobatto_legendre(n);
        BOOST_TEST_REQUIRE(rule.points.size() == static_cast<size_t>(n));
        BOOST_TEST(rule.points.front() == -1.0);
        BOOST_TEST(rule.points.back() == 1.0);
        for (int d = 0; d <= std::min(2 * n - 3, 40); ++d) {
            BOOST_TEST(std::abs(integrate(rule, d) - exact_monomial_integral(d)) < 1e-13,
                       "n " << n << " degree " << d);
        }
        for (int i = 1; i < n; ++i) BOOST_TEST(rule.points[i] > rule.points[i - 1]);
        // Symmetric nodes.
        for (int i = 0; i < n; ++i) BOOST_TEST(std::abs(rule.points[i] + rule.points[n - 1 - i]) < 1e-14);
    }
}

BOOST_AUTO_TEST_CASE(gauss_lobatto_matches_the_closed_form_for_five_points) {
    const QuadratureRule rule = gauss_lobatto_legendre(5);
    BOOST_TEST(std::abs(rule.points[3] - std::sqrt(3.0 / 7.0)) < 1e-15);
    BOOST_TEST(std::abs(rule.weights[0] - 0.1) < 1e-15);
    BOOST_TEST(std::abs(rule.weights[2] - 32.0 / 45.0) < 1e-15);
}

BOOST_AUTO_TEST_SUITE_END()
