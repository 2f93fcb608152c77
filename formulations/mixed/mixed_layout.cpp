#include "formulations/mixed/mixed_layout.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/errors.hpp"
#include "core/geometry.hpp"

namespace rotbeam::form {

namespace {

// Compliance at s/L by linear interpolation between stations (constant with one station).
Mat6 compliance_at(const Member& member, double fraction) {
    const std::vector<SectionStation>& st = member.sections;
    if (st.size() == 1 || fraction <= st.front().s_fraction) return st.front().section.compliance;
    for (std::size_t k = 1; k < st.size(); ++k) {
        if (fraction <= st[k].s_fraction) {
            const double w =
                (fraction - st[k - 1].s_fraction) / (st[k].s_fraction - st[k - 1].s_fraction);
            return (1.0 - w) * st[k - 1].section.compliance + w * st[k].section.compliance;
        }
    }
    return st.back().section.compliance;
}

// Mass per unit length at s/L (for gravity); zero without a mass matrix.
double mass_per_length(const Member& member, double fraction, bool& has_offset) {
    const std::vector<SectionStation>& st = member.sections;
    std::size_t k = 0;
    while (k + 1 < st.size() && st[k + 1].s_fraction < fraction) ++k;
    if (!st[k].section.mass) return 0.0;
    const Mat6& m = *st[k].section.mass;
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
            const double t = load.time(0.0);
            if (load.frame == LoadFrame::dead) {
                e.f_dead += t * load.force;
                e.m_dead += t * load.moment;
            } else {
                e.f_follower += t * load.force;
                e.m_follower += t * load.moment;
                layout.has_follower = true;
            }
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
    layout.force_scale = model.solver.force_scale > 0.0 ? model.solver.force_scale
                                                        : derived_force_scale(model, layout);
    return layout;
}

void mixed_scales(const MixedLayout& layout, VecX& residual_scale, VecX& increment_scale) {
    const double Ls = layout.length_scale;
    const double Fs = layout.force_scale;
    residual_scale.resize(layout.size());
    increment_scale.resize(layout.size());
    for (int n = 0; n < static_cast<int>(layout.nodes.size()); ++n) {
        const int o = layout.node_offset(n);
        residual_scale.segment<3>(o).setConstant(Fs);
        residual_scale.segment<3>(o + 3).setConstant(Fs * Ls);
        increment_scale.segment<3>(o).setConstant(layout.supported(n) ? Fs : Ls);
        increment_scale.segment<3>(o + 3).setConstant(layout.supported(n) ? Fs * Ls : 1.0);
    }
    for (int e = 0; e < layout.element_count(); ++e) {
        const int o = layout.element_offset(e);
        for (int half = 0; half < 2; ++half) {
            residual_scale.segment<3>(o + 6 * half).setConstant(Ls);
            residual_scale.segment<3>(o + 6 * half + 3).setConstant(1.0);
        }
        increment_scale.segment<3>(o).setConstant(Ls);
        increment_scale.segment<3>(o + 3).setConstant(1.0);
        increment_scale.segment<3>(o + 6).setConstant(Fs);
        increment_scale.segment<3>(o + 9).setConstant(Fs * Ls);
    }
}

SparseMatrix mixed_pattern(const MixedLayout& layout) {
    using Triplet = Eigen::Triplet<double, int>;
    std::vector<Triplet> t;
    auto block = [&t](int r0, int c0, int rows, int cols) {
        for (int j = 0; j < cols; ++j) {
            for (int i = 0; i < rows; ++i) t.emplace_back(r0 + i, c0 + j, 0.0);
        }
    };
    for (int n = 0; n < static_cast<int>(layout.nodes.size()); ++n) {
        const int o = layout.node_offset(n);
        block(o, o, 6, 6);  // reactions and follower point-load stiffness
    }
    for (int e = 0; e < layout.element_count(); ++e) {
        const MixedElement& el = layout.elements[static_cast<std::size_t>(e)];
        const int o = layout.element_offset(e);
        const int a = layout.node_offset(el.start_node);
        const int b = layout.node_offset(el.end_node);
        block(a, o + 3, 6, 9);  // f_u^−, f_ψ^− against c, F, M
        block(b, o + 3, 6, 9);
        block(o, o, 12, 12);    // kinematic rows against u, c, F, M
        block(o, a, 6, 6);      // −û_a, −ĉ_a
        block(o + 6, b, 6, 6);  // +û_b, +ĉ_b
    }
    SparseMatrix J(layout.size(), layout.size());
    J.setFromTriplets(t.begin(), t.end());  // duplicates are summed (all zero)
    J.makeCompressed();
    return J;
}

}  // namespace rotbeam::form
