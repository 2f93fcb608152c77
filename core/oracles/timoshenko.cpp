#include "core/oracles/timoshenko.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>

#include <cmath>
#include <limits>
#include <memory>

#include "core/errors.hpp"
#include "core/oracles/gsl_guard.hpp"
#include "core/types.hpp"

namespace rotbeam::oracle {
namespace {

void check_beam(const TimoshenkoBeam& b) {
    ROTBEAM_VERIFY(b.length > 0.0 && b.bending_stiffness > 0.0 && b.shear_stiffness > 0.0 &&
                       b.mass_per_length > 0.0 && b.rotary_inertia >= 0.0,
                   "Timoshenko beam needs L, EI, κGA, ρA > 0 and ρI ≥ 0");
}

// ω² cut-off of the first spectrum (infinite without rotary inertia).
double cutoff_squared(const TimoshenkoBeam& b) {
    return b.rotary_inertia > 0.0 ? b.shear_stiffness / b.rotary_inertia
                                  : std::numeric_limits<double>::infinity();
}

// ω from the Euler–Bernoulli wave number β = (ρA ω² L⁴/EI)^{1/4}.
double omega_of_beta(const TimoshenkoBeam& b, double beta) {
    const double L2 = b.length * b.length;
    return beta * beta / L2 * std::sqrt(b.bending_stiffness / b.mass_per_length);
}

double determinant_of_beta(double beta, void* params) {
    const TimoshenkoBeam& b = *static_cast<const TimoshenkoBeam*>(params);
    return timoshenko_cantilever_determinant(b, omega_of_beta(b, beta));
}

double refine_root(const TimoshenkoBeam& beam, double lo, double hi) {
    gsl_function f{&determinant_of_beta, const_cast<TimoshenkoBeam*>(&beam)};
    std::unique_ptr<gsl_root_fsolver, decltype(&gsl_root_fsolver_free)> solver(
        gsl_root_fsolver_alloc(gsl_root_fsolver_brent), &gsl_root_fsolver_free);
    if (gsl_root_fsolver_set(solver.get(), &f, lo, hi) != GSL_SUCCESS)
        throw SolverError("Timoshenko frequencies: could not bracket a root");
    for (int iteration = 0; iteration < 200; ++iteration) {
        if (gsl_root_fsolver_iterate(solver.get()) != GSL_SUCCESS) break;
        if (gsl_root_test_interval(gsl_root_fsolver_x_lower(solver.get()),
                                   gsl_root_fsolver_x_upper(solver.get()), 0.0,
                                   1e-15) == GSL_SUCCESS)
            return omega_of_beta(beam, gsl_root_fsolver_root(solver.get()));
    }
    throw SolverError("Timoshenko frequencies: Brent iteration did not converge");
}

}  // namespace

double timoshenko_tip_deflection(const TimoshenkoBeam& beam, double force) {
    check_beam(beam);
    const double L = beam.length;
    return force * L * L * L / (3.0 * beam.bending_stiffness) + force * L / beam.shear_stiffness;
}

double timoshenko_cantilever_determinant(const TimoshenkoBeam& beam, double omega) {
    check_beam(beam);
    const double w2 = omega * omega;
    ROTBEAM_VERIFY(w2 > 0.0 && w2 < cutoff_squared(beam), "ω must lie in (0, cut-off)");
    const double kGA = beam.shear_stiffness, EI = beam.bending_stiffness;
    const double rA = beam.mass_per_length, rI = beam.rotary_inertia, L = beam.length;
    // λ² roots of  kGA EI λ⁴ + B λ² + C = 0 with C < 0 below the cut-off.
    const double B = w2 * (kGA * rI + rA * EI);
    const double C = rA * w2 * (rI * w2 - kGA);
    const double disc = std::sqrt(B * B - 4.0 * kGA * EI * C);
    const double a = std::sqrt((-B + disc) / (2.0 * kGA * EI));
    // The negative root is λ² = −b² = (−B − disc)/(2 kGA EI).
    const double b = std::sqrt((B + disc) / (2.0 * kGA * EI));
    // ψ amplitudes: for e^{λx}, Ψ/W = (kGA λ² + ρA ω²)/(kGA λ) (first equation).
    const double qa = (kGA * a * a + rA * w2) / (kGA * a);
    const double qb = (rA * w2 - kGA * b * b) / (kGA * b);
    // The shear strains w' − ψ of the two waves in closed form: a − qa and b + qb computed as
    // differences would cancel catastrophically in the slender (κGA → ∞) limit.
    const double shear_a = -rA * w2 / (kGA * a), shear_b = rA * w2 / (kGA * b);
    // Basis w = [cosh ax, sinh ax, cos bx, sin bx], ψ = [qa sinh, qa cosh, qb sin, −qb cos];
    // the hyperbolic columns are scaled by e^{−aL} (a positive factor: zeros unchanged).
    const double ch = 0.5 * (1.0 + std::exp(-2.0 * a * L)),
                 sh = 0.5 * (1.0 - std::exp(-2.0 * a * L));
    const double e = std::exp(-a * L);
    const double c = std::cos(b * L), s = std::sin(b * L);
    Mat4 D;
    D << e, 0.0, 1.0, 0.0,                                      // w(0) = 0
        0.0, qa * e, 0.0, -qb,                                  // ψ(0) = 0
        qa * a * ch, qa * a * sh, qb * b * c, qb * b * s,       // ψ'(L) = 0
        shear_a * sh, shear_a * ch, -shear_b * s, shear_b * c;  // w'(L) − ψ(L) = 0
    return D.determinant();
}

std::vector<double> timoshenko_cantilever_frequencies(const TimoshenkoBeam& beam, int count) {
    check_beam(beam);
    ROTBEAM_VERIFY(count >= 1, "ask for at least one frequency");
    const GslErrorHandlerOff guard;
    // Consecutive Euler–Bernoulli roots are ≈ π apart in β and Timoshenko roots are lower and
    // no closer, so a scan step of 0.01 brackets each root alone.
    const double step = 0.01;
    std::vector<double> omegas;
    TimoshenkoBeam b = beam;
    double beta = 0.05;
    double f_prev = determinant_of_beta(beta, &b);
    while (static_cast<int>(omegas.size()) < count) {
        const double next = beta + step;
        const double w = omega_of_beta(b, next);
        if (!(w * w < cutoff_squared(b)))
            throw SolverError("Timoshenko frequencies: only " + std::to_string(omegas.size()) +
                              " lie below the cut-off");
        const double f_next = determinant_of_beta(next, &b);
        if ((f_prev < 0.0) != (f_next < 0.0)) omegas.push_back(refine_root(b, beta, next));
        beta = next;
        f_prev = f_next;
    }
    return omegas;
}

}  // namespace rotbeam::oracle
