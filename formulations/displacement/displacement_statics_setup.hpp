// DisplacementStatics<P>: construction, sparsity pattern, scales, state handling. Included only by
// displacement_statics.cpp, which instantiates the template for every parameterization.
#pragma once

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/beam_rotation.hpp"
#include "core/errors.hpp"
#include "core/so3.hpp"
#include "formulations/displacement/displacement_statics.hpp"
#include "formulations/displacement/rotation_columns.hpp"

namespace rotbeam::form {

template <param::RotationParameterization P>
DisplacementStatics<P>::DisplacementStatics(const Model& model)
    : model_(model), mesh_(build_mesh(model)) {
    assemble_absent_terms(model.solver.assemble_all_terms, model.solver.assemble_all_terms);
    const size_t nodes = mesh_.nodes.size();
    u_.assign(nodes, Vec3::Zero());
    p_.assign(nodes, P::identity());
    p_trial_ = p_;
    for (int k = 0; k < kCheckpointSlots; ++k) {
        saved_u_[k] = u_;
        saved_p_[k] = p_;
    }
    for (size_t k = 0; k < model.point_loads.size(); ++k) {
        const PointLoad& l = model.point_loads[k];
        const int node = (l.point >= 0 && l.point < static_cast<int>(mesh_.point_node.size()))
                             ? mesh_.point_node[l.point]
                             : -1;
        if (node < 0) throw InputError("point load on a point that no member reaches");
        point_loads_.push_back(
            {node, l.force, l.moment, l.frame == LoadFrame::follower, 1.0, static_cast<int>(k)});
    }
    distributed_factor_.assign(model.distributed_loads.size(), 1.0);
    for (const DistributedLoad& l : model.distributed_loads) {
        if (l.member < 0 || l.member >= static_cast<int>(model.members.size())) {
            throw InputError("distributed load on an unknown member");
        }
    }
    if (model.gravity.norm() > 0.0) {
        for (const MeshElement& e : mesh_.elements) {
            for (const QuadraturePoint& q : e.qp) {
                if (!(q.mass > 0.0)) {
                    throw InputError("member '" + model.members[e.member].name +
                                     "': gravity needs a section mass matrix");
                }
            }
        }
    }
    relative_ = model.discretization.displacement.interpolation == Interpolation::relative;
    rescale_nodes_ = relative_ && model.discretization.displacement.rescale && P::kCanRescale;
    rescale_refused_ = !relative_ && model.discretization.displacement.rescale && P::kCanRescale;
    additive_ = model.discretization.displacement.update == Update::additive;
    if (model.discretization.displacement.mip && additive_) {
        throw InputError(
            "solver.mip: the mixed-integration-point Newton needs the "
            "multiplicative update (its stress prediction maps δψ, not δp)");
    }
    if (additive_ && P::kSize != 3) {
        throw InputError(
            "discretization.update: additive needs a three-parameter rotation "
            "(wiener-milenkovic | rodrigues | rotation-vector | euler-angles), not '" +
            std::string(P::kName) + "'");
    }
    const size_t nn = static_cast<size_t>(mesh_.order) + 1;
    pe_.resize(nn);
    ue_.resize(nn);
    Me_.resize(nn);
    A_.resize(nn);
    K_.resize(nn);
    D_.resize(nn);
    E_.resize(nn);
    build_pattern();
    mip_.setup(mesh_, model.discretization.displacement.mip);
    compute_scales(model);
    set_load_factor(0.0);
}

template <param::RotationParameterization P>
void DisplacementStatics<P>::build_pattern() {
    const int n = mesh_.unknowns;
    std::vector<Eigen::Triplet<double, int>> triplets;
    for (const MeshElement& e : mesh_.elements) {
        for (int a : e.nodes) {
            for (int b : e.nodes) {
                const int ra = mesh_.nodes[a].dof, cb = mesh_.nodes[b].dof;
                if (ra < 0 || cb < 0) continue;
                for (int i = 0; i < 6; ++i) {
                    for (int j = 0; j < 6; ++j) triplets.emplace_back(ra + i, cb + j, 0.0);
                }
            }
        }
    }
    pattern_.resize(n, n);
    pattern_.setFromTriplets(triplets.begin(), triplets.end());
    pattern_.makeCompressed();
    // Value index of (row, col): the rows of a node's 6 unknowns are contiguous in each column.
    const auto index_of = [this](int row, int col) {
        const int* begin = pattern_.innerIndexPtr() + pattern_.outerIndexPtr()[col];
        const int* end = pattern_.innerIndexPtr() + pattern_.outerIndexPtr()[col + 1];
        const int* it = std::lower_bound(begin, end, row);
        ROTBEAM_VERIFY(it != end && *it == row, "sparsity pattern misses an element block");
        return static_cast<int>(it - pattern_.innerIndexPtr());
    };
    block_index_.assign(mesh_.elements.size(), {});
    for (size_t k = 0; k < mesh_.elements.size(); ++k) {
        const std::vector<int>& nodes = mesh_.elements[k].nodes;
        const int nn = static_cast<int>(nodes.size());
        block_index_[k].assign(nodes.size() * nodes.size() * 6, -1);
        for (int a = 0; a < nn; ++a) {
            for (int b = 0; b < nn; ++b) {
                const int ra = mesh_.nodes[nodes[a]].dof, cb = mesh_.nodes[nodes[b]].dof;
                if (ra < 0 || cb < 0) continue;
                for (int c = 0; c < 6; ++c)
                    block_index_[k][(a * nn + b) * 6 + c] = index_of(ra, cb + c);
            }
        }
    }
    diagonal_index_.assign(mesh_.nodes.size() * 6, -1);
    for (size_t i = 0; i < mesh_.nodes.size(); ++i) {
        const int d = mesh_.nodes[i].dof;
        if (d < 0) continue;
        for (int c = 0; c < 6; ++c) diagonal_index_[i * 6 + c] = index_of(d, d + c);
    }
}

// Force scale: the largest applied load at λ = 1 (moments / L, distributed × L, weight); with no
// loads (prescribed motion only) the bending stiffness over L² times the prescribed magnitude.
template <param::RotationParameterization P>
void DisplacementStatics<P>::compute_scales(const Model& model) {
    const double L =
        model.solver.length_scale > 0.0 ? model.solver.length_scale : mesh_.max_member_length;
    double F = 0.0;
    for (const PointLoad& l : model.point_loads) {
        F = std::max({F, l.force.norm(), l.moment.norm() / L});
    }
    for (const DistributedLoad& l : model.distributed_loads) {
        F = std::max({F, l.force.norm() * L, l.moment.norm()});
    }
    double stiffness = 0.0;
    for (const MeshElement& e : mesh_.elements) {
        for (const QuadraturePoint& q : e.qp) {
            F = std::max(F, q.mass * model.gravity.norm() * L);
            stiffness = std::max(stiffness, q.C_star.block<3, 3>(3, 3).diagonal().maxCoeff());
            axial_stiffness_ =
                std::max(axial_stiffness_, q.C_star.block<3, 3>(0, 0).diagonal().maxCoeff());
        }
    }
    if (model.rotating_frame.active()) {
        // The centrifugal load m Ω² r over the length, at the node farthest from the axis.
        const RotatingFrame& f = model.rotating_frame;
        double r = 0.0;
        for (const MeshNode& n : mesh_.nodes) r = std::max(r, (n.x0 - f.center).norm());
        for (const MeshElement& e : mesh_.elements) {
            for (const QuadraturePoint& q : e.qp) {
                F = std::max(F, q.M_star(0, 0) * f.angular_velocity.squaredNorm() * r * L);
            }
        }
    }
    if (!(F > 0.0)) {
        double motion = 0.0;
        for (const PrescribedMotion& m : mesh_.prescribed) {
            motion = std::max({motion, m.displacement.norm() / L, m.rotation.norm()});
        }
        F = stiffness / (L * L) * (motion > 0.0 ? motion : 1.0);
    }
    fixed_force_scale_ = model.solver.force_scale > 0.0;
    if (fixed_force_scale_) F = model.solver.force_scale;
    unit_force_scale_ = F;
    force_scale_ = F;
    length_scale_ = L;
    residual_scale_.resize(mesh_.unknowns);
    increment_scale_.resize(mesh_.unknowns);
    for (int i = 0; i < mesh_.unknowns; i += 6) {
        increment_scale_.segment<3>(i).setConstant(L);
        increment_scale_.segment<3>(i + 3).setConstant(1.0);
    }
    update_residual_scale();
}

// The loads grow with λ, so does the characteristic force: F(λ) = max(1, |λ|) F(1), unless the
// case fixes it (solver.force_scale). A force scale frozen at λ = 1 would ask for 1e-12 of a unit
// load when the case applies 600 units (the 45° bend) — far below the round-off of the residual
// (EA ε_mach per term). The values change in place (drivers hold a reference).
template <param::RotationParameterization P>
void DisplacementStatics<P>::update_residual_scale() {
    // Floor: the residual's round-off is ~c ε_mach EA (c ≲ 1e3: sums over quadrature points
    // weighted by |N′| ~ p²/h). With F ≥ 1e-4 EA that floor stays ≤ 2e-9 scaled, where the
    // driver's stall test recognizes it (stalled-at-round-off, within 100× the floor it expects,
    // docs/solver-convergence.md); below it, a small load on a stiff member (13 lbf on EA = 1e7)
    // would stall far above any tolerance a user would ask for.
    constexpr double kRoundoffFloor = 1e-4;
    force_scale_ = fixed_force_scale_
                       ? unit_force_scale_
                       : std::max(std::max(1.0, std::abs(lambda_)) * unit_force_scale_,
                                  kRoundoffFloor * axial_stiffness_);
    for (int i = 0; i < mesh_.unknowns; i += 6) {
        residual_scale_.segment<3>(i).setConstant(force_scale_);
        residual_scale_.segment<3>(i + 3).setConstant(force_scale_ * length_scale_);
    }
}

template <param::RotationParameterization P>
void DisplacementStatics<P>::set_load_factor(double lambda) {
    lambda_ = lambda;
    mip_.drop();
    if (residual_scale_.size() == mesh_.unknowns) update_residual_scale();
    for (const PrescribedMotion& m : mesh_.prescribed) {
        u_[m.node] = lambda * m.displacement;
        p_[m.node] = P::from_rotation_vector(lambda * m.rotation);
    }
}

template <param::RotationParameterization P>
void DisplacementStatics<P>::set_time(double t) {
    set_load_factor(1.0);
    time_ = t;
    for (NodeLoad& l : point_loads_) l.factor = model_.point_loads[l.source].time(t);
    for (size_t i = 0; i < distributed_factor_.size(); ++i) {
        distributed_factor_[i] = model_.distributed_loads[i].time(t);
    }
}

// p ← exp(δψ) ⊗ p for every free node; all new parameters are computed before any is stored, so
// a parameterization refusing one leaves the state unchanged. The quaternion is renormalized
// (R is homogeneous in q, so this only stops the norm drifting).
template <param::RotationParameterization P>
void DisplacementStatics<P>::retract(const Eigen::Ref<const VecX>& dx) {
    for (size_t i = 0; i < mesh_.nodes.size(); ++i) {
        const int d = mesh_.nodes[i].dof;
        if (d < 0) continue;
        const Vec3 dpsi = dx.segment<3>(d + 3);
        if constexpr (P::kSize == 3) {
            if (additive_) {
                p_trial_[i] = p_[i] + dpsi;  // δp, not δψ
                if (rescale_nodes_) p_trial_[i] = P::rescale(p_trial_[i], P::identity());
                continue;
            }
        }
        p_trial_[i] = P::compose(P::from_rotation_vector(dpsi), p_[i]);
        if constexpr (P::kSize == 4) p_trial_[i].normalize();
        if (rescale_nodes_) p_trial_[i] = P::rescale(p_trial_[i], P::identity());
    }
    for (size_t i = 0; i < mesh_.nodes.size(); ++i) {
        const int d = mesh_.nodes[i].dof;
        if (d < 0) continue;
        u_[i] += dx.segment<3>(d);
        p_[i] = p_trial_[i];
    }
    mip_.retract(mesh_, dx);
}

template <param::RotationParameterization P>
void DisplacementStatics<P>::save_state(int slot) {
    ROTBEAM_VERIFY(slot >= 0 && slot < kCheckpointSlots, "checkpoint slot out of range");
    saved_u_[slot] = u_;
    saved_p_[slot] = p_;
    mip_.save(slot);
}

template <param::RotationParameterization P>
void DisplacementStatics<P>::restore_state(int slot) {
    ROTBEAM_VERIFY(slot >= 0 && slot < kCheckpointSlots, "checkpoint slot out of range");
    u_ = saved_u_[slot];
    p_ = saved_p_[slot];
    mip_.restore(slot);
}

template <param::RotationParameterization P>
PointState DisplacementStatics<P>::point_state(int point_index) const {
    ROTBEAM_VERIFY(point_index >= 0 && point_index < static_cast<int>(mesh_.point_node.size()) &&
                       mesh_.point_node[point_index] >= 0,
                   "point_state: the point is not a mesh node");
    const int node = mesh_.point_node[point_index];
    PointState s;
    s.displacement = u_[node];
    s.rotation = P::matrix(p_[node]);
    return s;
}

template <param::RotationParameterization P>
double DisplacementStatics<P>::max_rotation_angle() const {
    double m = 0.0;
    for (const Params& p : p_) m = std::max(m, P::angle(p));
    return m;
}

template <param::RotationParameterization P>
std::string DisplacementStatics<P>::describe_state() const {
    std::ostringstream s;
    const double phi = max_rotation_angle();
    // The angle continued along the beam (a closed roll-up: 2π), not a node's parameter angle (π
    // after a rescale).
    s << "largest nodal rotation " << largest_continued_angle(model_, rotation_stations())
      << " rad (" << P::kName << ")";
    // With `direct` interpolation the nodal parameters are interpolated as they
    // are, so rescaling one node (WM: complementary parameters; rotation vector: −2π) would put
    // it in another chart than its neighbours. It is not done; say so where it would have been.
    if constexpr (P::kSize == 3) {
        if (rescale_refused_ && phi > kPi) {
            s << "; nodes past pi were not rescaled: with direct interpolation a rescale would "
                 "split the chart of their elements (singular angle "
              << P::singular_angle() << " rad; relative interpolation rescales)";
        }
    }
    return s.str();
}

// Additive update: J_p = J_ψ · blockdiag(H_s(p_i)) on each node's rotation columns.
template <param::RotationParameterization P>
void DisplacementStatics<P>::apply_parameter_tangent(SparseMatrix& J) const {
    if constexpr (P::kSize == 3) {
        right_multiply_rotation_columns(J, mesh_,
                                        [&](size_t i) { return P::spatial_tangent(p_[i]); });
    } else {
        (void)J;
    }
}

}  // namespace rotbeam::form
