// J ← J · blockdiag(T_i) on the three rotation columns of every free node: the change of
// rotation unknowns both displacement problems make — the additive update (δψ = H_s(p) δp,
// DisplacementStatics) and the Lie-group time step (δθ = dexp(ψ) δψ, DisplacementDynamics).
// The three columns of a node share one row pattern (the pattern is built from 6×6 node
// blocks), so the product is formed in place, entry by entry of the column triple: no
// allocation, no change of pattern.
#pragma once

#include <Eigen/Core>

#include "core/nonlinear_system.hpp"
#include "formulations/displacement/mesh.hpp"

namespace rotbeam::form {

// `node_matrix(i)` returns T_i for free node i (called once per free node).
template <class NodeMatrix>
void right_multiply_rotation_columns(SparseMatrix& J, const Mesh& mesh, NodeMatrix&& node_matrix) {
    const int* outer = J.outerIndexPtr();
    double* values = J.valuePtr();
    for (size_t i = 0; i < mesh.nodes.size(); ++i) {
        const int d = mesh.nodes[i].dof;
        if (d < 0) continue;
        const Mat3 T = node_matrix(i);
        const int c = d + 3;
        const int count = outer[c + 1] - outer[c];
        for (int k = 0; k < count; ++k) {
            double* v0 = values + outer[c] + k;
            double* v1 = values + outer[c + 1] + k;
            double* v2 = values + outer[c + 2] + k;
            const Eigen::RowVector3d row = Eigen::RowVector3d(*v0, *v1, *v2) * T;
            *v0 = row[0];
            *v1 = row[1];
            *v2 = row[2];
        }
    }
}

}  // namespace rotbeam::form
