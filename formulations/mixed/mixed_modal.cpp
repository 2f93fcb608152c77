#include "formulations/mixed/mixed_modal.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <optional>
#include <sstream>
#include <utility>

#include "core/errors.hpp"
#include "core/refined_ritz_modes.hpp"
#include "core/shift_invert_arnoldi.hpp"

namespace rotbeam::form {

namespace {

struct Mode {
    std::complex<double> s;
    VecXc shape;
};

// Keeps one of each conjugate pair of oscillatory eigenvalues (Im s > 0), drops the infinite
// ones (the algebraic unknowns) and real s (non-oscillatory).
std::vector<Mode> modes_from_ritz(const ShiftInvertRitz& ritz, double shift) {
    std::vector<Mode> out;
    for (Eigen::Index i = 0; i < ritz.theta.size(); ++i) {
        const std::optional<std::complex<double>> s = ritz_eigenvalue(ritz, i, shift);
        if (!s || !(s->imag() > kRealEigenvalueTolerance * std::abs(*s))) continue;
        out.push_back({*s, ritz.vectors.col(i)});
    }
    std::sort(out.begin(), out.end(),
              [](const Mode& a, const Mode& b) { return a.s.imag() < b.s.imag(); });
    return out;
}

DaeModalSolution pack(const SparseMatrix& A, const SparseMatrix& B, std::vector<Mode> modes,
                      int count, const std::string& solver) {
    if (static_cast<int>(modes.size()) < count) {
        std::ostringstream m;
        m << "modal analysis (" << solver << "): only " << modes.size()
          << " oscillatory modes found, " << count << " requested";
        throw SolverError(m.str());
    }
    DaeModalSolution s;
    for (int i = 0; i < count; ++i) {
        const Mode& m = modes[static_cast<std::size_t>(i)];
        s.frequencies_hz.push_back(m.s.imag() / (2.0 * kPi));
        s.growth_rates.push_back(m.s.real());
        s.shapes.push_back(m.shape);
        s.checks.push_back(check_general_pair(A, -B, m.s, m.shape, false));
    }
    return s;
}

// The Ritz pairs for `count` modes.
ShiftInvertRitz dae_modal_ritz(const SparseMatrix& A, const SparseMatrix& B, int count,
                               double shift) {
    ROTBEAM_VERIFY(count > 0 && A.rows() == B.rows() && A.rows() == A.cols(), "bad modal input");
    const int n = static_cast<int>(A.rows());
    // Each oscillatory mode is a conjugate pair of Ritz values; two spare pairs guard against a
    // pair split at the edge of the requested set.
    const int nev = std::min(2 * count + 4, n - 2);
    return shift_invert_arnoldi(A, B, nev, shift);
}

}  // namespace

bool DaeModalSolution::accepted() const {
    return std::all_of(checks.begin(), checks.end(),
                       [](const EigenpairCheck& c) { return c.accepted; });
}

DaeModalSolution solve_dae_modal(const SparseMatrix& A, const SparseMatrix& B, int count,
                                 double shift) {
    const ShiftInvertRitz ritz = dae_modal_ritz(A, B, count, shift);
    DaeModalSolution s = pack(A, B, modes_from_ritz(ritz, shift), count, "Arnoldi");
    s.arnoldi_vectors = ritz.arnoldi_vectors;
    s.converged = ritz.converged;
    return s;
}

DaeModalSolution solve_dae_modal_refined(const SparseMatrix& A, const SparseMatrix& B, int count) {
    const ShiftInvertRitz ritz = dae_modal_ritz(A, B, count, 0.0);
    // A φ + s B φ = 0 is the quadratic problem with M = 0, G = B, K = A; the DAE's Jacobians have
    // no symmetry the one-sided functional could use, so the two-sided one is taken.
    const SparseMatrix none(A.rows(), A.cols());
    const QuadraticPencil pencil{none, B, A, false};
    DaeModalSolution s;
    for (RefinedRitzMode& m :
         refined_ritz_modes(ritz, 0.0, pencil, count, "of the linearized dynamics")) {
        s.frequencies_hz.push_back(m.s.imag() / (2.0 * kPi));
        s.growth_rates.push_back(m.s.real());
        s.shapes.push_back(std::move(m.x));
        s.checks.push_back(std::move(m.check));
        s.arnoldi_s.push_back(m.arnoldi_s);
        s.refinement_steps.push_back(m.refinement_steps);
    }
    s.arnoldi_vectors = ritz.arnoldi_vectors;
    s.converged = ritz.converged;
    return s;
}

DaeModalSolution solve_dae_modal_dense(const SparseMatrix& A, const SparseMatrix& B, int count,
                                       double shift) {
    const MatX K = MatX(A) + shift * MatX(B);
    const Eigen::PartialPivLU<MatX> lu(K);
    const MatX C = lu.solve(MatX(B));
    const Eigen::EigenSolver<MatX> es(C, true);
    if (es.info() != Eigen::Success) throw SolverError("modal analysis: dense QR did not converge");
    ShiftInvertRitz all;
    all.theta = es.eigenvalues();
    all.vectors = es.eigenvectors();
    return pack(A, B, modes_from_ritz(all, shift), count, "dense");
}

Model frozen_loads(const Model& model, double lambda, double t) {
    Model m = model;
    TimeFunction one;  // constant 1
    for (PointLoad& p : m.point_loads) {
        const double s = lambda * p.time(t);
        p.force *= s;
        p.moment *= s;
        p.time = one;
    }
    for (DistributedLoad& d : m.distributed_loads) {
        const double s = lambda * d.time(t);
        d.force *= s;
        d.moment *= s;
        d.time = one;
    }
    for (Constraint& c : m.constraints) {
        const double s = lambda;  // as MixedStatics: prescribed motion scales with λ only
        c.displacement *= s;
        c.rotation *= s;
        c.time = one;
    }
    m.gravity *= lambda;
    return m;
}

}  // namespace rotbeam::form
