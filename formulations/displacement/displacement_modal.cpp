#include "formulations/displacement/displacement_modal.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <optional>
#include <sstream>

namespace rotbeam::form {

Mesh build_mass_mesh(const Model& model) {
    Model m = model;
    Discretization& d = m.discretization;
    d.quadrature_points = 0;
    switch (d.displacement.mass_rule) {
        case MassRule::consistent:
            // A trapezoidal stiffness rule keeps its station points for the inertia too, as
            // BeamDyn integrates both there: p+1 Gauss points would sample a tabulated section
            // at p+1 places only.
            if (d.quadrature != Quadrature::trapezoidal) d.quadrature = Quadrature::full;
            break;
        case MassRule::midpoint:
            d.quadrature = Quadrature::full;
            d.quadrature_points = 1;
            break;
        case MassRule::lumped:
            d.quadrature = Quadrature::gll;
            break;
    }
    return build_mesh(m);
}

namespace {

struct Eigenpair {
    std::complex<double> omega2;
    VecXc shape;  // in the scaled unknowns
};

// D = diag(M)^(−1/2). A zero or negative diagonal entry is an unknown without inertia: M is
// singular and the pencil has an infinite eigenvalue there, whatever the solver.
VecX mass_scaling(const SparseMatrix& M) {
    const VecX d = M.diagonal();
    for (Eigen::Index i = 0; i < d.size(); ++i) {
        if (!(d[i] > 0.0)) {
            static const char* const kComponent[6] = {"u_x", "u_y", "u_z", "ψ_x", "ψ_y", "ψ_z"};
            throw SolverError("modal analysis: the mass matrix has no inertia on unknown " +
                              std::to_string(i) + " (" + kComponent[i % 6] +
                              " of a node): a section without rotary inertia or a mass rule "
                              "with too few points");
        }
    }
    return d.cwiseSqrt().cwiseInverse();
}

// Cholesky of the scaled mass. Its failure is reported with the smallest pivot reached, never
// handed to an eigensolver (which would turn the indefinite factor into eigenvalues of any size).
Eigen::LLT<MatX> mass_cholesky(const MatX& M) {
    Eigen::LLT<MatX> llt(M);
    if (llt.info() != Eigen::Success) {
        throw SolverError(
            "modal analysis: the mass matrix is not positive definite (no Cholesky factor): a "
            "mass rule with too few points for the element order, or a section without inertia");
    }
    return llt;
}

std::vector<Eigenpair> symmetric_pairs(const MatX& K, const Eigen::LLT<MatX>& llt) {
    // L⁻¹ K L⁻ᵀ z = ω² z, x = L⁻ᵀ z (Eigen's GeneralizedSelfAdjointEigenSolver, factor reused).
    MatX C = llt.matrixL().solve(K);
    C = llt.matrixL().solve(C.transpose()).transpose();
    const Eigen::SelfAdjointEigenSolver<MatX> es(0.5 * (C + C.transpose()));
    if (es.info() != Eigen::Success) {
        throw SolverError("modal analysis: the symmetric eigensolver did not converge");
    }
    const MatX X = llt.matrixU().solve(es.eigenvectors());
    std::vector<Eigenpair> out;
    for (Eigen::Index i = 0; i < es.eigenvalues().size(); ++i) {
        out.push_back({es.eigenvalues()[i], X.col(i).cast<std::complex<double>>()});
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
        out.push_back({lambda, es.eigenvectors().col(i)});
    }
    return out;
}

// s = i√ω² with Im s ≥ 0; the pair ±Re s both exist, the growing one is reported.
void set_motion(ModalPair& p) {
    const std::complex<double> root = std::sqrt(p.omega2);  // principal: Re ≥ 0
    p.frequency_hz = root.real() / (2.0 * kPi);
    p.growth_rate = std::abs(root.imag());
}

}  // namespace

bool ModalSolution::accepted() const {
    return std::all_of(pairs.begin(), pairs.end(),
                       [](const ModalPair& p) { return p.check.accepted; });
}

ModalSolution solve_modal(const SparseMatrix& K_sparse, const SparseMatrix& M_sparse, int count) {
    const VecX D = mass_scaling(M_sparse);
    const SparseMatrix Ks = D.asDiagonal() * K_sparse * D.asDiagonal();
    const SparseMatrix Ms = D.asDiagonal() * M_sparse * D.asDiagonal();
    const MatX K(Ks);
    const MatX M(Ms);
    ModalSolution s;
    const double kmax = K.cwiseAbs().maxCoeff();
    s.asymmetry = kmax > 0.0 ? (K - K.transpose()).cwiseAbs().maxCoeff() / kmax : 0.0;
    s.symmetric = s.asymmetry <= kStiffnessSymmetryTolerance;
    std::optional<Eigen::LLT<MatX>> llt;
    if (s.symmetric) llt = mass_cholesky(M);
    std::vector<Eigenpair> pairs = s.symmetric ? symmetric_pairs(K, *llt) : general_pairs(K, M);
    std::vector<double> spectrum;  // ascending (the symmetric solver's order), for the gaps
    for (const Eigenpair& p : pairs) spectrum.push_back(p.omega2.real());
    std::sort(pairs.begin(), pairs.end(), [](const Eigenpair& a, const Eigenpair& b) {
        return std::abs(a.omega2) < std::abs(b.omega2);
    });
    if (static_cast<int>(pairs.size()) < count) {
        std::ostringstream m;
        m << "modal analysis: only " << pairs.size() << " finite eigenvalues, " << count
          << " modes requested";
        throw SolverError(m.str());
    }
    pairs.resize(static_cast<size_t>(count));
    std::vector<EigenpairCheck> checks;
    if (s.symmetric) {
        const SparseMatrix K_sym = 0.5 * (Ks + SparseMatrix(Ks.transpose()));
        std::vector<SymmetricPair> sp;
        for (const Eigenpair& p : pairs) sp.push_back({p.omega2.real(), p.shape.real()});
        checks = check_symmetric_definite(K_sym, Ms, *llt, sp, spectrum);
        for (size_t i = 0; i < pairs.size(); ++i) pairs[i].omega2 = sp[i].lambda;
    } else {
        for (const Eigenpair& p : pairs) {
            checks.push_back(check_general_pair(Ks, Ms, p.omega2, p.shape, true));
        }
    }
    for (size_t i = 0; i < pairs.size(); ++i) {
        ModalPair m;
        m.omega2 = pairs[i].omega2;
        m.shape = D.cast<std::complex<double>>().asDiagonal() * pairs[i].shape;
        // Phase removed: the largest component real and positive (a real ω²'s shape is real).
        Eigen::Index peak = 0;
        m.shape.cwiseAbs().maxCoeff(&peak);
        if (std::abs(m.shape[peak]) > 0.0) m.shape *= std::abs(m.shape[peak]) / m.shape[peak];
        m.check = checks[i];
        set_motion(m);
        s.frequencies_hz.push_back(m.frequency_hz);
        s.shapes.push_back(m.shape.real());
        s.pairs.push_back(std::move(m));
    }
    return s;
}

}  // namespace rotbeam::form
