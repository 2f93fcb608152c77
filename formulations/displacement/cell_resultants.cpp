#include "formulations/displacement/cell_resultants.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "core/geometry.hpp"
#include "core/lagrange.hpp"
#include "core/quadrature.hpp"
#include "formulations/displacement/calculate_elastic_forces.hpp"
#include "formulations/displacement/calculate_strain.hpp"
#include "formulations/displacement/interpolate_rotation.hpp"
#include "formulations/displacement/mesh.hpp"
#include "formulations/displacement/mesh_element.hpp"
#include "formulations/displacement/rotate_section.hpp"
#include "parameterizations/registry.hpp"

namespace rotbeam::form {

namespace {

// Every element of the mesh with the points midway between its neighbouring nodes as its
// quadrature points (weights zero: nothing is integrated).
std::vector<MeshElement> cell_midpoint_elements(const Model& model, const Mesh& mesh) {
    const LagrangeBasis basis(gauss_lobatto_legendre(mesh.order + 1).points);
    QuadratureRule midpoints;
    for (int j = 0; j < mesh.order; ++j) {
        midpoints.points.push_back(0.5 * (basis.nodes()[j] + basis.nodes()[j + 1]));
        midpoints.weights.push_back(0.0);
    }
    std::vector<ReferenceGeometry> geometry;
    for (size_t m = 0; m < model.members.size(); ++m)
        geometry.emplace_back(model, static_cast<int>(m));
    std::vector<MeshElement> out;
    for (const MeshElement& e : mesh.elements) {
        MeshElement c = make_element(model, e.member, geometry[static_cast<size_t>(e.member)],
                                     e.node_s.front(), e.node_s.back(), basis, midpoints);
        c.nodes = e.nodes;
        c.node_s = e.node_s;
        set_reference_tangents(mesh, c);
        out.push_back(std::move(c));
    }
    return out;
}

// Whether `field` holds the state of `mesh`: its elements, members and node arc lengths.
bool field_fits_mesh(const NodalField& field, const Mesh& mesh) {
    if (field.elements.size() != mesh.elements.size()) return false;
    for (size_t k = 0; k < mesh.elements.size(); ++k) {
        const NodalField::Element& f = field.elements[k];
        const MeshElement& e = mesh.elements[k];
        if (f.member != e.member || f.node_s.size() != e.node_s.size() ||
            f.displacement.size() != e.nodes.size() || f.rotation.size() != e.nodes.size())
            return false;
        for (size_t j = 0; j < e.node_s.size(); ++j) {
            const double slack = 1e-12 * std::max(1.0, std::abs(e.node_s.back()));
            if (std::abs(f.node_s[j] - e.node_s[j]) > slack) return false;
        }
    }
    return true;
}

template <param::RotationParameterization P>
std::vector<SectionResultants> cell_resultants_of(const std::vector<MeshElement>& cells,
                                                  const NodalField& field) {
    using Params = param::Params<P::kSize>;
    std::vector<SectionResultants> out;
    for (size_t k = 0; k < cells.size(); ++k) {
        const MeshElement& e = cells[k];
        const NodalField::Element& f = field.elements[k];
        const int nn = static_cast<int>(e.nodes.size());
        std::vector<Params> pe;
        for (const VecX& v : f.rotation) {
            if (v.size() != P::kSize) return {};
            pe.emplace_back(v);
        }
        // As DisplacementStatics::gather_element: relative parameters of R_0ᵀ R_j, or the direct
        // ones in the chart of the element's first node.
        Mat3 R0 = Mat3::Identity();
        if (field.relative) {
            R0 = P::matrix(pe[0]);
            relative_parameters<P>(pe.data(), nn, pe.data());
        } else {
            for (int j = 1; j < nn; ++j) pe[j] *= chart_sign<P>(pe[j], pe[0]);
        }
        for (int q = 0; q < static_cast<int>(e.qp.size()); ++q) {
            const QuadraturePoint& qp = e.qp[q];
            const double* N = e.N.col(q).data();
            const double* dN = e.dN.col(q).data();
            InterpolatedRotation<P> rot;
            if (field.relative) {
                interpolate_relative<P>(pe.data(), N, dN, nn, R0, rot);
            } else {
                interpolate_rotation<P>(pe.data(), N, dN, nn, rot);
            }
            Vec3 up = Vec3::Zero();
            for (int j = 0; j < nn; ++j) up += dN[j] * f.displacement[j];
            const Vec6 strain = calculate_strain(qp.x0_prime, up, rot.R, rot.kappa);
            const Mat3 Q = rot.R * qp.Rr;
            const Vec6 F =
                calculate_elastic_forces(rotate_section(qp.C_star, Q), strain, qp.x0_prime + up)
                    .FE1;
            const Vec3 force = F.head<3>();
            const Vec3 moment = F.tail<3>();
            out.push_back(
                {e.member, qp.s, force, moment, Q.transpose() * force, Q.transpose() * moment});
        }
    }
    return out;
}

}  // namespace

std::vector<SectionResultants> displacement_cell_resultants(const Model& model,
                                                            const NodalField& field) {
    const std::optional<ParameterizationId> id =
        param::parse_parameterization(field.parameterization);
    if (!id) return {};
    const Mesh mesh = build_mesh(model);
    if (!field_fits_mesh(field, mesh)) return {};
    const std::vector<MeshElement> cells = cell_midpoint_elements(model, mesh);
    return param::dispatch_parameterization(
        *id, [&]<class P>() { return cell_resultants_of<P>(cells, field); });
}

}  // namespace rotbeam::form
