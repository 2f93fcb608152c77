#include "core/oracles/timoshenko.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_roots.h>

#include <Eigen/SVD>
#include <algorithm>
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

namespace {

// The waves of circular frequency ω and the 4×4 boundary matrix of the cantilever in the basis
// w = [e^{−ax}, e^{a(x−L)}, cos bx, sin bx], ψ = [−qa e^{−ax}, qa e^{a(x−L)}, qb sin, −qb cos]:
// each exponential is 1 at the end where it lives and e^{−aL} at the other, so neither overflows
// and a mode's coefficients are all of the size of the mode (with cosh and sinh the hyperbolic part
// is a difference of terms e^{aL} times larger than the mode, its digits lost for aL ≳ 20).
struct CantileverWaves {
    double a = 0.0, b = 0.0, qa = 0.0, qb = 0.0;
    Mat4 boundary;
};

CantileverWaves cantilever_waves(const TimoshenkoBeam& beam, double omega) {
    check_beam(beam);
    const double w2 = omega * omega;
    ROTBEAM_VERIFY(w2 > 0.0 && w2 < cutoff_squared(beam), "ω must lie in (0, cut-off)");
    const double kGA = beam.shear_stiffness, EI = beam.bending_stiffness;
    const double rA = beam.mass_per_length, rI = beam.rotary_inertia, L = beam.length;
    CantileverWaves v;
    // λ² roots of  kGA EI λ⁴ + B λ² + C = 0 with C < 0 below the cut-off.
    const double B = w2 * (kGA * rI + rA * EI);
    const double C = rA * w2 * (rI * w2 - kGA);
    const double disc = std::sqrt(B * B - 4.0 * kGA * EI * C);
    v.a = std::sqrt((-B + disc) / (2.0 * kGA * EI));
    // The negative root is λ² = −b² = (−B − disc)/(2 kGA EI).
    v.b = std::sqrt((B + disc) / (2.0 * kGA * EI));
    const double a = v.a, b = v.b;
    // ψ amplitudes: for e^{λx}, Ψ/W = (kGA λ² + ρA ω²)/(kGA λ) (first equation).
    v.qa = (kGA * a * a + rA * w2) / (kGA * a);
    v.qb = (rA * w2 - kGA * b * b) / (kGA * b);
    const double qa = v.qa, qb = v.qb;
    // The shear strains w' − ψ of the two waves in closed form: a − qa and b + qb computed as
    // differences would cancel catastrophically in the slender (κGA → ∞) limit.
    const double shear_a = -rA * w2 / (kGA * a), shear_b = rA * w2 / (kGA * b);
    const double e = std::exp(-a * L);
    const double c = std::cos(b * L), s = std::sin(b * L);
    v.boundary << 1.0, e, 1.0, 0.0,                        // w(0) = 0
        -qa, qa * e, 0.0, -qb,                             // ψ(0) = 0
        qa * a * e, qa * a, qb * b * c, qb * b * s,        // ψ'(L) = 0
        -shear_a * e, shear_a, -shear_b * s, shear_b * c;  // w'(L) − ψ(L) = 0
    return v;
}

// A mode shape: the boundary matrix's null vector at a natural frequency.
struct ModeShape {
    CantileverWaves waves;
    Vec4 c;
    double length = 1.0;
    double w(double x) const {
        const double bx = waves.b * x;
        return c(0) * std::exp(-waves.a * x) + c(1) * std::exp(waves.a * (x - length)) +
               c(2) * std::cos(bx) + c(3) * std::sin(bx);
    }
    double psi(double x) const {
        const double bx = waves.b * x;
        return waves.qa *
                   (c(1) * std::exp(waves.a * (x - length)) - c(0) * std::exp(-waves.a * x)) +
               waves.qb * (c(2) * std::sin(bx) - c(3) * std::cos(bx));
    }
};

ModeShape mode_shape(const TimoshenkoBeam& beam, double omega) {
    ModeShape m{cantilever_waves(beam, omega), Vec4::Zero(), beam.length};
    const Eigen::JacobiSVD<Mat4> svd(m.waves.boundary, Eigen::ComputeFullV);
    m.c = svd.matrixV().col(3);
    return m;
}

struct MassIntegrand {
    const ModeShape* mode;
    const TimoshenkoBeam* beam;
};

double mass_density(double x, void* params) {
    const auto& p = *static_cast<const MassIntegrand*>(params);
    const double w = p.mode->w(x), psi = p.mode->psi(x);
    return p.beam->mass_per_length * w * w + p.beam->rotary_inertia * psi * psi;
}

// m = ∫₀ᴸ (ρA W² + ρI Ψ²) dx (adaptive Gauss–Kronrod, 1e-10 relative).
double modal_mass(const TimoshenkoBeam& beam, const ModeShape& mode) {
    MassIntegrand params{&mode, &beam};
    gsl_function f{&mass_density, &params};
    std::unique_ptr<gsl_integration_workspace, decltype(&gsl_integration_workspace_free)> work(
        gsl_integration_workspace_alloc(1000), &gsl_integration_workspace_free);
    double m = 0.0, error = 0.0;
    if (gsl_integration_qag(&f, 0.0, beam.length, 0.0, 1e-10, 1000, GSL_INTEG_GAUSS61, work.get(),
                            &m, &error) != GSL_SUCCESS) {
        throw SolverError("Timoshenko modes: the modal mass integral did not converge");
    }
    return m;
}

}  // namespace

double timoshenko_cantilever_determinant(const TimoshenkoBeam& beam, double omega) {
    return cantilever_waves(beam, omega).boundary.determinant();
}

TimoshenkoTipModes timoshenko_tip_modes(const TimoshenkoBeam& beam, double force, int modes) {
    const std::vector<double> omegas = timoshenko_cantilever_frequencies(beam, modes);
    const GslErrorHandlerOff guard;
    TimoshenkoTipModes r;
    r.omegas = omegas;
    // Σ_k W_k(L)² / (ω_k² m_k) is the tip's flexibility under a tip force, δ/P, and
    // Σ_k Ψ_k(L)² / (ω_k² m_k) its rotation's under a tip moment, L/EI (the modal expansion of
    // the flexibility); what the kept modes leave of each bounds the truncated ones.
    double force_flexibility = 0.0, moment_flexibility = 0.0;
    for (const double omega : omegas) {
        const ModeShape mode = mode_shape(beam, omega);
        const double stiffness = omega * omega * modal_mass(beam, mode);
        const double w = mode.w(beam.length), psi = mode.psi(beam.length);
        r.deflection.push_back(force * w * w / stiffness);
        r.rotation.push_back(force * w * psi / stiffness);
        force_flexibility += w * w / stiffness;
        moment_flexibility += psi * psi / stiffness;
    }
    const double force_tail =
        std::max(0.0, timoshenko_tip_deflection(beam, 1.0) - force_flexibility);
    const double moment_tail =
        std::max(0.0, beam.length / beam.bending_stiffness - moment_flexibility);
    r.static_deflection = timoshenko_tip_deflection(beam, force);
    r.static_rotation = force * beam.length * beam.length / (2.0 * beam.bending_stiffness);
    r.deflection_tail = std::abs(force) * force_tail;
    // Cauchy–Schwarz on the truncated modes: |Σ W Ψ/(ω² m)| ≤ √(Σ W²/(ω² m) · Σ Ψ²/(ω² m)).
    r.rotation_tail = std::abs(force) * std::sqrt(force_tail * moment_tail);
    return r;
}

namespace {

// Σ_k a_k g_k(t) over the kept modes.
template <class G>
double modal_sum(const TimoshenkoTipModes& modes, const std::vector<double>& a, G g) {
    double x = 0.0;
    for (std::size_t k = 0; k < modes.omegas.size(); ++k) x += a[k] * g(modes.omegas[k]);
    return x;
}

double sine_response(double w, double omega, double t) {
    return w * w * (std::sin(omega * t) - omega / w * std::sin(w * t)) / (w * w - omega * omega);
}

}  // namespace

double release_tip_deflection(const TimoshenkoTipModes& modes, double t) {
    return modal_sum(modes, modes.deflection, [t](double w) { return std::cos(w * t); });
}

double release_tip_rotation(const TimoshenkoTipModes& modes, double t) {
    return modal_sum(modes, modes.rotation, [t](double w) { return std::cos(w * t); });
}

namespace {

// The kept modes' sine responses plus the truncated modes' quasi-static part (mode acceleration).
double sine_sum(const TimoshenkoTipModes& modes, const std::vector<double>& a, double all,
                double omega, double t) {
    ROTBEAM_VERIFY(omega < modes.omegas.front(), "Ω must lie below the first frequency");
    double kept = 0.0;
    for (const double x : a) kept += x;
    return modal_sum(modes, a, [omega, t](double w) { return sine_response(w, omega, t); }) +
           (all - kept) * std::sin(omega * t);
}

}  // namespace

double sine_tip_deflection(const TimoshenkoTipModes& modes, double omega, double t) {
    return sine_sum(modes, modes.deflection, modes.static_deflection, omega, t);
}

double sine_tip_rotation(const TimoshenkoTipModes& modes, double omega, double t) {
    return sine_sum(modes, modes.rotation, modes.static_rotation, omega, t);
}

double sine_tail_factor(const TimoshenkoTipModes& modes, double omega) {
    return omega / (modes.omegas.back() - omega);
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
