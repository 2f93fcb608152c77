#include "formulations/displacement/gyroscopic_modal.hpp"

#include <map>
#include <utility>
#include <vector>

#include "core/errors.hpp"
#include "core/so3.hpp"
#include "formulations/displacement/calculate_inertial_forces.hpp"

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

}  // namespace rotbeam::form
