#include "core/oracles/elastica.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>
#include <gsl/gsl_sf_ellint.h>

#include <cmath>
#include <memory>
#include <string>

#include "core/errors.hpp"
#include "core/oracles/gsl_guard.hpp"
#include "core/types.hpp"

namespace rotbeam::oracle {
namespace {

// The modulus is carried by its complementary parameter m₁ = 1 − k² = (1 − sin θ₀)/2 ∈ (0, ½]:
// near θ₀ = π/2 it keeps the digits that k itself (rounded to 1) would lose.
struct Modulus {
    double m1;
    double k;
    double phi0;  // sin φ₀ = 1/(k√2)
};

Modulus modulus_of(double m1) {
    const double k = std::sqrt(1.0 - m1);
    return {m1, k, std::asin(std::min(1.0, 1.0 / (k * std::sqrt(2.0))))};
}

// K(k) = π / (2 AGM(1, k')) and E(k) = K (1 − Σₙ 2ⁿ⁻¹ cₙ²) with c₀ = k, cₙ₊₁ = (aₙ − bₙ)/2
// (Abramowitz & Stegun 17.6), k' = √m₁: accurate for every m₁ > 0, unlike GSL's K(k), E(k)
// evaluated at a k that has rounded to 1.
struct CompleteIntegrals {
    double K;
    double E;
};

CompleteIntegrals complete_integrals(double m1) {
    double a = 1.0, b = std::sqrt(m1), c2 = 1.0 - m1, weight = 0.5;
    double sum = weight * c2;
    for (int i = 0; i < 64 && std::abs(a - b) > 1e-16 * a; ++i) {
        const double c = 0.5 * (a - b);
        const double next = 0.5 * (a + b);
        b = std::sqrt(a * b);
        a = next;
        weight *= 2.0;
        sum += weight * c * c;
    }
    const double K = kPi / (a + b);
    return {K, K * (1.0 - sum)};
}

double incomplete_F(const Modulus& m) {
    gsl_sf_result F;
    if (gsl_sf_ellint_F_e(m.phi0, m.k, GSL_PREC_DOUBLE, &F) != GSL_SUCCESS)
        throw SolverError("elastica: F(φ₀, k) failed at k = " + std::to_string(m.k));
    return F.val;
}

struct LengthEquation {
    double sqrt_alpha;
};

// f(y) = K(k) − F(φ₀, k) − √α with m₁ = e^y: decreasing in y, from +∞ (θ₀ → π/2) to −√α
// (y = ln ½, θ₀ = 0).
double length_residual(double y, void* params) {
    const Modulus m = modulus_of(std::exp(y));
    return complete_integrals(m.m1).K - incomplete_F(m) -
           static_cast<LengthEquation*>(params)->sqrt_alpha;
}

double solve_m1(double sqrt_alpha) {
    LengthEquation equation{sqrt_alpha};
    gsl_function f{&length_residual, &equation};
    const double lower = std::log(1e-300), upper = std::log(0.5);
    if (length_residual(lower, &equation) < 0.0)
        throw SolverError("elastica: load PL²/EI = " + std::to_string(sqrt_alpha * sqrt_alpha) +
                          " is beyond the bracket of the tip-angle root");
    std::unique_ptr<gsl_root_fsolver, decltype(&gsl_root_fsolver_free)> solver(
        gsl_root_fsolver_alloc(gsl_root_fsolver_brent), &gsl_root_fsolver_free);
    gsl_root_fsolver_set(solver.get(), &f, lower, upper);
    for (int iteration = 0; iteration < 400; ++iteration) {
        if (gsl_root_fsolver_iterate(solver.get()) != GSL_SUCCESS) break;
        const double lo = gsl_root_fsolver_x_lower(solver.get());
        const double hi = gsl_root_fsolver_x_upper(solver.get());
        // y = ln m₁ to ~1e-15 (+ a few ulps of y) is m₁ to ~1e-15 relative.
        if (gsl_root_test_interval(lo, hi, 1e-15, 4e-16) == GSL_SUCCESS)
            return std::exp(gsl_root_fsolver_root(solver.get()));
    }
    throw SolverError("elastica: Brent iteration on the tip angle did not converge");
}

}  // namespace

ElasticaTip elastica_tip(double alpha) {
    ROTBEAM_VERIFY(std::isfinite(alpha) && alpha >= 0.0, "elastica needs a finite α ≥ 0");
    if (alpha == 0.0) return {0.0, 0.0, 0.0, 1.0 / std::sqrt(2.0)};
    const GslErrorHandlerOff guard;
    const double sqrt_alpha = std::sqrt(alpha);
    const Modulus m = modulus_of(solve_m1(sqrt_alpha));
    gsl_sf_result E0;
    if (gsl_sf_ellint_E_e(m.phi0, m.k, GSL_PREC_DOUBLE, &E0) != GSL_SUCCESS)
        throw SolverError("elastica: E(φ₀, k) failed");
    const double E = complete_integrals(m.m1).E;
    ElasticaTip tip;
    tip.modulus = m.k;
    // sin θ₀ = 1 − 2m₁ = cos 2β with sin β = √m₁: θ₀ = π/2 − 2 asin √m₁ keeps m₁'s digits.
    tip.angle = kPi / 2.0 - 2.0 * std::asin(std::sqrt(m.m1));
    tip.deflection = 1.0 - 2.0 * (E - E0.val) / sqrt_alpha;
    tip.shortening = 1.0 - std::sqrt(2.0 * (1.0 - 2.0 * m.m1) / alpha);
    return tip;
}

}  // namespace rotbeam::oracle
