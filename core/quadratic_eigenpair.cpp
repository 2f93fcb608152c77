#include "core/quadratic_eigenpair.hpp"

#include <Eigen/SparseLU>
#include <cmath>
#include <limits>

namespace rotbeam {

namespace {

using Complex = std::complex<double>;
using ComplexSparseMatrix = Eigen::SparseMatrix<Complex>;

constexpr double kUnitRoundOff = std::numeric_limits<double>::epsilon() / 2.0;

ComplexSparseMatrix quadratic_at(const QuadraticPencil& p, Complex s) {
    const ComplexSparseMatrix M = p.M.cast<Complex>(), G = p.G.cast<Complex>(),
                              K = p.K.cast<Complex>();
    ComplexSparseMatrix Q = (s * s) * M + s * G + K;
    Q.makeCompressed();
    return Q;
}

VecXc derivative_times(const QuadraticPencil& p, Complex s, const VecXc& x) {
    return (2.0 * s) * (p.M.cast<Complex>() * x) + p.G.cast<Complex>() * x;
}

// The root of a s² + b s + c = 0 nearest `near` (a ≠ 0), without the cancellation of −b ± √·.
Complex nearest_root(Complex a, Complex b, Complex c, Complex near) {
    const Complex root = std::sqrt(b * b - 4.0 * a * c);
    const Complex q = -0.5 * (std::abs(b + root) >= std::abs(b - root) ? b + root : b - root);
    if (q == Complex(0.0)) return Complex(0.0);  // b = c = 0: the double root 0
    const Complex s1 = q / a, s2 = c / q;
    return std::abs(s1 - near) <= std::abs(s2 - near) ? s1 : s2;
}

// The conservative functional's root nearest `near` (header comment): m ω² + g ω − k = 0 with
// s = iω when g² + 4mk ≥ 0 (Re s exactly 0), else the complex pair (±√(−g² − 4mk) − i g)/2m.
Complex conservative_root(const QuadraticPencil& p, const VecXc& x, Complex near) {
    const double m = x.dot(p.M.cast<Complex>() * x).real();
    const double g = x.dot(p.G.cast<Complex>() * x).imag();
    const double k = x.dot(p.K.cast<Complex>() * x).real();
    const double d = g * g + 4.0 * m * k;
    if (d < 0.0) {
        const double re = std::sqrt(-d) / (2.0 * m), im = -g / (2.0 * m);
        return std::abs(Complex(re, im) - near) <= std::abs(Complex(-re, im) - near)
                   ? Complex(re, im)
                   : Complex(-re, im);
    }
    // ω = (−g ± √d)/2m, the pair formed without cancellation: q = −(g + sign(g)√d)/2.
    const double q = -0.5 * (g + std::copysign(std::sqrt(d), g));
    const double w1 = q / m, w2 = q != 0.0 ? -k / q : 0.0;
    return std::abs(Complex(0.0, w1) - near) <= std::abs(Complex(0.0, w2) - near)
               ? Complex(0.0, w1)
               : Complex(0.0, w2);
}

Complex rayleigh_root(const QuadraticPencil& p, const VecXc& x, const VecXc& y, Complex near) {
    if (p.conservative) return conservative_root(p, x, near);
    const ComplexSparseMatrix M = p.M.cast<Complex>(), G = p.G.cast<Complex>(),
                              K = p.K.cast<Complex>();
    return nearest_root(y.dot(M * x), y.dot(G * x), y.dot(K * x), near);
}

}  // namespace

double quadratic_eigenvalue_error(const QuadraticPencil& p, std::complex<double> s, const VecXc& x,
                                  const VecXc& y) {
    const double slope = std::abs(y.dot(derivative_times(p, s, x)));
    const VecXc r = quadratic_at(p, s) * x;
    // |y|ᵀ(|s|²|M| + |s||G| + |K|)|x|: the entries' absolute values times the vectors' moduli.
    const VecX ax = x.cwiseAbs(), ay = y.cwiseAbs();
    const double as = std::abs(s);
    const double componentwise = as * as * ay.dot(p.M.cwiseAbs() * ax) +
                                 as * ay.dot(p.G.cwiseAbs() * ax) + ay.dot(p.K.cwiseAbs() * ax);
    const double numerator = std::abs(y.dot(r)) + kUnitRoundOff * componentwise;
    if (!(slope > 0.0)) return std::numeric_limits<double>::infinity();
    // Plus s's own rounding to a floating-point number.
    return numerator / slope + kUnitRoundOff * as;
}

RefinedQuadraticPair refine_quadratic_pair(const QuadraticPencil& p, std::complex<double> s0,
                                           const VecXc& x0) {
    RefinedQuadraticPair out;
    out.s = s0;
    out.x = x0.normalized();
    out.y = out.x;
    Eigen::SparseLU<ComplexSparseMatrix> lu;
    for (int step = 0; step < kMaxQuadraticRefinementSteps; ++step) {
        const ComplexSparseMatrix Q = quadratic_at(p, out.s);
        lu.compute(Q);
        // An exactly singular Q(s) (no pivot): s is an eigenvalue to working precision already.
        if (lu.info() != Eigen::Success) break;
        const VecXc x = lu.solve(derivative_times(p, out.s, out.x)).normalized();
        const VecXc y =
            lu.adjoint()
                .solve(VecXc((2.0 * std::conj(out.s)) * (p.M.transpose().cast<Complex>() * out.y) +
                             p.G.transpose().cast<Complex>() * out.y))
                .normalized();
        if (!x.allFinite() || !y.allFinite()) break;
        const Complex s = rayleigh_root(p, x, y, out.s);
        const double moved = std::abs(s - out.s);
        out.s = s;
        out.x = x;
        out.y = y;
        out.steps = step + 1;
        if (moved <= quadratic_eigenvalue_error(p, out.s, out.x, out.y)) break;
    }
    out.error = quadratic_eigenvalue_error(p, out.s, out.x, out.y);
    // How far s₀ may be from its eigenvalue: the Cauchy–Schwarz form of the estimate, a bound to
    // first order whatever direction the Arnoldi pair's residual has.
    const VecXc x0n = x0.normalized();
    const double start_bound =
        (quadratic_at(p, s0) * x0n).norm() / std::abs(out.y.dot(derivative_times(p, s0, x0n)));

    EigenpairCheck& c = out.check;
    const double as = std::abs(out.s);
    const VecXc r = quadratic_at(p, out.s) * out.x;
    c.backward_error = r.norm() / (as * as * p.M.norm() + as * p.G.norm() + p.K.norm());
    c.error_estimate = as > 0.0 ? out.error / as : out.error;
    if (!(std::isfinite(as) && c.backward_error <= kBackwardErrorTolerance)) {
        c.failure = "backward error";
    } else if (!std::isfinite(out.error)) {
        c.failure = "error estimate";  // a defective eigenvalue: no first-order estimate exists
    } else if (!(std::abs(out.s - s0) <= start_bound + out.error)) {
        c.failure = "refinement";
    }
    c.accepted = c.failure.empty();
    return out;
}

}  // namespace rotbeam
