#include "core/eigenpair_check.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace rotbeam {

namespace {

// δ of the Kato–Temple bound: the distance from ρ to the nearest computed eigenvalue that is not
// ρ's own. Its own may differ from the Rayleigh quotient by the dense solver's absolute error
// ε‖L⁻¹AL⁻ᵀ‖ = ε λ_max (6e-10 relative for the joined beam's first mode at p = 8), so every entry
// within `radius` (the linear bound: an eigenvalue lies there) or within kClusterWidth |ρ| (a
// double frequency of a symmetric section, split by round-off) counts as ρ's own: the bound is
// then to that cluster.
constexpr double kClusterWidth = 1e-10;

double gap_outside_cluster(double rho, double radius, const std::vector<double>& spectrum) {
    const double own = std::max(radius, kClusterWidth * std::abs(rho));
    double gap = std::numeric_limits<double>::infinity();
    for (double s : spectrum) {
        const double d = std::abs(s - rho);
        if (d > own) gap = std::min(gap, d);
    }
    return gap;
}

}  // namespace

std::vector<EigenpairCheck> check_symmetric_definite(const SparseMatrix& A, const SparseMatrix& B,
                                                     const Eigen::LLT<MatX>& llt,
                                                     std::vector<SymmetricPair>& pairs,
                                                     const std::vector<double>& spectrum) {
    const double norm_a = A.norm(), norm_b = B.norm();
    // The residual in extended precision: formed in double, Ax and ρBx cancel to the round-off of
    // ‖A‖‖x‖, far above the solver's actual residual for the lowest modes of a stiff model (the
    // joined beam at p = 8: a floor of 2e-8 on ρ against 1e-18 for the other modes).
    using VecL = Eigen::Matrix<long double, Eigen::Dynamic, 1>;
    const Eigen::SparseMatrix<long double> Al = A.cast<long double>();
    const Eigen::SparseMatrix<long double> Bl = B.cast<long double>();
    std::vector<VecL> bx;
    std::vector<double> xbx;
    for (const SymmetricPair& p : pairs) {
        bx.push_back(Bl * p.x.cast<long double>());
        xbx.push_back(static_cast<double>(p.x.cast<long double>().dot(bx.back())));
    }
    std::vector<EigenpairCheck> out(pairs.size());
    for (size_t i = 0; i < pairs.size(); ++i) {
        EigenpairCheck& c = out[i];
        SymmetricPair& p = pairs[i];
        const VecL xl = p.x.cast<long double>();
        const VecL ax = Al * xl;
        const long double rho_l = xl.dot(ax) / xl.dot(bx[i]);
        const double rho = static_cast<double>(rho_l);
        const VecX r = (ax - rho_l * bx[i]).cast<double>();
        c.backward_error = r.norm() / ((norm_a + std::abs(rho) * norm_b) * p.x.norm());
        // ‖r‖_{B⁻¹} = ‖L⁻¹r‖ and ‖x‖_B = √(xᵀBx).
        const double r_binv = llt.matrixL().solve(r).norm();
        const double x_b = std::sqrt(std::abs(xbx[i]));
        const double linear = r_binv / x_b;
        const double delta = gap_outside_cluster(rho, linear, spectrum) - linear;
        const double quadratic = delta > 0.0 ? r_binv * r_binv / (x_b * x_b * delta)
                                             : std::numeric_limits<double>::infinity();
        c.error_bound = std::min(linear, quadratic) / std::abs(rho);
        c.mass_orthogonality = 0.0;
        for (size_t j = 0; j < pairs.size(); ++j) {
            if (j == i) continue;
            // Pairs of one cluster span its eigenspace: any B-orthogonal basis of it is right, and
            // the dense solver returns one.
            const double o =
                std::abs(static_cast<double>(xl.dot(bx[j]))) / std::sqrt(std::abs(xbx[i] * xbx[j]));
            c.mass_orthogonality = std::max(c.mass_orthogonality, o);
        }
        p.lambda = rho;
        if (!(std::isfinite(rho) && rho != 0.0 && c.error_bound <= kEigenvalueErrorTolerance)) {
            c.failure = "error bound";
        } else if (!(c.mass_orthogonality <= kMassOrthogonalityTolerance)) {
            c.failure = "mass orthogonality";
        }
        c.accepted = c.failure.empty();
    }
    return out;
}

EigenpairCheck check_general_pair(const SparseMatrix& A, const SparseMatrix& B,
                                  std::complex<double> lambda, const VecXc& x, bool mass) {
    EigenpairCheck c;
    const Eigen::SparseMatrix<std::complex<double>> Ac = A.cast<std::complex<double>>();
    const Eigen::SparseMatrix<std::complex<double>> Bc = B.cast<std::complex<double>>();
    const VecXc bx = Bc * x;
    const VecXc r = Ac * x - lambda * bx;
    const double x_norm = x.norm();
    c.backward_error = r.norm() / ((A.norm() + std::abs(lambda) * B.norm()) * x_norm);
    if (mass) {
        double b_one = 0.0;  // ‖B‖₁: the largest column sum
        for (Eigen::Index k = 0; k < B.outerSize(); ++k) {
            double sum = 0.0;
            for (SparseMatrix::InnerIterator it(B, k); it; ++it) sum += std::abs(it.value());
            b_one = std::max(b_one, sum);
        }
        c.mass_participation = std::abs(x.dot(bx)) / (b_one * x_norm * x_norm);
    }
    if (!(std::isfinite(std::abs(lambda)) && c.backward_error <= kBackwardErrorTolerance)) {
        c.failure = "backward error";
    } else if (mass && !(c.mass_participation >= kMassParticipationTolerance)) {
        c.failure = "mass participation";
    }
    c.accepted = c.failure.empty();
    return c;
}

std::string describe(const EigenpairCheck& c) {
    std::ostringstream s;
    s.precision(2);
    s << std::scientific << "backward error " << c.backward_error;
    if (c.error_bound >= 0.0) s << ", error bound " << c.error_bound;
    if (c.error_estimate >= 0.0) s << ", error estimate " << c.error_estimate;
    if (c.mass_orthogonality >= 0.0) s << ", mass orthogonality " << c.mass_orthogonality;
    if (c.mass_participation >= 0.0) s << ", mass participation " << c.mass_participation;
    if (!c.accepted) s << " (" << c.failure << " check failed)";
    return s.str();
}

}  // namespace rotbeam
