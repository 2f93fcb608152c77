// Gauss–Legendre (GSL tables) and Gauss–Lobatto–Legendre rules: exactness on polynomials; the
// composite trapezoidal rule: exact on piecewise-linear integrands, second order on smooth ones.
#include <boost/test/unit_test.hpp>
#include <cmath>

#include "core/quadrature.hpp"

using namespace rotbeam;

namespace {
double integrate(const QuadratureRule& rule, int degree) {
    double s = 0.0;
    for (size_t i = 0; i < rule.points.size(); ++i)
        s += rule.weights[i] * std::pow(rule.points[i], degree);
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
        for (int i = 0; i < n; ++i)
            BOOST_TEST(std::abs(rule.points[i] + rule.points[n - 1 - i]) < 1e-14);
    }
}

BOOST_AUTO_TEST_CASE(gauss_lobatto_matches_the_closed_form_for_five_points) {
    const QuadratureRule rule = gauss_lobatto_legendre(5);
    BOOST_TEST(std::abs(rule.points[3] - std::sqrt(3.0 / 7.0)) < 1e-15);
    BOOST_TEST(std::abs(rule.weights[0] - 0.1) < 1e-15);
    BOOST_TEST(std::abs(rule.weights[2] - 32.0 / 45.0) < 1e-15);
}

// Breakpoints at uneven stations (as a blade's): the points are the breakpoints and r equal
// divisions of each interval, the weights sum to the length 2, and an integrand linear between
// the points (|x − 0.3| with a kink at a breakpoint) is integrated exactly.
BOOST_AUTO_TEST_CASE(trapezoidal_is_exact_on_piecewise_linear_integrands) {
    const std::vector<double> breaks = {-1.0, -0.9, -0.2, 0.3, 0.35, 1.0};
    for (int r : {1, 2, 3, 7}) {
        const QuadratureRule rule = trapezoidal(breaks, r);
        BOOST_TEST_REQUIRE(rule.points.size() == (breaks.size() - 1) * r + 1);
        double sum = 0.0, kink = 0.0;
        for (size_t i = 0; i < rule.points.size(); ++i) {
            sum += rule.weights[i];
            kink += rule.weights[i] * std::abs(rule.points[i] - 0.3);
            if (i > 0) BOOST_TEST(rule.points[i] > rule.points[i - 1]);
        }
        for (size_t k = 0; k < breaks.size(); ++k) {
            BOOST_TEST(rule.points[k * r] == breaks[k]);  // every breakpoint is a point
        }
        // ∫|x − 0.3| dx on [−1, 1] = (1.3² + 0.7²)/2 = 1.09; round-off of a few terms.
        BOOST_TEST(std::abs(sum - 2.0) < 1e-15);
        BOOST_TEST(std::abs(kink - 1.09) < 1e-15);
    }
}

// On a smooth integrand (x⁴, ∫ = 2/5) the error is Σ h³ f″/12 → (h²/12) ∫ f″ = (h²/12)·4 with
// division length h = 2/(n r): halving h quarters it. Measured order log₂(e_r / e_2r) within 0.01
// of 2 from r = 8 on (the next term is h⁴).
BOOST_AUTO_TEST_CASE(trapezoidal_error_falls_as_the_division_length_squared) {
    const std::vector<double> breaks = {-1.0, -0.25, 0.5, 1.0};
    auto error = [&](int r) { return std::abs(integrate(trapezoidal(breaks, r), 4) - 0.4); };
    for (int r = 8; r <= 64; r *= 2) {
        const double order = std::log2(error(r) / error(2 * r));
        BOOST_TEST(std::abs(order - 2.0) < 0.01, "refine " << r << ": order " << order);
    }
    // On uniform divisions Euler–Maclaurin gives the error whole for a quartic:
    // (h²/12)(f′(1) − f′(−1)) − (h⁴/720)(f‴(1) − f‴(−1)) = h²·8/12 − h⁴·48/720.
    const QuadratureRule uniform = trapezoidal({-1.0, 1.0}, 100);
    const double h = 0.02;
    const double expected = h * h * 8.0 / 12.0 - std::pow(h, 4) * 48.0 / 720.0;
    BOOST_TEST(std::abs(integrate(uniform, 4) - 0.4 - expected) < 1e-14);
}

BOOST_AUTO_TEST_CASE(trapezoidal_refuses_bad_breakpoints) {
    BOOST_CHECK_THROW(trapezoidal({-1.0, 1.0}, 0), std::logic_error);
    BOOST_CHECK_THROW(trapezoidal({-1.0, 0.2, 0.2, 1.0}, 1), std::logic_error);
    BOOST_CHECK_THROW(trapezoidal({-0.5, 1.0}, 1), std::logic_error);
}

BOOST_AUTO_TEST_SUITE_END()
