#include "formulations/mixed/mixed_quaternion_layout.hpp"

#include <string>

#include "core/errors.hpp"

namespace rotbeam::form {

MixedQuaternionLayout build_mixed_quaternion_layout(const Model& model, bool allow_free) {
    MixedQuaternionLayout q;
    q.base = build_mixed_layout(model);
    const int nodes = static_cast<int>(q.base.nodes.size());
    for (int n = 0; n < nodes; ++n) {
        if (q.base.supported(n)) {
            q.first_support = n;
            break;
        }
    }
    for (int n = 0; n < nodes; ++n) {
        q.node_columns.push_back(q.node_unknowns);
        q.node_sizes.push_back(q.base.supported(n) && !q.has_scale(n) ? 6 : 7);
        q.node_unknowns += q.node_sizes.back();
    }
    // Columns − rows = nodes − 1 − elements (header): zero exactly for one tree, with at least one
    // support (without one every node has 7 unknowns and the count is one short of square).
    const int rows = MixedQuaternionLayout::kNodeRows * nodes +
                     MixedQuaternionLayout::kElementRows * q.base.element_count();
    // A free tree is one row short: the norm row (header) closes it.
    q.free_norm = allow_free && q.first_support < 0 && rows + 1 == q.size();
    if (!q.free_norm && (q.first_support < 0 || rows != q.size())) {
        throw InputError(
            "the mixed formulation with the quaternion needs a structure without closed loops "
            "held by at least one support (" +
            std::to_string(nodes) + " nodes, " + std::to_string(q.base.element_count()) +
            " elements): four-component kinematics close a loop with one redundant row");
    }
    return q;
}

void mixed_quaternion_scales(const MixedQuaternionLayout& layout, VecX& residual_scale,
                             VecX& increment_scale) {
    const double Ls = layout.base.length_scale;
    const double Fs = layout.base.force_scale;
    residual_scale.resize(layout.size());
    increment_scale.resize(layout.size());
    for (int n = 0; n < static_cast<int>(layout.base.nodes.size()); ++n) {
        const int r = layout.node_row(n);
        residual_scale.segment<3>(r).setConstant(Fs);
        residual_scale.segment<3>(r + 3).setConstant(Fs * Ls);
        const int c = layout.node_column(n);
        const bool s = layout.supported(n);
        increment_scale.segment<3>(c).setConstant(s ? Fs : Ls);
        increment_scale.segment<3>(c + 3).setConstant(s ? Fs * Ls : 1.0);
        if (layout.node_sizes[static_cast<std::size_t>(n)] == 7) {
            increment_scale[c + 6] = 1.0;  // q̂_0 of a free node or ρ of a support
        }
    }
    for (int e = 0; e < layout.base.element_count(); ++e) {
        const int r = layout.element_row(e);
        residual_scale.segment<3>(r).setConstant(Ls);        // f_F^−
        residual_scale.segment<4>(r + 3).setConstant(1.0);   // f_M^−
        residual_scale.segment<3>(r + 7).setConstant(Ls);    // f_F^+
        residual_scale.segment<4>(r + 10).setConstant(1.0);  // f_M^+
        const int c = layout.element_column(e);
        increment_scale.segment<3>(c).setConstant(Ls);
        increment_scale.segment<4>(c + 3).setConstant(1.0);
        increment_scale.segment<3>(c + 7).setConstant(Fs);
        increment_scale.segment<3>(c + 10).setConstant(Fs * Ls);
    }
}

SparseMatrix mixed_quaternion_pattern(const MixedQuaternionLayout& layout) {
    using Triplet = Eigen::Triplet<double, int>;
    std::vector<Triplet> t;
    auto block = [&t](int r0, int c0, int rows, int cols) {
        for (int j = 0; j < cols; ++j) {
            for (int i = 0; i < rows; ++i) t.emplace_back(r0 + i, c0 + j, 0.0);
        }
    };
    for (int n = 0; n < static_cast<int>(layout.base.nodes.size()); ++n) {
        // Reactions (supported) or the follower point-load stiffness against q̂ (free).
        block(layout.node_row(n), layout.node_column(n), 6, 6 + (layout.supported(n) ? 0 : 1));
    }
    for (int e = 0; e < layout.base.element_count(); ++e) {
        const MixedElement& el = layout.base.elements[static_cast<std::size_t>(e)];
        const int r = layout.element_row(e);
        const int c = layout.element_column(e);
        block(layout.node_row(el.start_node), c + 3, 6, 10);  // f_u^−, f_ψ^− against q, F, M
        block(layout.node_row(el.end_node), c + 3, 6, 10);
        block(r, c, 14, 13);  // kinematic rows against u, q, F, M
        const int ends[2] = {el.start_node, el.end_node};
        for (int side = 0; side < 2; ++side) {
            const int n = ends[side];
            const int rn = r + 7 * side;
            if (!layout.supported(n)) block(rn, layout.node_column(n), 7, 7);  // ∓û, ∓q̂
            if (layout.has_scale(n)) block(rn + 3, layout.node_column(n) + 6, 4, 1);  // ∓ρ q_given
        }
    }
    SparseMatrix J(layout.size(), layout.size());
    J.setFromTriplets(t.begin(), t.end());  // duplicates are summed (all zero)
    J.makeCompressed();
    return J;
}

}  // namespace rotbeam::form
