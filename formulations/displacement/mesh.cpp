#include "formulations/displacement/mesh.hpp"

#include <algorithm>
#include <string>

#include "core/errors.hpp"
#include "core/geometry.hpp"
#include "core/lagrange.hpp"
#include "core/quadrature.hpp"
#include "core/so3.hpp"
#include "formulations/displacement/mesh_element.hpp"

namespace rotbeam::form {

namespace {

// Material section at s/L: linear interpolation between stations (one station: constant).
void section_at(const Member& m, double t, Mat6& C, double& mass, Vec3& eta, Mat6& M_star,
                Mat6& D_star) {
    const auto& st = m.sections;
    size_t k = 0;
    while (k + 2 < st.size() && st[k + 1].s_fraction < t) ++k;
    double w = 0.0;
    if (st.size() > 1) {
        const double span = st[k + 1].s_fraction - st[k].s_fraction;
        w = span > 0.0 ? std::clamp((t - st[k].s_fraction) / span, 0.0, 1.0) : 0.0;
    }
    const Section& a = st[k].section;
    const Section& b = st.size() > 1 ? st[k + 1].section : st[k].section;
    C = (1.0 - w) * *a.stiffness + w * *b.stiffness;
    // Stiffness-proportional damping μ C* (seed 000 Eq. 10), μ = diag(damping) scaling the rows.
    D_star = (1.0 - w) * (a.damping.asDiagonal() * *a.stiffness) +
             w * (b.damping.asDiagonal() * *b.stiffness);
    mass = 0.0;
    eta.setZero();
    M_star.setZero();
    if (a.mass && b.mass) {
        const Mat6 M = (1.0 - w) * *a.mass + w * *b.mass;
        M_star = M;
        mass = M(0, 0);
        if (mass > 0.0) eta = so3::axial(M.block<3, 3>(3, 0)) / mass;
    }
}

void check_member(const Model& model, const Member& m) {
    if (m.sections.empty()) throw InputError("member '" + m.name + "': no section");
    for (const SectionStation& s : m.sections) {
        if (!s.section.stiffness) {
            throw InputError("member '" + m.name +
                             "': the displacement formulation needs an invertible compliance "
                             "(a stiffness matrix)");
        }
    }
    if (m.elements < 1) throw InputError("member '" + m.name + "': elements must be ≥ 1");
    const int np = static_cast<int>(model.points.size());
    if (m.start_point < 0 || m.start_point >= np || m.end_point < 0 || m.end_point >= np) {
        throw InputError("member '" + m.name + "': unknown end point");
    }
}

int point_node(Mesh& mesh, const Model& model, int point) {
    if (mesh.point_node[point] < 0) {
        mesh.point_node[point] = static_cast<int>(mesh.nodes.size());
        MeshNode n;
        n.x0 = model.points[point].position;
        n.point = point;
        mesh.nodes.push_back(n);
    }
    return mesh.point_node[point];
}

}  // namespace

// x^r′ from the nodal reference positions (seed 000's equivalent strain): with u interpolated by
// the same functions, a rigid motion is strain-free exactly.
void set_reference_tangents(const Mesh& mesh, MeshElement& e) {
    for (size_t q = 0; q < e.qp.size(); ++q) {
        Vec3 t = Vec3::Zero();
        for (size_t j = 0; j < e.nodes.size(); ++j) t += e.dN(j, q) * mesh.nodes[e.nodes[j]].x0;
        e.qp[q].x0_prime = t;
    }
}

MeshElement make_element(const Model& model, int member, const ReferenceGeometry& g, double s0,
                         double s1, const LagrangeBasis& basis, const QuadratureRule& rule) {
    const Member& m = model.members[member];
    const int nn = basis.size();
    const int nq = static_cast<int>(rule.points.size());
    const double jac = 0.5 * (s1 - s0);
    MeshElement e;
    e.member = member;
    e.N.resize(nn, nq);
    e.dN.resize(nn, nq);
    e.qp.resize(nq);
    VecX v(nn), d(nn);
    for (int q = 0; q < nq; ++q) {
        const double s = s0 + (rule.points[q] + 1.0) * jac;
        basis.values(rule.points[q], v);
        basis.derivatives(rule.points[q], d);
        e.N.col(q) = v;
        e.dN.col(q) = d / jac;
        QuadraturePoint& p = e.qp[q];
        p.weight = rule.weights[q] * jac;
        p.s = s;
        p.Rr = g.frame(s);
        section_at(m, s / g.length(), p.C_star, p.mass, p.eta_star, p.M_star, p.D_star);
    }
    return e;
}

namespace {

// The trapezoidal rule of element [s0, s1] of member m: breakpoints at the element's ends and at
// every section station strictly inside it, each interval divided into d.refine parts. A station
// closer than 1e-12 of the member length to an element end is that end (no sliver interval).
QuadratureRule trapezoidal_rule(const Member& m, const Discretization& d, double L, double s0,
                                double s1, int element) {
    std::vector<double> breaks{-1.0};
    for (const SectionStation& st : m.sections) {
        const double s = st.s_fraction * L;
        if (s > s0 + 1e-12 * L && s < s1 - 1e-12 * L)
            breaks.push_back(2.0 * (s - s0) / (s1 - s0) - 1.0);
    }
    breaks.push_back(1.0);
    QuadratureRule rule = trapezoidal(breaks, d.refine);
    // Fewer points than nodes leave the element's mass singular and, below p points, its
    // stiffness too (a strain of degree p − 1 vanishing at every point need not vanish).
    const int points = static_cast<int>(rule.points.size());
    if (points < d.order + 1) {
        throw InputError("discretization.quadrature: trapezoidal: member '" + m.name +
                         "', element " + std::to_string(element + 1) + " has " +
                         std::to_string(points) + " points, fewer than its " +
                         std::to_string(d.order + 1) +
                         " nodes (its matrices would be singular; raise discretization.refine)");
    }
    return rule;
}

void add_member(Mesh& mesh, const Model& model, int member, const LagrangeBasis& basis,
                const QuadratureRule& fixed_rule) {
    const Member& m = model.members[member];
    check_member(model, m);
    const ReferenceGeometry g(model, member);
    const double L = g.length();
    mesh.max_member_length = std::max(mesh.max_member_length, L);
    const int p = mesh.order;
    int left = point_node(mesh, model, m.start_point);
    for (int k = 0; k < m.elements; ++k) {
        const double s0 = L * k / m.elements;
        const double s1 = L * (k + 1) / m.elements;
        std::vector<int> nodes{left};
        std::vector<double> node_s{s0};
        for (int j = 1; j < p; ++j) {
            const double s = s0 + 0.5 * (basis.nodes()[j] + 1.0) * (s1 - s0);
            node_s.push_back(s);
            MeshNode n;
            n.x0 = g.position(s);
            nodes.push_back(static_cast<int>(mesh.nodes.size()));
            mesh.nodes.push_back(n);
        }
        if (k + 1 == m.elements) {
            left = point_node(mesh, model, m.end_point);
        } else {
            MeshNode n;
            n.x0 = g.position(s1);
            left = static_cast<int>(mesh.nodes.size());
            mesh.nodes.push_back(n);
        }
        nodes.push_back(left);
        node_s.push_back(s1);
        const bool trapezoid = model.discretization.quadrature == Quadrature::trapezoidal;
        const QuadratureRule rule =
            trapezoid ? trapezoidal_rule(m, model.discretization, L, s0, s1, k) : fixed_rule;
        MeshElement e = make_element(model, member, g, s0, s1, basis, rule);
        e.nodes = std::move(nodes);
        e.node_s = std::move(node_s);
        set_reference_tangents(mesh, e);
        mesh.elements.push_back(std::move(e));
    }
}

void apply_constraints(Mesh& mesh, const Model& model) {
    std::vector<bool> fixed(mesh.nodes.size(), false);
    for (const Constraint& c : model.constraints) {
        const int node = (c.point >= 0 && c.point < static_cast<int>(mesh.point_node.size()))
                             ? mesh.point_node[c.point]
                             : -1;
        if (node < 0) throw InputError("constraint on a point that no member reaches");
        if (fixed[node])
            throw InputError("point '" + model.points[c.point].name + "' is constrained twice");
        fixed[node] = true;
        PrescribedMotion pm;
        pm.node = node;
        if (c.kind == Constraint::Kind::prescribed) {
            pm.displacement = c.displacement;
            pm.rotation = c.rotation;
        }
        mesh.prescribed.push_back(pm);
    }
    mesh.unknowns = 0;
    for (size_t i = 0; i < mesh.nodes.size(); ++i) {
        mesh.nodes[i].dof = fixed[i] ? -1 : mesh.unknowns;
        if (!fixed[i]) mesh.unknowns += 6;
    }
}

}  // namespace

int quadrature_point_count(const Discretization& d, bool& gll) {
    const int p = d.order;
    gll = d.quadrature == Quadrature::gll;
    int n = p + 1;
    if (d.quadrature == Quadrature::reduced || (d.quadrature == Quadrature::automatic && p <= 2)) {
        n = p;
    }
    if (d.quadrature_points > 0) n = d.quadrature_points;
    if (gll && n < 2) throw InputError("discretization.quadrature_points: GLL needs ≥ 2 points");
    return n;
}

Mesh build_mesh(const Model& model) {
    const Discretization& d = model.discretization;
    if (d.order < 1) throw InputError("discretization.order: must be ≥ 1");
    if (model.members.empty()) throw InputError("the model has no members");
    Mesh mesh;
    mesh.order = d.order;
    mesh.point_node.assign(model.points.size(), -1);
    const LagrangeBasis basis(gauss_lobatto_legendre(d.order + 1).points);
    // The trapezoidal rule depends on each element's stations (add_member); the others are one
    // rule on [−1, 1] for every element.
    QuadratureRule rule;
    if (d.quadrature != Quadrature::trapezoidal) {
        bool gll = false;
        const int nq = quadrature_point_count(d, gll);
        rule = gll ? gauss_lobatto_legendre(nq) : gauss_legendre(nq);
    }
    for (int m = 0; m < static_cast<int>(model.members.size()); ++m) {
        add_member(mesh, model, m, basis, rule);
    }
    apply_constraints(mesh, model);
    return mesh;
}

}  // namespace rotbeam::form
