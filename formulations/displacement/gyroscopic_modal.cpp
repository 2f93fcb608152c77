#include "formulations/displacement/gyroscopic_modal.hpp"

#include <algorithm>
#include <map>
#include <utility>
#include <vector>

#include "core/errors.hpp"
#include "core/quadratic_eigenpair.hpp"
#include "core/refined_ritz_modes.hpp"
#include "core/shift_invert_arnoldi.hpp"
#include "core/so3.hpp"
#include "formulations/displacement/calculate_inertial_forces.hpp"
#include "formulations/displacement/displacement_modal.hpp"

namespace rotbeam::form {

SparseMatrix gyroscopic_matrix(const SparseMatrix& M, const Vec3& omega) {
    ROTBEAM_VERIFY(M.rows() % 6 == 0 && M.rows() == M.cols(), "6 unknowns per node");
    std::map<std::pair<Eigen::Index, Eigen::Index>, Mat6> blocks;
    for (Eigen::Index k = 0; k < M.outerSize(); ++k) {
        for (SparseMatrix::InnerIterator it(M, k); it; ++it) {
            auto [entry, fresh] = blocks.try_emplace({it.row() / 6, it.col() / 6}, Mat6::Zero());
            entry->second(it.row() % 6, it.col() % 6) = it.value();
        }
    }
    const Mat3 W = so3::skew(omega);
    std::vector<Eigen::Triplet<double>> triplets;
    for (const auto& [at, Mab] : blocks) {
        InertialState s;  // Q = I: the block is already in the unknowns' axes
        s.omega = omega;
        const InertialBlocks b = calculate_inertial_blocks(Mab, s);
        Mat6 G = b.G;
        G.leftCols<3>() += 2.0 * b.M.leftCols<3>() * W;
        G.rightCols<3>() += b.M.rightCols<3>() * W;
        for (int i = 0; i < 6; ++i) {
            for (int j = 0; j < 6; ++j) {
                if (G(i, j) != 0.0)
                    triplets.emplace_back(6 * at.first + i, 6 * at.second + j, G(i, j));
            }
        }
    }
    SparseMatrix G(M.rows(), M.cols());
    G.setFromTriplets(triplets.begin(), triplets.end());
    return G;
}

GyroscopicPencil gyroscopic_pencil(const SparseMatrix& K, const SparseMatrix& G,
                                   const SparseMatrix& M) {
    const Eigen::Index n = K.rows();
    GyroscopicPencil p;
    const VecX diagonal = M.diagonal();
    if (!(diagonal.minCoeff() > 0.0)) {
        throw SolverError(
            "modal analysis about the rotating state: the mass matrix has an "
            "unknown without inertia (a section without rotary inertia)");
    }
    p.scaling = diagonal.cwiseSqrt().cwiseInverse();
    const auto D = p.scaling.asDiagonal();
    const SparseMatrix Ks = D * K * D, Gs = D * G * D, Ms = D * M * D;
    std::vector<Eigen::Triplet<double>> a, b;
    for (Eigen::Index i = 0; i < n; ++i) {
        a.emplace_back(i, n + i, -1.0);
        b.emplace_back(i, i, 1.0);
    }
    // S into rows n.. and columns `column`.. of t.
    const auto lower = [n](std::vector<Eigen::Triplet<double>>& t, const SparseMatrix& S,
                           Eigen::Index column) {
        for (Eigen::Index k = 0; k < S.outerSize(); ++k) {
            for (SparseMatrix::InnerIterator it(S, k); it; ++it) {
                t.emplace_back(n + it.row(), column + it.col(), it.value());
            }
        }
    };
    lower(a, Ks, 0);
    lower(a, Gs, n);
    lower(b, Ms, n);
    p.A.resize(2 * n, 2 * n);
    p.A.setFromTriplets(a.begin(), a.end());
    p.B.resize(2 * n, 2 * n);
    p.B.setFromTriplets(b.begin(), b.end());
    return p;
}

namespace {

// ‖S ∓ Sᵀ‖_max / ‖S‖_max: the asymmetry (sign −1) or the departure from skew symmetry (+1).
double gyroscopic_structure_defect(const SparseMatrix& S, double sign) {
    if (S.nonZeros() == 0) return 0.0;  // G = 0 (no spin): no entries to take a maximum over
    const double largest = S.coeffs().cwiseAbs().maxCoeff();
    if (!(largest > 0.0)) return 0.0;
    const SparseMatrix d = S + sign * SparseMatrix(S.transpose());
    return d.nonZeros() > 0 ? d.coeffs().cwiseAbs().maxCoeff() / largest : 0.0;
}

}  // namespace

GyroscopicModes solve_gyroscopic_modes(const SparseMatrix& K, const SparseMatrix& G,
                                       const SparseMatrix& M, int count, bool conservative_loads) {
    ROTBEAM_VERIFY(count > 0, "modal analysis: a positive mode count");
    const GyroscopicPencil pencil = gyroscopic_pencil(K, G, M);
    const auto D = pencil.scaling.asDiagonal();
    const SparseMatrix Ks = D * K * D, Gs = D * G * D, Ms = D * M * D;
    GyroscopicModes out;
    out.conservative = gyroscopic_structure_defect(Ks, -1.0) <= kStiffnessSymmetryTolerance &&
                       gyroscopic_structure_defect(Gs, 1.0) <= kStiffnessSymmetryTolerance &&
                       gyroscopic_structure_defect(Ms, -1.0) <= kStiffnessSymmetryTolerance;

    const Eigen::Index n = K.rows();
    // Each mode is a conjugate (or a ±) pair of Ritz values; two spare pairs guard against a
    // pair split at the edge of the requested set (as the mixed formulation's modal analysis).
    const int nev = std::min(2 * count + 4, static_cast<int>(2 * n) - 2);
    const ShiftInvertRitz ritz = shift_invert_arnoldi(pencil.A, pencil.B, nev, 0.0);
    out.arnoldi_vectors = ritz.arnoldi_vectors;
    QuadraticPencil q{Ms, Gs, Ks, out.conservative};
    // Conservative loads and a K that is not symmetric: the weak form's skew part (header).
    const SparseMatrix skew = 0.5 * (Ks - SparseMatrix(Ks.transpose()));
    if (conservative_loads && !out.conservative) {
        q.discretization_skew = &skew;
        out.discretization_asymmetry = gyroscopic_structure_defect(Ks, -1.0);
    }
    for (RefinedRitzMode& r : refined_ritz_modes(ritz, 0.0, q, count, "about the rotating state")) {
        GyroscopicMode m;
        m.s = r.s;
        m.arnoldi_s = r.arnoldi_s;
        m.shape = pencil.scaling.cast<std::complex<double>>().asDiagonal() * r.x;
        m.check = std::move(r.check);
        m.error = r.error;
        m.refinement_steps = r.refinement_steps;
        out.modes.push_back(std::move(m));
    }
    return out;
}

}  // namespace rotbeam::form
