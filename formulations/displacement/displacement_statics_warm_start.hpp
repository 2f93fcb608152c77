// DisplacementStatics<P>: the warm start (core/nodal_field.hpp). Included only by
// displacement_statics.cpp, which instantiates the template for every parameterization.
//
// start_from evaluates another discretization's solution at this mesh's nodes with that
// discretization's own interpolation, so the guess is its discrete solution, not a resampling of
// it: displacements Σ_j N_j(s) u_j through the old element's Lagrange shape functions on its own
// nodes; rotations as that element interpolates them (interpolate_rotation.hpp): `relative`,
// R(s) = R_0 R(r̄(s)) with r̄ = Σ_j N_j r_j the relative parameters of R_0ᵀ R_j; `direct`,
// R(s) = R(p̄(s)) with p̄ = Σ_j N_j σ_j p_j. Both hold for every parameterization (the quaternion's
// homogeneous form is normalized). The new parameters are put in the chart a solve of this
// discretization keeps: the short one when it rescales (as retract does), else the chart nearest
// the old element's closest node, which continues the old parameters along the beam as a solve
// from the undeformed beam does (the rotation vector past π).
#pragma once

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "core/lagrange.hpp"
#include "formulations/displacement/displacement_statics.hpp"

namespace rotbeam::form {

template <param::RotationParameterization P>
std::optional<NodalField> DisplacementStatics<P>::nodal_field() const {
    NodalField f;
    f.parameterization = std::string(P::kName);
    f.relative = relative_;
    for (const MeshElement& e : mesh_.elements) {
        NodalField::Element x{e.member, e.node_s, {}, {}};
        for (const int n : e.nodes) {
            x.displacement.push_back(u_[n]);
            x.rotation.push_back(VecX(p_[n]));
        }
        f.elements.push_back(std::move(x));
    }
    return f;
}

namespace warm_start {

// One element of the field with its nodal parameters typed and its basis on its own nodes.
template <param::RotationParameterization P>
struct OldElement {
    const NodalField::Element* element = nullptr;
    LagrangeBasis basis;
    std::vector<param::Params<P::kSize>> p;
};

// The field's elements, or none when they do not fit P (sizes, ordering).
template <param::RotationParameterization P>
std::vector<OldElement<P>> typed_elements(const NodalField& field) {
    std::vector<OldElement<P>> out;
    for (const NodalField::Element& e : field.elements) {
        const std::size_t nn = e.node_s.size();
        if (nn < 2 || e.displacement.size() != nn || e.rotation.size() != nn) return {};
        for (std::size_t j = 1; j < nn; ++j) {
            if (!(e.node_s[j] > e.node_s[j - 1])) return {};
        }
        std::vector<param::Params<P::kSize>> p;
        for (const VecX& v : e.rotation) {
            if (v.size() != P::kSize) return {};
            p.push_back(v);
        }
        out.push_back({&e, LagrangeBasis(e.node_s), std::move(p)});
    }
    return out;
}

// The element of `member` whose span holds s (its ends within round-off), or null.
template <param::RotationParameterization P>
const OldElement<P>* containing(const std::vector<OldElement<P>>& old, int member, double s) {
    for (const OldElement<P>& o : old) {
        const std::vector<double>& ns = o.element->node_s;
        const double slack = 1e-12 * std::max({1.0, std::abs(ns.front()), std::abs(ns.back())});
        if (o.element->member == member && s >= ns.front() - slack && s <= ns.back() + slack) {
            return &o;
        }
    }
    return nullptr;
}

}  // namespace warm_start

template <param::RotationParameterization P>
bool DisplacementStatics<P>::start_from(const NodalField& field) {
    if (field.parameterization != P::kName || field.relative != relative_) return false;
    const std::vector<warm_start::OldElement<P>> old = warm_start::typed_elements<P>(field);
    if (old.empty()) return false;
    std::vector<Vec3> u = u_;
    std::vector<Params> p = p_;
    std::vector<char> done(mesh_.nodes.size(), 0);
    std::vector<Params> r;
    VecX N;
    try {
        for (const MeshElement& e : mesh_.elements) {
            for (std::size_t j = 0; j < e.nodes.size(); ++j) {
                const int n = e.nodes[j];
                if (mesh_.nodes[n].dof < 0 || done[n]) continue;
                const warm_start::OldElement<P>* o =
                    warm_start::containing<P>(old, e.member, e.node_s[j]);
                if (!o) return false;
                const int nn = o->basis.size();
                N.resize(nn);
                o->basis.values(e.node_s[j], N);
                Vec3 un = Vec3::Zero();
                for (int k = 0; k < nn; ++k) un += N[k] * o->element->displacement[k];
                Params bar = Params::Zero();
                int nearest = 0;
                for (int k = 0; k < nn; ++k) {
                    if (std::abs(N[k]) > std::abs(N[nearest])) nearest = k;
                }
                if (relative_) {
                    r.resize(nn);
                    relative_parameters<P>(o->p.data(), nn, r.data());
                    for (int k = 0; k < nn; ++k) bar += N[k] * r[k];
                } else {
                    for (int k = 0; k < nn; ++k) {
                        bar += N[k] * chart_sign<P>(o->p[k], o->p[0]) * o->p[k];
                    }
                }
                if constexpr (P::kSize == 4) bar.normalize();
                Params pn = relative_ ? P::compose(o->p[0], bar) : bar;
                const Params& near = o->p[nearest];
                if constexpr (P::kSize == 4) {
                    pn *= chart_sign<P>(pn, near);
                } else if constexpr (P::kCanRescale) {
                    pn = P::rescale(pn, rescale_nodes_ ? P::identity() : near);
                }
                if (!un.allFinite() || !pn.allFinite()) return false;
                u[n] = un;
                p[n] = pn;
                done[n] = 1;
            }
        }
    } catch (const SingularityError&) {
        return false;  // a parameter at its chart's singular angle: no guess, the state unchanged
    }
    u_ = std::move(u);
    p_ = std::move(p);
    mip_.drop();
    return true;
}

}  // namespace rotbeam::form
