// Member definitions of MixedDynamics<P>; included only by mixed_dynamics.cpp, which instantiates
// the template for every three-parameter parameterization.
#pragma once

#include <algorithm>
#include <sstream>

#include "core/errors.hpp"
#include "formulations/mixed/mixed_dynamic_common.hpp"
#include "formulations/mixed/mixed_dynamics.hpp"
#include "formulations/mixed/mixed_load_fields.hpp"

namespace rotbeam::form {

namespace detail {

template <class Derived>
void add_block(SparseMatrix& J, int r0, int c0, const Eigen::MatrixBase<Derived>& b) {
    for (Eigen::Index j = 0; j < b.cols(); ++j) {
        for (Eigen::Index i = 0; i < b.rows(); ++i) {
            J.coeffRef(r0 + static_cast<int>(i), c0 + static_cast<int>(j)) += b(i, j);
        }
    }
}

inline void reset_to_pattern(const SparseMatrix& pattern, SparseMatrix& J) {
    if (J.rows() != pattern.rows() || J.nonZeros() != pattern.nonZeros()) J = pattern;
    std::fill(J.valuePtr(), J.valuePtr() + J.nonZeros(), 0.0);
}

}  // namespace detail

template <param::RotationParameterization P>
MixedDynamics<P>::MixedDynamics(const Model& model, double time_scale, double load_time_floor)
    : model_(model),
      layout_(build_mixed_layout(without_distributed_loads(model))),
      load_time_floor_(load_time_floor) {
    static_assert(P::kSize == 3, "the quaternion has MixedQuaternionDynamics");
    refuse_mixed_damping(model);
    numbering_.nodes = static_cast<int>(layout_.nodes.size());
    numbering_.elements = layout_.element_count();
    numbering_.rotation_size = P::kSize;
    // The statics' force scale ignores distributed loads when they were removed: recompute it
    // from the full model so both analyses scale alike.
    layout_.force_scale = build_mixed_layout(model).force_scale;
    layout_.has_follower = model.has_follower_loads();
    const MixedMassInverses masses = mixed_mass_inverses(model_, layout_);
    mass_inverse_ = masses.inverse;
    const double mass_scale = masses.mass_scale, inertia_scale = masses.inertia_scale;
    pattern_ = mixed_dynamic_pattern(layout_, numbering_);
    const int n = numbering_.size();
    differential_ = VecX::Zero(n);
    VecX static_rows, static_increments;
    mixed_scales(layout_, static_rows, static_increments);
    residual_scale_ = VecX::Zero(n);
    state_scale_ = VecX::Zero(n);
    const int nodes6 = 6 * numbering_.nodes;
    residual_scale_.head(nodes6) = static_rows.head(nodes6);
    state_scale_.head(nodes6) = static_increments.head(nodes6);
    const double Ls = layout_.length_scale;
    const double Vs = Ls / (time_scale > 0.0 ? time_scale : 1.0);
    for (int e = 0; e < numbering_.elements; ++e) {
        const int o = numbering_.element_offset(e);
        const int os = nodes6 + 12 * e;
        residual_scale_.segment<12>(o) = static_rows.segment<12>(os);
        state_scale_.segment<12>(o) = static_increments.segment<12>(os);
        residual_scale_.segment<3>(o + numbering_.P()).setConstant(Vs);       // f_P: velocity
        residual_scale_.segment<3>(o + numbering_.H()).setConstant(Vs / Ls);  // f_H: ang. vel.
        state_scale_.segment<3>(o + numbering_.P()).setConstant(mass_scale * Vs);
        state_scale_.segment<3>(o + numbering_.H()).setConstant(inertia_scale * Vs / Ls);
        differential_.segment<6>(o).setOnes();                   // u, c
        differential_.segment<6>(o + numbering_.P()).setOnes();  // P, H
    }
    // Newton increments of F and M: negligible when the strain they cause, S δ[F; M] (γ, and κ
    // times the length scale), is below the tolerance. The force scale (the applied load) alone
    // would ask for F to 1e-12 of the load, below F's round-off ε·EA when EA ≫ load (the
    // free-vibration cantilever: EA = 2.1e7 N against 1 N).
    increment_scale_ = state_scale_;
    for (int e = 0; e < numbering_.elements; ++e) {
        const Mat6& S = layout_.elements[static_cast<std::size_t>(e)].S;
        const int o = numbering_.element_offset(e) + numbering_.F();
        for (int i = 0; i < 6; ++i) {
            const double strain_unit = i < 3 ? 1.0 : 1.0 / Ls;  // γ dimensionless, κ per length
            if (S(i, i) > 0.0) {
                increment_scale_[o + i] = std::max(state_scale_[o + i], strain_unit / S(i, i));
            }
        }
        // A supported node's reactions are the adjacent elements' A F, A M: same round-off.
        const MixedElement& el = layout_.elements[static_cast<std::size_t>(e)];
        for (const int node : {el.start_node, el.end_node}) {
            if (!layout_.supported(node)) continue;
            const int on = numbering_.node_offset(node);
            for (int i = 0; i < 6; ++i) {
                const double element_scale =
                    increment_scale_.segment<3>(o + 3 * (i / 3)).maxCoeff();
                increment_scale_[on + i] = std::max(increment_scale_[on + i], element_scale);
            }
        }
    }
}

template <param::RotationParameterization P>
double MixedDynamics<P>::time_value(const TimeFunction& f, double t) const {
    return mixed_time_value(f, t, load_time_floor_);
}

template <param::RotationParameterization P>
void MixedDynamics<P>::node_motion(const VecX& x, double t, int node, Vec3& u_hat,
                                   Vec3& c_hat) const {
    if (!layout_.supported(node)) {
        const int o = numbering_.node_offset(node);
        u_hat = x.segment<3>(o);
        c_hat = x.segment<3>(o + 3);
        return;
    }
    const Constraint& con = model_.constraints[static_cast<std::size_t>(
        layout_.nodes[static_cast<std::size_t>(node)].constraint)];
    if (con.kind == Constraint::Kind::clamped) {
        u_hat.setZero();
        c_hat.setZero();
        return;
    }
    const double s = time_value(con.time, t);  // prescribed motion in time
    u_hat = s * con.displacement;
    c_hat = P::from_rotation_vector(s * con.rotation);
}

template <param::RotationParameterization P>
MixedElement MixedDynamics<P>::loaded_element(int e, double t) const {
    return mixed_loaded_element(model_, layout_.elements[static_cast<std::size_t>(e)], t,
                                load_time_floor_);
}

template <param::RotationParameterization P>
void MixedDynamics<P>::evaluate(double t, const VecX& x, const VecX& xdot, VecX& residual,
                                SparseMatrix* J_x, SparseMatrix* J_xdot) {
    ROTBEAM_VERIFY(x.size() == size() && xdot.size() == size(), "state size mismatch");
    residual.setZero(size());
    if (J_x != nullptr) detail::reset_to_pattern(pattern_, *J_x);
    if (J_xdot != nullptr) detail::reset_to_pattern(pattern_, *J_xdot);
    if (J_x != nullptr || J_xdot != nullptr) ++counters_.jacobian_evaluations;
    ++counters_.residual_evaluations;
    for (int e = 0; e < numbering_.elements; ++e) {
        assemble_element(e, t, x, xdot, residual, J_x, J_xdot);
    }
    add_point_loads(t, x, residual, J_x);
    // The follower point loads' stiffness blocks add_point_loads assembled (free nodes only).
    if (J_x != nullptr) {
        for (const PointLoad& load : model_.point_loads) {
            if (load.frame == LoadFrame::follower && !layout_.supported(load.point))
                ++counters_.follower_stiffness;
        }
    }
}

template <param::RotationParameterization P>
void MixedDynamics<P>::assemble_element(int e, double t, const VecX& x, const VecX& xdot,
                                        VecX& residual, SparseMatrix* J_x, SparseMatrix* J_xdot) {
    const MixedDynamicNumbering& nb = numbering_;
    const MixedElement el = loaded_element(e, t);
    const int o = nb.element_offset(e);
    MixedElementState s;
    s.u = x.segment<3>(o + nb.u());
    s.c = x.segment<3>(o + nb.c());
    s.F = x.segment<3>(o + nb.F());
    s.M = x.segment<3>(o + nb.M());
    MixedElementRates<> rate;
    rate.u_dot = xdot.segment<3>(o + nb.u());
    rate.c_dot = xdot.segment<3>(o + nb.c());
    rate.P_dot = xdot.segment<3>(o + nb.P());
    rate.H_dot = xdot.segment<3>(o + nb.H());
    const bool jac = J_x != nullptr || J_xdot != nullptr;
    MixedElementResult& r = static_result_;
    MixedInertiaResult<>& q = inertia_result_;
    mixed_element_statics<P>(el, s, 1.0, jac, r);  // Eqs. 45–48, static part
    mixed_element_inertia<P>(el, mass_inverse_[static_cast<std::size_t>(e)], s.c,
                             x.segment<3>(o + nb.P()), x.segment<3>(o + nb.H()), rate, jac, q);
    ++counters_.elastic_terms;
    ++counters_.inertial_terms;
    const bool follower = el.f_follower.norm() + el.m_follower.norm() > 0.0;
    if (follower || el.f_dead.norm() + el.m_dead.norm() > 0.0) ++counters_.distributed_load_terms;
    if (follower) ++counters_.follower_stiffness;
    const int a = nb.node_offset(el.start_node);
    const int b = nb.node_offset(el.end_node);
    residual.segment<3>(a) += r.fu_minus + q.fu;
    residual.segment<3>(a + 3) += r.fpsi_minus + q.fpsi;
    residual.segment<3>(b) += r.fu_plus + q.fu;
    residual.segment<3>(b + 3) += r.fpsi_plus + q.fpsi;
    // Load fields (manufactured motions): dead, so no Jacobian term.
    counters_.distributed_load_terms += add_mixed_load_fields(
        model_.load_fields, el, 1.0, mixed_load_field_rule(), a, b, residual, t);
    Vec3 ua, ca, ub, cb;
    node_motion(x, t, el.start_node, ua, ca);
    node_motion(x, t, el.end_node, ub, cb);
    residual.segment<12>(o) = r.kinematic;  // Eqs. 47–48 with the node terms (33–34, 37–38)
    residual.segment<3>(o) -= ua;
    residual.segment<3>(o + 3) -= ca;
    residual.segment<3>(o + 6) += ub;
    residual.segment<3>(o + 9) += cb;
    residual.segment<3>(o + nb.P()) = q.fP;  // Eq. 49
    residual.segment<3>(o + nb.H()) = q.fH;  // Eq. 50
    if (J_x != nullptr) {
        SparseMatrix& J = *J_x;
        for (const int node : {a, b}) {
            detail::add_block(J, node, o + nb.c(), node == a ? r.J_minus : r.J_plus);
            detail::add_block(J, node, o + nb.c(), q.J_x.block<6, 3>(0, 0));
            detail::add_block(J, node, o + nb.P(), q.J_x.block<6, 6>(0, 3));
        }
        detail::add_block(J, o, o, r.J_kinematic);
        if (!layout_.supported(el.start_node)) detail::add_block(J, o, a, -Mat6::Identity());
        if (!layout_.supported(el.end_node)) detail::add_block(J, o + 6, b, Mat6::Identity());
        detail::add_block(J, o + nb.P(), o + nb.c(), q.J_x.block<6, 3>(6, 0));
        detail::add_block(J, o + nb.P(), o + nb.P(), q.J_x.block<6, 6>(6, 3));
    }
    if (J_xdot != nullptr) {
        SparseMatrix& K = *J_xdot;
        for (const int node : {a, b}) {
            detail::add_block(K, node, o + nb.c(), q.J_xdot.block<6, 3>(0, 3));
            detail::add_block(K, node, o + nb.P(), q.J_xdot.block<6, 6>(0, 6));
        }
        detail::add_block(K, o + nb.P(), o + nb.u(), q.J_xdot.block<6, 6>(6, 0));
    }
}

// Applied point loads with their time functions (Eqs. 31–32, 35–36) and the reactions of
// supported nodes, as in the statics.
template <param::RotationParameterization P>
void MixedDynamics<P>::add_point_loads(double t, const VecX& x, VecX& residual,
                                       SparseMatrix* J_x) const {
    for (const PointLoad& load : model_.point_loads) {
        const int o = numbering_.node_offset(load.point);
        const double s = time_value(load.time, t);
        Vec3 u_hat, c_hat;
        node_motion(x, t, load.point, u_hat, c_hat);
        const Mat3 R = load.frame == LoadFrame::follower ? P::matrix(c_hat) : Mat3::Identity();
        residual.segment<3>(o) -= s * (R * load.force);
        residual.segment<3>(o + 3) -= s * (R * load.moment);
        if (J_x == nullptr || load.frame == LoadFrame::dead || layout_.supported(load.point)) {
            continue;
        }
        // Follower: ∂(−R f0)/∂ĉ = R f̃0 H_m(ĉ).
        const Mat3 H = P::material_tangent(c_hat);
        detail::add_block(*J_x, o, o + 3, s * R * so3::skew(load.force) * H);
        detail::add_block(*J_x, o + 3, o + 3, s * R * so3::skew(load.moment) * H);
    }
    for (int n = 0; n < numbering_.nodes; ++n) {
        if (!layout_.supported(n)) continue;
        const int o = numbering_.node_offset(n);
        residual.segment<6>(o) -= x.segment<6>(o);  // − (reaction force, moment)
        if (J_x != nullptr) detail::add_block(*J_x, o, o, -Mat6::Identity());
    }
}

template <param::RotationParameterization P>
VecX MixedDynamics<P>::from_static_state(const VecX& static_state) const {
    ROTBEAM_VERIFY(static_state.size() == layout_.size(), "static state size mismatch");
    VecX x = VecX::Zero(size());
    const int nodes6 = 6 * numbering_.nodes;
    x.head(nodes6) = static_state.head(nodes6);
    for (int e = 0; e < numbering_.elements; ++e) {
        x.segment<12>(numbering_.element_offset(e)) = static_state.segment<12>(nodes6 + 12 * e);
    }
    return x;
}

template <param::RotationParameterization P>
void MixedDynamics<P>::set_translational_momenta(VecX& x, const Vec3& v) const {
    for (int e = 0; e < numbering_.elements; ++e) {
        const MixedElement& el = layout_.elements[static_cast<std::size_t>(e)];
        const int o = numbering_.element_offset(e);
        const Mat3 A = P::matrix(x.segment<3>(o + numbering_.c())) * el.Cab;
        const Mat6 I = mass_inverse_[static_cast<std::size_t>(e)].inverse();
        const Vec6 momenta = I * (Vec6() << A.transpose() * v, Vec3::Zero()).finished();
        x.segment<6>(o + numbering_.P()) = momenta;
    }
}

template <param::RotationParameterization P>
PointState MixedDynamics<P>::point_state(const VecX& x, double t, int point_index) const {
    ROTBEAM_VERIFY(point_index >= 0 && point_index < static_cast<int>(model_.points.size()),
                   "point index out of range");
    Vec3 u_hat, c_hat;
    node_motion(x, t, point_index, u_hat, c_hat);
    PointState s;
    s.displacement = u_hat;
    s.rotation = P::matrix(c_hat);
    return s;
}

template <param::RotationParameterization P>
std::vector<StaticProblem::RotationStation> MixedDynamics<P>::rotation_stations(const VecX& x,
                                                                                double t) const {
    std::vector<StaticProblem::RotationStation> out;
    Vec3 u_hat, c_hat;
    for (int e = 0; e < layout_.element_count(); ++e) {
        const MixedElement& el = layout_.elements[static_cast<std::size_t>(e)];
        if (out.empty() || out.back().member != el.member) {
            node_motion(x, t, el.start_node, u_hat, c_hat);
            out.push_back({el.member, true, P::matrix(c_hat)});
        }
        const int o = numbering_.element_offset(e);
        const Vec6 strain = el.S * x.segment<6>(o + numbering_.F());
        const Vec3 kappa = strain.tail<3>();
        out.push_back({el.member, false, P::matrix(x.segment<3>(o + numbering_.c())),
                       el.length * (el.Cab * kappa)});
        node_motion(x, t, el.end_node, u_hat, c_hat);
        out.push_back({el.member, true, P::matrix(c_hat)});
    }
    return out;
}

template <param::RotationParameterization P>
double MixedDynamics<P>::max_rotation_angle(const VecX& x) const {
    double angle = 0.0;
    for (int e = 0; e < numbering_.elements; ++e) {
        angle = std::max(angle, P::angle(x.segment<3>(numbering_.element_offset(e) + 3)));
    }
    return angle;
}

template <param::RotationParameterization P>
std::string MixedDynamics<P>::describe_state(const VecX& x) const {
    std::ostringstream s;
    s << "mixed/" << P::kName << ", largest element rotation " << max_rotation_angle(x) << " rad";
    return s.str();
}

}  // namespace rotbeam::form
