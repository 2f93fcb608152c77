#include "core/lagrange.hpp"

#include <cmath>
#include <string>

#include "core/errors.hpp"

namespace rotbeam {

LagrangeBasis::LagrangeBasis(std::vector<double> nodes) : nodes_(std::move(nodes)) {
    const int n = size();
    ROTBEAM_VERIFY(n >= 1, "LagrangeBasis needs at least one node");
    bary_.assign(n, 1.0);
    for (int j = 0; j < n; ++j) {
        for (int k = 0; k < n; ++k) {
            if (k == j) continue;
            const double d = nodes_[j] - nodes_[k];
            ROTBEAM_VERIFY(d != 0.0, "LagrangeBasis nodes must be distinct");
            bary_[j] /= d;
        }
    }
}

void LagrangeBasis::values(double x, Eigen::Ref<VecX> out) const {
    const int n = size();
    ROTBEAM_VERIFY(out.size() == n, "LagrangeBasis::values: output size " + std::to_string(out.size()));
    for (int j = 0; j < n; ++j) {
        if (x == nodes_[j]) {
            out.setZero();
            out[j] = 1.0;
            return;
        }
    }
    double sum = 0.0;
    for (int j = 0; j < n; ++j) {
        out[j] = bary_[j] / (x - nodes_[j]);
        sum += out[j];
    }
    out /= sum;
}

void LagrangeBasis::derivatives(double x, Eigen::Ref<VecX> out) const {
    // dN_j(x) = N_j(x) Σ_{k≠j} 1/(x − x_k); at a node x_i, use the differentiation-matrix row
    // D_ij = (w_j/w_i)/(x_i − x_j), D_ii = −Σ_{j≠i} D_ij (rows sum to zero exactly).
    const int n = size();
    ROTBEAM_VERIFY(out.size() == n, "LagrangeBasis::derivatives: output size " + std::to_string(out.size()));
    for (int i = 0; i < n; ++i) {
        if (x == nodes_[i]) {
            double diag = 0.0;
            for (int j = 0; j < n; ++j) {
                if (j == i) continue;
                out[j] = (bary_[j] / bary_[i]) / (x - nodes_[j]);
                diag -= out[j];
            }
            out[i] = diag;
            return;
        }
    }
    VecX N(n);
    values(x, N);
    double s_total = 0.0;
    for (int k = 0; k < n; ++k) s_total += 1.0 / (x - nodes_[k]);
    for (int j = 0; j < n; ++j) out[j] = N[j] * (s_total - 1.0 / (x - nodes_[j]));
    // Enforce Σ dN_j = 0 (partition of unity) against round-off.
    const double mean = out.sum() / n;
    out.array() -= mean;
}

}  // namespace rotbeam
