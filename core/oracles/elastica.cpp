#include "core/oracles/elastica.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>
#include <gsl/gsl_sf_ellint.h>

#include <cmath>
#include <memory>

#include "core/errors.hpp"
#include "core/oracles/gsl_guard.hpp"

namespace rotbeam::oracle {
namespace {

struct Modulus {
    double k;
    double phi0;
};

Modulus modulus_of(double sin_theta0) {
    const double k = std::sqrt((1.0 + sin_theta0) / 2.0);
    return {k, std::asin(std::min(1.0, 1.0 / (k * std::sqrt(2.0))))};
}

double ellint_K_minus_F(double k, double phi0) {
    gsl_sf_result K, F;
    if (gsl_sf_ellint_Kcomp_e(k, GSL_PREC_DOUBLE, &K) != GSL_SUCCESS ||
        gsl_sf_ellint_F_e(phi0, k, GSL_PREC_DOUBLE, &F) != GSL_SUCCESS)
        throw SolverError("elastica: elliptic integral of the first kind failed at k = " +
                          std::to_string(k));
    return K.val - F.val;
}

struct LengthEquation {
    double sqrt_alpha;
};

// f(sin θ₀) = K(k) − F(φ₀, k) − √α: increasing from −√α (θ₀ = 0) to +∞ (θ₀ → π/2).
double length_residual(double sin_theta0, void* params) {
    const Modulus m = modulus_of(sin_theta0);
    return ellint_K_minus_F(m.k, m.phi0) - static_cast<LengthEquation*>(params)->sqrt_alpha;
}

double solve_sin_theta0(double sqrt_alpha) {
    LengthEquation equation{sqrt_alpha};
    gsl_function f{&length_residual, &equation};
    const double upper = 1.0 - 1e-14;
    if (length_residual(upper, &equation) < 0.0)
        throw SolverError("elastica: load PL²/EI = " + std::to_string(sqrt_alpha * sqrt_alpha) +
                          " is beyond the bracket of the tip-angle root");
    std::unique_ptr<gsl_root_fsolver, decltype(&gsl_root_fsolver_free)> solver(
        gsl_root_fsolver_alloc(gsl_root_fsolver_brent), &gsl_root_fsolver_free);
    gsl_root_fsolver_set(solver.get(), &f, 0.0, upper);
    for (int iteration = 0; iteration < 200; ++iteration) {
        if (gsl_root_fsolver_iterate(solver.get()) != GSL_SUCCESS) break;
        const double lo = gsl_root_fsolver_x_lower(solver.get());
        const double hi = gsl_root_fsolver_x_upper(solver.get());
        // Bracket down to a few ulps: the tip values are then limited by the elliptic integrals.
        if (gsl_root_test_interval(lo, hi, 1e-18, 4e-16) == GSL_SUCCESS)
            return gsl_root_fsolver_root(solver.get());
    }
    throw SolverError("elastica: Brent iteration on the tip angle did not converge");
}

}  // namespace

ElasticaTip elastica_tip(double alpha) {
    ROTBEAM_VERIFY(std::isfinite(alpha) && alpha >= 0.0, "elastica needs a finite α ≥ 0");
    if (alpha == 0.0) return {0.0, 0.0, 0.0, 1.0 / std::sqrt(2.0)};
    const GslErrorHandlerOff guard;
    const double sqrt_alpha = std::sqrt(alpha);
    const double sin_theta0 = solve_sin_theta0(sqrt_alpha);
    const Modulus m = modulus_of(sin_theta0);
    gsl_sf_result E, E0;
    if (gsl_sf_ellint_Ecomp_e(m.k, GSL_PREC_DOUBLE, &E) != GSL_SUCCESS ||
        gsl_sf_ellint_E_e(m.phi0, m.k, GSL_PREC_DOUBLE, &E0) != GSL_SUCCESS)
        throw SolverError("elastica: elliptic integral of the second kind failed");
    ElasticaTip tip;
    tip.modulus = m.k;
    tip.angle = std::asin(sin_theta0);
    tip.deflection = 1.0 - 2.0 * (E.val - E0.val) / sqrt_alpha;
    tip.shortening = 1.0 - std::sqrt(2.0 * sin_theta0 / alpha);
    return tip;
}

}  // namespace rotbeam::oracle
