#include "formulations/displacement/displacement_modal.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

namespace rotbeam::form {

Mesh build_mass_mesh(const Model& model) {
    Model m = model;
    Discretization& d = m.discretization;
    d.quadrature_points = 0;
    if (d.mass_rule == "consistent") {
        d.quadrature = Quadrature::full;
    } else if (d.mass_rule == "midpoint") {
        d.quadrature = Quadrature::full;
        d.quadrature_points = 1;
    } else if (d.mass_rule == "lumped") {
        d.quadrature = Quadrature::gll;
    } else {
        throw InputError("discretization.mass_rule: unknown rule '" + d.mass_rule +
                         "' (consistent | midpoint | lumped)");
    }
    return build_mesh(m);
}

namespace {

struct Eigenpair {
    double omega2 = 0.0;
    double imaginary = 0.0;
    VecX shape;
};

std::vector<Eigenpair> symmetric_pairs(const MatX& K, const MatX& M) {
    const MatX Ks = 0.5 * (K + K.transpose());
    Eigen::GeneralizedSelfAdjointEigenSolver<MatX> es(Ks, M);
    if (es.info() != Eigen::Success) {
        throw SolverError("modal analysis: the mass matrix is not positive definite");
    }
    std::vector<Eigenpair> out;
    for (Eigen::Index i = 0; i < es.eigenvalues().size(); ++i) {
        out.push_back({es.eigenvalues()[i], 0.0, es.eigenvectors().col(i)});
    }
    return out;
}

std::vector<Eigenpair> general_pairs(const MatX& K, const MatX& M) {
    Eigen::GeneralizedEigenSolver<MatX> es(K, M, true);
    if (es.info() != Eigen::Success) throw SolverError("modal analysis: QZ did not converge");
    std::vector<Eigenpair> out;
    const double scale = K.cwiseAbs().maxCoeff() / M.cwiseAbs().maxCoeff();
    for (Eigen::Index i = 0; i < es.betas().size(); ++i) {
        const std::complex<double> alpha = es.alphas()[i];
        const double beta = es.betas()[i];
        if (std::abs(beta) * scale * 1e12 <= std::abs(alpha)) continue;  // infinite
        const std::complex<double> lambda = alpha / beta;
        if (lambda.imag() < 0.0) continue;  // one of each conjugate pair
        out.push_back({lambda.real(), lambda.imag(), es.eigenvectors().col(i).real()});
    }
    return out;
}

}  // namespace

ModalSolution solve_modal(const SparseMatrix& K_sparse, const SparseMatrix& M_sparse, int count) {
    const MatX K(K_sparse);
    const MatX M(M_sparse);
    ModalSolution s;
    const double kmax = K.cwiseAbs().maxCoeff();
    s.asymmetry = kmax > 0.0 ? (K - K.transpose()).cwiseAbs().maxCoeff() / kmax : 0.0;
    s.symmetric = s.asymmetry <= 1e-10;
    std::vector<Eigenpair> pairs = s.symmetric ? symmetric_pairs(K, M) : general_pairs(K, M);
    pairs.erase(std::remove_if(pairs.begin(), pairs.end(),
                               [](const Eigenpair& p) { return !(p.omega2 > 0.0); }),
                pairs.end());
    std::sort(pairs.begin(), pairs.end(),
              [](const Eigenpair& a, const Eigenpair& b) { return a.omega2 < b.omega2; });
    if (static_cast<int>(pairs.size()) < count) {
        std::ostringstream m;
        m << "modal analysis: only " << pairs.size() << " positive eigenvalues, " << count
          << " modes requested";
        throw SolverError(m.str());
    }
    for (int i = 0; i < count; ++i) {
        const Eigenpair& p = pairs[static_cast<size_t>(i)];
        s.frequencies_hz.push_back(std::sqrt(p.omega2) / (2.0 * kPi));
        s.imaginary_parts.push_back(p.imaginary / (4.0 * kPi * kPi));
        s.shapes.push_back(p.shape);
    }
    return s;
}

}  // namespace rotbeam::form
