// assemble_mass_matrix (displacement_modal.hpp): templated on how nodal rotations are read.
#pragma once

#include <vector>

#include "core/errors.hpp"
#include "core/so3.hpp"

namespace rotbeam::form {

template <class NodeRotation>
SparseMatrix assemble_mass_matrix(const Model& model, const Mesh& mesh,
                                  const NodeRotation& node_rotation) {
    std::vector<Eigen::Triplet<double>> triplets;
    for (const MeshElement& e : mesh.elements) {
        const int nn = static_cast<int>(e.nodes.size());
        const Mat3 R0 = node_rotation(e.nodes[0]);
        std::vector<Vec3> log_rel(static_cast<size_t>(nn));
        for (int j = 0; j < nn; ++j) {
            log_rel[static_cast<size_t>(j)] = so3::log_map(R0.transpose() * node_rotation(e.nodes[j]));
        }
        for (size_t q = 0; q < e.qp.size(); ++q) {
            const QuadraturePoint& p = e.qp[q];
            if (!(p.M_star(0, 0) > 0.0)) {
                throw InputError("member '" + model.members[static_cast<size_t>(e.member)].name +
                                 "': modal and dynamic analyses need a section mass (density or "
                                 "mass)");
            }
            Vec3 psi = Vec3::Zero();
            for (int j = 0; j < nn; ++j) psi += e.N(j, static_cast<Eigen::Index>(q)) * log_rel[static_cast<size_t>(j)];
            const Mat3 Q = R0 * so3::exp_map(psi) * p.Rr;
            Mat6 M = p.M_star;
            M.topLeftCorner<3, 3>() = Q * M.topLeftCorner<3, 3>() * Q.transpose();
            M.topRightCorner<3, 3>() = Q * M.topRightCorner<3, 3>() * Q.transpose();
            M.bottomLeftCorner<3, 3>() = Q * M.bottomLeftCorner<3, 3>() * Q.transpose();
            M.bottomRightCorner<3, 3>() = Q * M.bottomRightCorner<3, 3>() * Q.transpose();
            for (int a = 0; a < nn; ++a) {
                const int ra = mesh.nodes[static_cast<size_t>(e.nodes[a])].dof;
                if (ra < 0) continue;
                for (int b = 0; b < nn; ++b) {
                    const int cb = mesh.nodes[static_cast<size_t>(e.nodes[b])].dof;
                    if (cb < 0) continue;
                    const double w = p.weight * e.N(a, static_cast<Eigen::Index>(q)) *
                                     e.N(b, static_cast<Eigen::Index>(q));
                    for (int i = 0; i < 6; ++i) {
                        for (int k = 0; k < 6; ++k) {
                            if (M(i, k) != 0.0) triplets.emplace_back(ra + i, cb + k, w * M(i, k));
                        }
                    }
                }
            }
        }
    }
    SparseMatrix out(mesh.unknowns, mesh.unknowns);
    out.setFromTriplets(triplets.begin(), triplets.end());
    return out;
}

}  // namespace rotbeam::form
