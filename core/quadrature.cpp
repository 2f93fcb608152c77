#include "core/quadrature.hpp"

#include <gsl/gsl_integration.h>
#include <gsl/gsl_sf_legendre.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

#include "core/errors.hpp"
#include "core/types.hpp"

namespace rotbeam {

QuadratureRule gauss_legendre(int n) {
    ROTBEAM_VERIFY(n >= 1, "gauss_legendre needs n >= 1, got " + std::to_string(n));
    std::unique_ptr<gsl_integration_glfixed_table, decltype(&gsl_integration_glfixed_table_free)>
        table(gsl_integration_glfixed_table_alloc(static_cast<size_t>(n)),
              &gsl_integration_glfixed_table_free);
    ROTBEAM_VERIFY(table != nullptr, "GSL could not allocate a Gauss-Legendre table");
    QuadratureRule rule;
    rule.points.resize(n);
    rule.weights.resize(n);
    for (int i = 0; i < n; ++i) {
        gsl_integration_glfixed_point(-1.0, 1.0, static_cast<size_t>(i), &rule.points[i],
                                      &rule.weights[i], table.get());
    }
    // GSL's tables are exact for the tabulated n but computed for the others, where the weights
    // carry errors up to ~3e-11 (measured at n = 61). One or two Newton steps on P_n polish the
    // nodes to round-off; weights 2 / ((1 − x²) P′_n(x)²).
    std::vector<double> p(n + 1), dp(n + 1);
    for (int i = 0; i < n; ++i) {
        double& x = rule.points[i];
        for (int it = 0; it < 3; ++it) {
            gsl_sf_legendre_Pl_deriv_array(n, x, p.data(), dp.data());
            x -= p[n] / dp[n];
        }
        gsl_sf_legendre_Pl_deriv_array(n, x, p.data(), dp.data());
        rule.weights[i] = 2.0 / ((1.0 - x * x) * dp[n] * dp[n]);
    }
    // GSL orders the points symmetrically in pairs; sort ascending for a predictable layout.
    std::vector<int> order(n);
    for (int i = 0; i < n; ++i) order[i] = i;
    std::sort(order.begin(), order.end(),
              [&](int a, int b) { return rule.points[a] < rule.points[b]; });
    QuadratureRule sorted;
    for (int i : order) {
        sorted.points.push_back(rule.points[i]);
        sorted.weights.push_back(rule.weights[i]);
    }
    return sorted;
}

QuadratureRule gauss_lobatto_legendre(int n) {
    ROTBEAM_VERIFY(n >= 2, "gauss_lobatto_legendre needs n >= 2, got " + std::to_string(n));
    const int N = n - 1;  // polynomial degree
    std::vector<double> p(N + 1), dp(N + 1);
    QuadratureRule rule;
    rule.points.resize(n);
    rule.weights.resize(n);
    rule.points.front() = -1.0;
    rule.points.back() = 1.0;
    for (int i = 1; i < N; ++i) {
        // Chebyshev–Gauss–Lobatto initial guess, then Newton on f = P′_N, with
        // f′ = (2x P′_N − N(N+1) P_N)/(1 − x²) (Legendre's equation).
        double x = -std::cos(kPi * i / N);
        for (int it = 0; it < 100; ++it) {
            gsl_sf_legendre_Pl_deriv_array(N, x, p.data(), dp.data());
            const double f = dp[N];
            const double fp = (2.0 * x * dp[N] - N * (N + 1.0) * p[N]) / (1.0 - x * x);
            const double dx = f / fp;
            x -= dx;
            if (std::abs(dx) < 1e-16) break;
        }
        rule.points[i] = x;
    }
    for (int i = 0; i < n; ++i) {
        gsl_sf_legendre_Pl_array(N, rule.points[i], p.data());
        rule.weights[i] = 2.0 / (N * (N + 1.0) * p[N] * p[N]);
    }
    return rule;
}

QuadratureRule trapezoidal(const std::vector<double>& breaks, int refine) {
    ROTBEAM_VERIFY(breaks.size() >= 2 && breaks.front() == -1.0 && breaks.back() == 1.0,
                   "trapezoidal needs breakpoints from -1 to 1");
    ROTBEAM_VERIFY(refine >= 1, "trapezoidal needs refine >= 1, got " + std::to_string(refine));
    QuadratureRule rule;
    rule.points.push_back(breaks.front());
    for (size_t k = 1; k < breaks.size(); ++k) {
        const double a = breaks[k - 1];
        const double b = breaks[k];
        ROTBEAM_VERIFY(b > a, "trapezoidal breakpoints must increase strictly");
        // a + (b − a) j / refine, the last one b itself (no round-off drift onto the next break).
        for (int j = 1; j < refine; ++j) rule.points.push_back(a + (b - a) * j / refine);
        rule.points.push_back(b);
    }
    const size_t n = rule.points.size();
    rule.weights.assign(n, 0.0);
    for (size_t i = 0; i + 1 < n; ++i) {
        const double half = 0.5 * (rule.points[i + 1] - rule.points[i]);
        rule.weights[i] += half;
        rule.weights[i + 1] += half;
    }
    return rule;
}

}  // namespace rotbeam
