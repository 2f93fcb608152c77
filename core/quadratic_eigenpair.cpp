#include "core/quadratic_eigenpair.hpp"

#include <Eigen/SparseLU>
#include <cmath>
#include <limits>

#include "core/errors.hpp"

namespace rotbeam {

namespace {

using Complex = std::complex<double>;
using ComplexSparseMatrix = Eigen::SparseMatrix<Complex>;

constexpr double kUnitRoundOff = std::numeric_limits<double>::epsilon() / 2.0;

// M, G, K in complex arithmetic, all three on the union of their patterns (in the same order),
// so that Q(s) is formed entry by entry: cast once per pair, not once per product.
struct ComplexPencil {
    ComplexSparseMatrix M, G, K;
    explicit ComplexPencil(const QuadraticPencil& p) {
        const SparseMatrix zero = 0.0 * SparseMatrix(p.M + p.G + p.K);  // the union pattern
        M = SparseMatrix(p.M + zero).cast<Complex>();
        G = SparseMatrix(p.G + zero).cast<Complex>();
        K = SparseMatrix(p.K + zero).cast<Complex>();
        M.makeCompressed();
        G.makeCompressed();
        K.makeCompressed();
        ROTBEAM_VERIFY(M.nonZeros() == K.nonZeros() && G.nonZeros() == K.nonZeros(),
                       "one pattern for M, G, K");
    }
    ComplexSparseMatrix at(Complex s) const {
        ComplexSparseMatrix Q = K;
        const Eigen::Index n = Q.nonZeros();
        Eigen::Map<VecXc>(Q.valuePtr(), n) = (s * s) * Eigen::Map<const VecXc>(M.valuePtr(), n) +
                                             s * Eigen::Map<const VecXc>(G.valuePtr(), n) +
                                             Eigen::Map<const VecXc>(K.valuePtr(), n);
        return Q;
    }
    VecXc derivative_times(Complex s, const VecXc& x) const {
        return (2.0 * s) * VecXc(M * x) + VecXc(G * x);
    }
};

// The root of a s² + b s + c = 0 nearest `near`, without the cancellation of −b ± √·; for a = 0
// (a linear pencil, M = 0) the one root −c/b.
Complex nearest_root(Complex a, Complex b, Complex c, Complex near) {
    if (a == Complex(0.0)) return -c / b;
    const Complex root = std::sqrt(b * b - 4.0 * a * c);
    const Complex q = -0.5 * (std::abs(b + root) >= std::abs(b - root) ? b + root : b - root);
    if (q == Complex(0.0)) return Complex(0.0);  // b = c = 0: the double root 0
    const Complex s1 = q / a, s2 = c / q;
    return std::abs(s1 - near) <= std::abs(s2 - near) ? s1 : s2;
}

// The conservative functional's root nearest `near` (header comment): m ω² + g ω − k = 0 with
// s = iω when g² + 4mk ≥ 0 (Re s exactly 0), else the complex pair (±√(−g² − 4mk) − i g)/2m.
Complex conservative_root(const ComplexPencil& p, const VecXc& x, Complex near) {
    const double m = x.dot(VecXc(p.M * x)).real();
    const double g = x.dot(VecXc(p.G * x)).imag();
    const double k = x.dot(VecXc(p.K * x)).real();
    const double d = g * g + 4.0 * m * k;
    if (d < 0.0) {
        // im: +0 for a real x (g = 0), not −0 (a frequency of −0 Hz in the output).
        const double re = std::sqrt(-d) / (2.0 * m), im = g != 0.0 ? -g / (2.0 * m) : 0.0;
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

Complex rayleigh_root(const ComplexPencil& c, bool conservative, const VecXc& x, const VecXc& y,
                      Complex near) {
    if (conservative) return conservative_root(c, x, near);
    return nearest_root(y.dot(VecXc(c.M * x)), y.dot(VecXc(c.G * x)), y.dot(VecXc(c.K * x)), near);
}

double eigenvalue_error(const QuadraticPencil& p, const ComplexPencil& c, Complex s, const VecXc& x,
                        const VecXc& y) {
    const double slope = std::abs(y.dot(c.derivative_times(s, x)));
    const VecXc r = c.at(s) * x;
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

}  // namespace

double quadratic_eigenvalue_error(const QuadraticPencil& p, std::complex<double> s, const VecXc& x,
                                  const VecXc& y) {
    return eigenvalue_error(p, ComplexPencil(p), s, x, y);
}

RefinedQuadraticPair refine_quadratic_pair(const QuadraticPencil& p, std::complex<double> s0,
                                           const VecXc& x0) {
    const ComplexPencil c(p);
    RefinedQuadraticPair out;
    out.s = s0;
    out.x = x0.normalized();
    out.y = out.x;
    Eigen::SparseLU<ComplexSparseMatrix> lu;
    lu.analyzePattern(c.K);                                            // the pattern of every Q(s)
    const ComplexSparseMatrix Mt = c.M.adjoint(), Gt = c.G.adjoint();  // real: Mᵀ, Gᵀ
    for (int step = 0; step < kMaxQuadraticRefinementSteps; ++step) {
        lu.factorize(c.at(out.s));
        // An exactly singular Q(s) (no pivot): s is an eigenvalue to working precision already.
        if (lu.info() != Eigen::Success) break;
        const VecXc x = lu.solve(c.derivative_times(out.s, out.x)).normalized();
        // Q(s)ᴴ y' = Q'(s)ᴴ y, Q'(s)ᴴ = 2 s̄ Mᵀ + Gᵀ.
        const VecXc y =
            lu.adjoint()
                .solve(VecXc((2.0 * std::conj(out.s)) * VecXc(Mt * out.y) + VecXc(Gt * out.y)))
                .normalized();
        if (!x.allFinite() || !y.allFinite()) break;
        const Complex s = rayleigh_root(c, p.conservative, x, y, out.s);
        const double moved = std::abs(s - out.s);
        out.s = s;
        out.x = x;
        out.y = y;
        out.steps = step + 1;
        if (moved <= eigenvalue_error(p, c, out.s, out.x, out.y)) break;
    }
    out.error = eigenvalue_error(p, c, out.s, out.x, out.y);
    if (p.discretization_skew != nullptr) {
        const VecXc nx = p.discretization_skew->cast<Complex>() * out.x;
        out.error +=
            std::abs(out.y.dot(nx)) / std::abs(out.y.dot(c.derivative_times(out.s, out.x)));
    }
    // How far s₀ may be from its eigenvalue: the Cauchy–Schwarz form of the estimate, a bound to
    // first order whatever direction the Arnoldi pair's residual has.
    const VecXc x0n = x0.normalized();
    const double start_bound =
        (c.at(s0) * x0n).norm() / std::abs(out.y.dot(c.derivative_times(s0, x0n)));

    EigenpairCheck& check = out.check;
    const double as = std::abs(out.s);
    const VecXc r = c.at(out.s) * out.x;
    check.backward_error = r.norm() / (as * as * p.M.norm() + as * p.G.norm() + p.K.norm());
    check.error_estimate = as > 0.0 ? out.error / as : out.error;
    if (!(std::isfinite(as) && check.backward_error <= kBackwardErrorTolerance)) {
        check.failure = "backward error";
    } else if (!std::isfinite(out.error)) {
        check.failure = "error estimate";  // a defective eigenvalue: no first-order estimate exists
    } else if (!(std::abs(out.s - s0) <= start_bound + out.error)) {
        check.failure = "refinement";
    }
    check.accepted = check.failure.empty();
    return out;
}

}  // namespace rotbeam
