#include "formulations/mixed/mixed_layout.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/errors.hpp"
#include "core/geometry.hpp"

namespace rotbeam::form {

namespace {

// Compliance at s/L: the inverse of the stiffness linear between stations, the rule of the
// displacement mesh (formulations/displacement/mesh.cpp) and of BeamDyn (docs/beamdyn-import.md,
// "Section properties"), so that both formulations discretize one continuous model. A linear
// compliance is a different blade between stations (on the NREL 5-MW blade, 1.25 % of the tip
// deflection under a tip force: docs/mixed-formulation.md). With one station, or a member with a
// rigid component (no stiffness), the compliance itself, linear between stations.
Mat6 compliance_at(const Member& member, double fraction) {
    const std::vector<SectionStation>& st = member.sections;
    const bool stiff = std::all_of(st.begin(), st.end(), [](const SectionStation& s) {
        return s.section.stiffness.has_value();
    });
    if (st.size() == 1 || !stiff) {
        return section_property_at(member, fraction, [](const Section& s) { return s.compliance; });
    }
    const Mat6 C =
        section_property_at(member, fraction, [](const Section& s) { return *s.stiffness; });
    return C.inverse();  // a convex combination of positive definite matrices (case loader)
}

// Mass per unit length at s/L (for gravity), linear between stations like the mass of the
// dynamics (mixed_dynamics.cpp) and of the displacement mesh; a station without a mass matrix
// counts as massless.
double mass_per_length(const Member& member, double fraction, bool& has_offset) {
    const Mat6 m = section_property_at(
        member, fraction, [](const Section& s) -> Mat6 { return s.mass ? *s.mass : Mat6::Zero(); });
    has_offset = has_offset || m.block<3, 3>(0, 3).cwiseAbs().maxCoeff() > 0.0;
    return m(0, 0);
}

// The straight element's frame: e1 along the chord, e2 the mid-length frame's e2 projected
// normal to it (for a circular arc the chord is parallel to the mid-length tangent already).
Mat3 chord_frame(const Mat3& mid, const Vec3& chord) {
    const Vec3 e1 = chord.normalized();
    const Vec3 e2 = (mid.col(1) - mid.col(1).dot(e1) * e1).normalized();
    Mat3 C;
    C << e1, e2, e1.cross(e2);
    return C;
}

void add_member(const Model& model, int mi, MixedLayout& layout) {
    const Member& member = model.members[static_cast<std::size_t>(mi)];
    if (member.sections.empty()) throw InputError("member '" + member.name + "' has no section");
    if (member.elements < 1) throw InputError("member '" + member.name + "' needs ≥ 1 element");
    const ReferenceGeometry geometry(model, mi);
    const int n = member.elements;
    const double L = geometry.length();
    const double dL = L / n;
    int previous = member.start_point;
    for (int i = 0; i < n; ++i) {
        int next = member.end_point;
        if (i + 1 < n) {
            next = static_cast<int>(layout.nodes.size());
            layout.nodes.push_back({-1, -1, geometry.position((i + 1) * dL)});
        }
        MixedElement e;
        e.member = mi;
        e.start_node = previous;
        e.end_node = next;
        e.s_mid = (i + 0.5) * dL;
        e.chord = geometry.position((i + 1) * dL) - geometry.position(i * dL);
        e.length = e.chord.norm();
        e.Cab = chord_frame(geometry.frame(e.s_mid), e.chord);
        e.S = compliance_at(member, e.s_mid / L);
        bool offset = false;
        const double mu = mass_per_length(member, e.s_mid / L, offset);
        if (offset && model.gravity.norm() > 0.0) {
            throw InputError("member '" + member.name +
                             "': gravity with a mass-centre offset is not supported by the mixed "
                             "statics");
        }
        e.f_dead = mu * model.gravity;
        layout.elements.push_back(e);
        previous = next;
    }
}

void add_distributed_loads(const Model& model, MixedLayout& layout) {
    for (const DistributedLoad& load : model.distributed_loads) {
        for (MixedElement& e : layout.elements) {
            if (e.member != load.member) continue;
            e.add_load(load, load.time(0.0));
            if (load.frame == LoadFrame::follower) layout.has_follower = true;
        }
    }
}

double derived_force_scale(const Model& model, const MixedLayout& layout) {
    const double Ls = layout.length_scale;
    double scale = 0.0;
    for (const PointLoad& p : model.point_loads) {
        scale = std::max({scale, p.force.norm(), p.moment.norm() / Ls});
    }
    for (const DistributedLoad& d : model.distributed_loads) {
        scale = std::max({scale, d.force.norm() * Ls, d.moment.norm()});
    }
    scale = std::max(scale, model.gravity.norm() * Ls);
    if (model.rotating_frame.active()) {
        // The centrifugal load m Ω² r over the length, at the node farthest from the axis.
        double r = 0.0;
        for (const MixedNode& n : layout.nodes) {
            r = std::max(r, (n.reference - model.rotating_frame.center).norm());
        }
        const double w2 = model.rotating_frame.angular_velocity.squaredNorm();
        for (const Member& member : model.members) {
            for (const SectionStation& st : member.sections) {
                if (st.section.mass)
                    scale = std::max(scale, (*st.section.mass)(0, 0) * w2 * r * Ls);
            }
        }
    }
    if (scale > 0.0) return scale;
    // No loads (prescribed motion only): the bending stiffness over length squared.
    const double s_bend = layout.elements.front().S(4, 4);
    return s_bend > 0.0 ? 1.0 / (s_bend * Ls * Ls) : 1.0;
}

}  // namespace

MixedLayout build_mixed_layout(const Model& model) {
    if (model.members.empty()) throw InputError("the model has no member");
    MixedLayout layout;
    for (const Point& p : model.points) layout.nodes.push_back({-1, -1, p.position});
    for (std::size_t k = 0; k < model.points.size(); ++k)
        layout.nodes[k].point = static_cast<int>(k);
    for (std::size_t c = 0; c < model.constraints.size(); ++c) {
        const int p = model.constraints[c].point;
        if (p < 0 || p >= static_cast<int>(model.points.size())) {
            throw InputError("constraint " + std::to_string(c) + " names no point");
        }
        layout.nodes[static_cast<std::size_t>(p)].constraint = static_cast<int>(c);
    }
    double total = 0.0;
    for (int m = 0; m < static_cast<int>(model.members.size()); ++m) {
        add_member(model, m, layout);
    }
    for (const MixedElement& e : layout.elements) total += e.length;
    add_distributed_loads(model, layout);
    std::vector<int> degree(model.points.size(), 0);
    for (const Member& m : model.members) {
        ++degree[static_cast<std::size_t>(m.start_point)];
        ++degree[static_cast<std::size_t>(m.end_point)];
    }
    for (std::size_t p = 0; p < degree.size(); ++p) {
        if (degree[p] == 0) {
            throw InputError("point '" + model.points[p].name + "' is on no member");
        }
    }
    for (const PointLoad& p : model.point_loads) {
        layout.has_follower = layout.has_follower || p.frame == LoadFrame::follower;
    }
    layout.length_scale = model.solver.length_scale > 0.0 ? model.solver.length_scale : total;
    layout.rotating = model.rotating_frame.active();
    layout.force_scale = model.solver.force_scale > 0.0 ? model.solver.force_scale
                                                        : derived_force_scale(model, layout);
    return layout;
}

MixedNumbering number_mixed_unknowns(const MixedLayout& layout, int rotation_size,
                                     int constraint_rows, bool dynamic, bool allow_free) {
    MixedNumbering q;
    q.rotation_size = rotation_size;
    q.constraint_rows = constraint_rows;
    q.dynamic = dynamic;
    q.element_count = layout.element_count();
    const int nodes = static_cast<int>(layout.nodes.size());
    for (int n = 0; n < nodes; ++n) q.node_supported.push_back(layout.supported(n));
    for (int n = 0; n < nodes; ++n) {
        if (layout.supported(n)) {
            q.first_support = n;
            break;
        }
    }
    for (int n = 0; n < nodes; ++n) {
        q.node_columns.push_back(q.node_unknowns);
        q.node_sizes.push_back(!layout.supported(n) ? 3 + rotation_size : q.has_scale(n) ? 7 : 6);
        q.node_unknowns += q.node_sizes.back();
    }
    if (constraint_rows == 0) return q;  // 6 per node, as many rows as unknowns per element
    // Columns − rows = nodes − 1 − elements (header): zero exactly for one tree, with at least one
    // support (without one every node has 7 unknowns and the count is one short of square).
    const int rows = 6 * nodes + q.element_rows() * q.element_count;
    // A free tree is one row short: the constraint row (header) closes it.
    q.free_norm = allow_free && q.first_support < 0 && rows + 1 == q.size();
    if (!q.free_norm && (q.first_support < 0 || rows != q.size())) {
        throw InputError(
            "the mixed formulation with the quaternion needs a structure without closed loops "
            "held by at least one support (" +
            std::to_string(nodes) + " nodes, " + std::to_string(q.element_count) +
            " elements): four-component kinematics close a loop with one redundant row");
    }
    return q;
}

void mixed_scales(const MixedLayout& layout, const MixedNumbering& nb, VecX& residual_scale,
                  VecX& increment_scale) {
    const double Ls = layout.length_scale;
    const double Fs = layout.force_scale;
    const int K = nb.rotation_size;
    residual_scale.resize(nb.size());
    increment_scale.resize(nb.size());
    for (int n = 0; n < nb.node_count(); ++n) {
        const int r = nb.node_row(n);
        residual_scale.segment<3>(r).setConstant(Fs);
        residual_scale.segment<3>(r + 3).setConstant(Fs * Ls);
        const int c = nb.node_column(n);
        const bool s = nb.supported(n);
        increment_scale.segment<3>(c).setConstant(s ? Fs : Ls);
        increment_scale.segment<3>(c + 3).setConstant(s ? Fs * Ls : 1.0);
        const int rest = nb.node_sizes[static_cast<std::size_t>(n)] - 6;
        if (rest > 0) increment_scale.segment(c + 6, rest).setConstant(1.0);  // q̂_3 or ρ
    }
    for (int e = 0; e < nb.element_count; ++e) {
        const int r = nb.element_row(e);
        residual_scale.segment<3>(r).setConstant(Ls);           // f_F^−
        residual_scale.segment(r + 3, K).setConstant(1.0);      // f_M^−
        residual_scale.segment<3>(r + 3 + K).setConstant(Ls);   // f_F^+
        residual_scale.segment(r + 6 + K, K).setConstant(1.0);  // f_M^+
        const int c = nb.element_column(e);
        increment_scale.segment<3>(c).setConstant(Ls);
        increment_scale.segment(c + 3, K).setConstant(1.0);
        increment_scale.segment<3>(c + 3 + K).setConstant(Fs);
        increment_scale.segment<3>(c + 6 + K).setConstant(Fs * Ls);
    }
}

SparseMatrix mixed_pattern(const MixedLayout& layout, const MixedNumbering& nb) {
    using Triplet = Eigen::Triplet<double, int>;
    std::vector<Triplet> t;
    auto block = [&t](int r0, int c0, int rows, int cols) {
        for (int j = 0; j < cols; ++j) {
            for (int i = 0; i < rows; ++i) t.emplace_back(r0 + i, c0 + j, 0.0);
        }
    };
    const int K = nb.rotation_size;
    for (int n = 0; n < nb.node_count(); ++n) {
        // Reactions (supported) or the follower point-load stiffness against ĉ (free).
        block(nb.node_row(n), nb.node_column(n), 6, nb.supported(n) ? 6 : 3 + K);
    }
    for (int e = 0; e < nb.element_count; ++e) {
        const MixedElement& el = layout.elements[static_cast<std::size_t>(e)];
        const int r = nb.element_row(e);
        const int c = nb.element_column(e);
        // f_u^∓, f_ψ^∓ against c, F, M (and P, H and the rates in dynamics); against u too in a
        // rotating frame (the centrifugal force depends on the position).
        const int skip = layout.rotating ? 0 : 3;
        block(nb.node_row(el.start_node), c + skip, 6, nb.element_unknowns() - skip);
        block(nb.node_row(el.end_node), c + skip, 6, nb.element_unknowns() - skip);
        block(r, c, nb.element_rows(), nb.element_unknowns());  // the element's own rows
        const int ends[2] = {el.start_node, el.end_node};
        for (int side = 0; side < 2; ++side) {
            const int n = ends[side];
            const int rn = r + (3 + K) * side;
            // ∓û, ∓ĉ. Without a redundant parameter the block is reserved at a support too (zero
            // there, where û, ĉ are given): that has always been the three-parameter pattern, and
            // the pattern decides the sparse LU's fill-reducing ordering, hence the round-off.
            if (!nb.supported(n) || nb.constraint_rows == 0)
                block(rn, nb.node_column(n), 3 + K, 3 + K);
            if (nb.has_scale(n)) block(rn + 3, nb.node_column(n) + 6, K, 1);  // ∓ρ ĉ_given
        }
    }
    const int n = nb.size();
    if (nb.free_norm) block(n - 1, nb.node_column(0) + 3, 1, K);  // the constraint row, q̂_0
    SparseMatrix J(n, n);
    J.setFromTriplets(t.begin(), t.end());  // duplicates are summed (all zero)
    J.makeCompressed();
    return J;
}

}  // namespace rotbeam::form
