#include "core/static_stability.hpp"

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "core/potential_hessian.hpp"

namespace rotbeam {

const char* to_string(StaticStability::Assessment a) {
    switch (a) {
        case StaticStability::Assessment::not_assessed:
            return "not-assessed";
        case StaticStability::Assessment::stable:
            return "stable";
        case StaticStability::Assessment::unstable:
            return "unstable";
        case StaticStability::Assessment::critical:
            return "critical";
    }
    return "not-assessed";
}

const char* to_string(StaticStability::Criterion c) {
    switch (c) {
        case StaticStability::Criterion::none:
            return "none";
        case StaticStability::Criterion::energy:
            return "energy";
        case StaticStability::Criterion::kinetic:
            return "kinetic";
    }
    return "none";
}

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

double max_abs(const SparseMatrix& A) {
    double m = 0.0;
    for (int k = 0; k < A.outerSize(); ++k) {
        for (SparseMatrix::InnerIterator it(A, k); it; ++it) m = std::max(m, std::abs(it.value()));
    }
    return m;
}

// ‖A‖_∞ of a symmetric matrix (its largest column sum).
double infinity_norm(const SparseMatrix& A) {
    double m = 0.0;
    for (int k = 0; k < A.outerSize(); ++k) {
        double sum = 0.0;
        for (SparseMatrix::InnerIterator it(A, k); it; ++it) sum += std::abs(it.value());
        m = std::max(m, sum);
    }
    return m;
}

StaticStability not_assessed(const std::string& why) {
    StaticStability s;
    s.reason = why;
    return s;
}

// The inertia of `tangent`; a pivot within `scaled_error` (or n ε of the largest scaled entry)
// of zero is `critical`.
StaticStability scaled_inertia(const SparseMatrix& tangent, const VecX& increment_scale,
                               double scaled_error) {
    const SparseMatrix scaled =
        increment_scale.asDiagonal() * tangent * increment_scale.asDiagonal();
    const SparseMatrix transposed = scaled.transpose();
    const double norm = max_abs(scaled);
    if (!(norm > 0.0) || !std::isfinite(norm))
        return not_assessed("the tangent is zero or not finite");
    // A difference Hessian whose own error (inter-node asymmetry, and the step-halving difference
    // of its central differences) exceeds kDifferenceLimit of its largest entry is not a matrix
    // whose pivot signs can be trusted: central differences at h = ε^(1/3) of a smooth energy
    // err by ~ε^(2/3) ≈ 4e-11 of the entries (measured 5e-12 … 1e-11; an energy interpolated in
    // the Euler angles 0.03 rad from gimbal lock erred by 2e-8). The limit leaves 4 decades to
    // the smooth case.
    constexpr double kDifferenceLimit = 1e-7;
    if (scaled_error > kDifferenceLimit * norm) {
        std::ostringstream s;
        s.precision(2);
        s << "the difference Hessian is not accurate (error " << scaled_error / norm
          << " of its largest entry)";
        return not_assessed(s.str());
    }
    // Symmetric to round-off: an asymmetry beyond n ε of the largest scaled entry (the zero
    // threshold of the pivots below) is not round-off of a Hessian's assembly, and Sylvester's
    // count of its symmetric part is then not a criterion. The straight column's Newton tangent
    // measures exactly 0; at deformed states it measures 4e-7 … 1e-4 (its residual is not the
    // energy's gradient), so the driver assesses the potential's Hessian there
    // (core/potential_hessian.hpp; docs/solver-convergence.md, Stability of the equilibrium).
    const double n_eps = static_cast<double>(scaled.rows()) * kEps;
    const double asymmetry = max_abs(scaled - transposed) / norm;
    if (asymmetry > n_eps) {
        std::ostringstream s;
        s.precision(2);
        s << "the tangent is not symmetric (scaled asymmetry " << asymmetry
          << "): no energy, no inertia criterion";
        return not_assessed(s.str());
    }
    const SparseMatrix S = 0.5 * (scaled + transposed);
    Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower, Eigen::AMDOrdering<int>> ldlt(S);
    if (ldlt.info() != Eigen::Success) {
        return not_assessed("the LDLT factorization of the tangent met a zero pivot");
    }
    // The factorization does not pivot for stability: on an indefinite S its entries may grow
    // and its pivots belong to a matrix far from S. Its backward error on one solve (right-hand
    // side S·1) measures that: a stable factorization gives O(n ε); above √ε (growth of ~1e8)
    // the pivots' signs are not taken for S's.
    const Eigen::Index n = S.rows();
    const VecX ones = VecX::Ones(n);
    const VecX b = S * ones;
    const VecX x = ldlt.solve(b);
    const double backward =
        (S * x - b).lpNorm<Eigen::Infinity>() /
        (infinity_norm(S) * x.lpNorm<Eigen::Infinity>() + b.lpNorm<Eigen::Infinity>());
    if (!std::isfinite(backward) || backward > std::sqrt(kEps)) {
        std::ostringstream s;
        s.precision(2);
        s << "the LDLT factorization of the indefinite tangent is not accurate (backward error "
          << backward << ")";
        return not_assessed(s.str());
    }
    // A pivot below n ε ‖S‖ is at the size of the factorization's round-off: its sign, and so
    // the count, is not known (the threshold at which the dense eigenvalues of the same scaled
    // tangent lose their sign, tests/runs/test_static_stability.cpp).
    const double tiny = std::max(n_eps * norm, scaled_error);
    const VecX& d = ldlt.vectorD();
    StaticStability out;
    out.criterion = StaticStability::Criterion::energy;
    int zero = 0;
    for (Eigen::Index i = 0; i < n; ++i) {
        if (d(i) < -tiny) {
            ++out.negative;
        } else if (d(i) <= tiny) {
            ++zero;
        }
    }
    if (zero > 0) {
        std::ostringstream s;
        s << zero << " pivot(s) at round-off level (|d| <= " << tiny
          << " of the scaled tangent): singular to working precision";
        out.assessment = StaticStability::Assessment::critical;
        out.reason = s.str();
    } else {
        out.assessment = out.negative > 0 ? StaticStability::Assessment::unstable
                                          : StaticStability::Assessment::stable;
    }
    return out;
}

}  // namespace

StaticStability assess_stability(const SparseMatrix& tangent, const VecX& increment_scale) {
    return scaled_inertia(tangent, increment_scale, 0.0);
}

StaticStability assess_potential_stability(const PotentialHessian& hessian,
                                           const VecX& increment_scale) {
    return scaled_inertia(hessian.matrix, increment_scale, hessian.scaled_error);
}

}  // namespace rotbeam
