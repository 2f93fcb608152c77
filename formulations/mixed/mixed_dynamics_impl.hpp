// Member definitions of MixedDynamics<P>; included only by mixed_dynamics.cpp, which instantiates
// the template for every parameterization.
#pragma once

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/errors.hpp"
#include "core/turning_frame_loads.hpp"
#include "formulations/mixed/mixed_dynamic_common.hpp"
#include "formulations/mixed/mixed_dynamics.hpp"
#include "formulations/mixed/mixed_load_fields.hpp"
#include "formulations/mixed/mixed_support_rotation.hpp"

namespace rotbeam::form {

namespace detail {

inline void reset_to_pattern(const SparseMatrix& pattern, SparseMatrix& J) {
    if (J.rows() != pattern.rows() || J.nonZeros() != pattern.nonZeros()) J = pattern;
    std::fill(J.valuePtr(), J.valuePtr() + J.nonZeros(), 0.0);
}

}  // namespace detail

template <param::RotationParameterization P>
MixedDynamics<P>::MixedDynamics(const Model& model, double time_scale, double load_time_floor)
    : model_(model),
      layout_(build_mixed_layout(without_distributed_loads(model))),
      numbering_(number_mixed_unknowns(layout_, K, kConstraintRows, true, true)),
      load_time_floor_(load_time_floor) {
    if (model.rotating_frame.active()) {
        refuse_dead_loads_with_turning_root(model);
        spinning_ = true;
        omega_frame_ = model.rotating_frame.angular_velocity;
        center_ = model.rotating_frame.center;
    }
    damping_ = mixed_damping_sections(model, layout_);
    // The statics' force scale ignores distributed loads when they were removed: recompute it
    // from the full model so both analyses scale alike.
    layout_.force_scale = build_mixed_layout(model).force_scale;
    layout_.has_follower = model.has_follower_loads();
    const MixedMassInverses masses = mixed_mass_inverses(model_, layout_);
    mass_inverse_ = masses.inverse;
    pattern_ = mixed_pattern(layout_, numbering_);
    differential_ = VecX::Zero(size());
    for (int e = 0; e < element_count(); ++e) {
        const int c = element_column(e);
        differential_.segment<3 + K>(c + numbering_.u()).setOnes();  // u, c (all K components)
        differential_.segment<6>(c + numbering_.P()).setOnes();      // P, H
    }
    configuration_ = differential_;
    for (int e = 0; e < element_count(); ++e) {
        configuration_.segment<6>(element_column(e) + numbering_.P()).setZero();
    }
    ic_differential_ = differential_;
    for (int e = 0; e < element_count(); ++e) {
        const Vec6& mu = damping_[static_cast<std::size_t>(e)].mu;
        for (int i = 0; i < 6; ++i) {
            if (mu[i] != 0.0) differential_[element_column(e) + numbering_.F() + i] = 1.0;
        }
    }
    build_scales(time_scale, masses.mass_scale, masses.inertia_scale);
}

// The statics' scales (mixed_scales) for nodes and the kinematic part of elements; the momentum
// rows and unknowns by the velocity scale length / time_scale. Newton increments of F and M:
// negligible when the strain they cause, S δ[F; M] (γ, and κ times the length scale), is below the
// tolerance. The force scale (the applied load) alone would ask for F to 1e-12 of the load, below
// F's round-off ε·EA when EA ≫ load (the free-vibration cantilever: EA = 2.1e7 N against 1 N). A
// supported node's reactions are the adjacent elements' A F, A M: same round-off.
template <param::RotationParameterization P>
void MixedDynamics<P>::build_scales(double time_scale, double mass_scale, double inertia_scale) {
    VecX static_rows, static_increments;
    const MixedNumbering statics =
        number_mixed_unknowns(layout_, K, kConstraintRows, false, numbering_.free_norm);
    mixed_scales(layout_, statics, static_rows, static_increments);
    residual_scale_ = VecX::Zero(size());
    state_scale_ = VecX::Zero(size());
    const int node_rows = 6 * node_count();
    residual_scale_.head(node_rows) = static_rows.head(node_rows);
    state_scale_.head(numbering_.node_unknowns) = static_increments.head(numbering_.node_unknowns);
    const double Ls = layout_.length_scale;
    const double Vs = Ls / (time_scale > 0.0 ? time_scale : 1.0);
    // An element's rotation parameters at their change per radian at the identity (1 for the
    // three-parameter charts, ½ for the quaternion's half-angle components), so that the time
    // integrators' error tolerances on the configuration (IDA's absolute tolerance, the Radau IIA
    // and trapezoidal error weights) read in radians whatever the parameterization.
    const double per_radian = 1.0 / P::spatial_tangent(P::identity()).colwise().norm().maxCoeff();
    for (int e = 0; e < element_count(); ++e) {
        const int r = element_row(e), c = element_column(e);
        residual_scale_.segment<MixedElementResult<K>::kRows>(r) =
            static_rows.segment<MixedElementResult<K>::kRows>(statics.element_row(e));
        state_scale_.segment<MixedElementResult<K>::kCols>(c) =
            static_increments.segment<MixedElementResult<K>::kCols>(statics.element_column(e));
        state_scale_.segment<K>(c + numbering_.c()) *= per_radian;
        residual_scale_.segment<3>(r + numbering_.fP()).setConstant(Vs);       // velocity
        residual_scale_.segment<3>(r + numbering_.fH()).setConstant(Vs / Ls);  // angular velocity
        state_scale_.segment<3>(c + numbering_.P()).setConstant(mass_scale * Vs);
        state_scale_.segment<3>(c + numbering_.H()).setConstant(inertia_scale * Vs / Ls);
    }
    if (numbering_.free_norm) residual_scale_[size() - 1] = 1.0;  // the constraint row: |q|²
    increment_scale_ = state_scale_;
    for (int e = 0; e < element_count(); ++e) {
        const MixedElement& el = layout_.elements[static_cast<std::size_t>(e)];
        const int o = element_column(e) + numbering_.F();
        for (int i = 0; i < 6; ++i) {
            const double strain_unit = i < 3 ? 1.0 : 1.0 / Ls;  // γ dimensionless, κ per length
            if (el.S(i, i) > 0.0) {
                increment_scale_[o + i] = std::max(state_scale_[o + i], strain_unit / el.S(i, i));
            }
        }
        for (const int node : {el.start_node, el.end_node}) {
            if (!supported(node)) continue;
            const int on = node_column(node);
            for (int i = 0; i < 6; ++i) {
                const double element_scale =
                    increment_scale_.segment<3>(o + 3 * (i / 3)).maxCoeff();
                increment_scale_[on + i] = std::max(increment_scale_[on + i], element_scale);
            }
        }
    }
}

template <param::RotationParameterization P>
VecX MixedDynamics<P>::initial_condition_differential(const VecX& x) const {
    if constexpr (kConstraintRows == 0) {
        return ic_differential_;
    } else {
        VecX d = ic_differential_;
        for (int e = 0; e < element_count(); ++e) {
            const int c = element_column(e) + numbering_.c();
            d[c + param::ParameterConstraint<P>::algebraic_component(x.segment<K>(c))] = 0.0;
        }
        return d;
    }
}

template <param::RotationParameterization P>
void MixedDynamics<P>::complete_initial_rates(const VecX& x, VecX& xdot) const {
    if constexpr (kConstraintRows > 0) {
        for (int e = 0; e < element_count(); ++e) {
            const int c = element_column(e) + numbering_.c();
            xdot.segment<K>(c) -=
                param::ParameterConstraint<P>::radial_part(x.segment<K>(c), xdot.segment<K>(c));
        }
    }
}

// A support's rotation at time t: the identity when clamped, the prescribed rotation otherwise,
// on the sheet reached continuously from the identity (mixed_support_rotation.hpp).
template <param::RotationParameterization P>
typename MixedDynamics<P>::Params MixedDynamics<P>::given_rotation(int node, double t) const {
    const Constraint& con = model_.constraints[static_cast<std::size_t>(
        layout_.nodes[static_cast<std::size_t>(node)].constraint)];
    if (con.kind == Constraint::Kind::clamped) return P::identity();
    return continued_support_rotation<P>(mixed_time_value(con.time, t, load_time_floor_) *
                                         con.rotation);
}

template <param::RotationParameterization P>
void MixedDynamics<P>::node_motion(const VecX& x, double t, int node, Vec3& u_hat,
                                   Params& c_hat) const {
    const int c = node_column(node);
    if (!supported(node)) {
        u_hat = x.segment<3>(c);
        c_hat = x.segment<K>(c + 3);
        return;
    }
    const Constraint& con = model_.constraints[static_cast<std::size_t>(
        layout_.nodes[static_cast<std::size_t>(node)].constraint)];
    u_hat = con.kind == Constraint::Kind::clamped
                ? Vec3::Zero()
                : Vec3(mixed_time_value(con.time, t, load_time_floor_) * con.displacement);
    c_hat = given_rotation(node, t);
    if (numbering_.has_scale(node)) c_hat *= x[c + 6];
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
    for (int e = 0; e < element_count(); ++e) {
        assemble_element(e, t, x, xdot, residual, J_x, J_xdot);
        add_node_terms(e, t, x, residual, J_x);
    }
    add_point_loads(t, x, residual, J_x);
    for (int e = 0; e < element_count(); ++e) {
        if (damping_[static_cast<std::size_t>(e)].active()) {
            add_damping(e, x, xdot, residual, J_x, J_xdot);
        }
    }
    // The follower point loads' stiffness blocks add_point_loads assembled (free nodes only).
    if (J_x != nullptr) {
        for (const PointLoad& load : model_.point_loads) {
            if (load.frame == LoadFrame::follower && !supported(load.point))
                ++counters_.follower_stiffness;
        }
    }
    if constexpr (kConstraintRows > 0) {
        if (numbering_.free_norm) {
            // A free tree: the constraint at node 0 (½(|q̂_0|² − 1) = 0) fixes the norm the Cayley
            // relations carry to every node.
            using Constraint = param::ParameterConstraint<P>;
            const Params q0 = x.segment<K>(node_column(0) + 3);
            residual[size() - 1] = Constraint::residual(q0);
            if (J_x != nullptr) {
                add_mixed_block(*J_x, size() - 1, node_column(0) + 3, Constraint::jacobian(q0));
            }
        }
    }
}

// The statics' element (Eqs. 45–48) plus the momentum terms
// (Eqs. 45–46, 49–50) into the end nodes' equilibrium rows and the element's own rows.
template <param::RotationParameterization P>
void MixedDynamics<P>::assemble_element(int e, double t, const VecX& x, const VecX& xdot,
                                        VecX& residual, SparseMatrix* J_x, SparseMatrix* J_xdot) {
    MixedElement el = mixed_loaded_element(model_, layout_.elements[static_cast<std::size_t>(e)], t,
                                           load_time_floor_);
    // Gravity (the only dead load with a turning frame) is fixed in inertial axes: Q(t)ᵀ g.
    if (spinning_) el.f_dead = frame_rotation(t).transpose() * el.f_dead;
    const int c = element_column(e);
    const int row = element_row(e);
    MixedElementState<K> s;
    s.u = x.segment<3>(c + numbering_.u());
    s.c = x.segment<K>(c + numbering_.c());
    s.F = x.segment<3>(c + numbering_.F());
    s.M = x.segment<3>(c + numbering_.M());
    MixedElementRates<K> rate;
    rate.u_dot = xdot.segment<3>(c + numbering_.u());
    rate.c_dot = xdot.segment<K>(c + numbering_.c());
    rate.P_dot = xdot.segment<3>(c + numbering_.P());
    rate.H_dot = xdot.segment<3>(c + numbering_.H());
    const bool jac = J_x != nullptr || J_xdot != nullptr;
    MixedElementResult<K>& r = static_result_;
    MixedInertiaResult<K>& q = inertia_result_;
    mixed_element_statics<P>(el, s, 1.0, jac, r);  // Eqs. 45–48, static part
    mixed_element_inertia<P>(el, mass_inverse_[static_cast<std::size_t>(e)], s.c,
                             x.segment<3>(c + numbering_.P()), x.segment<3>(c + numbering_.H()),
                             rate, jac, q);
    MixedFrameResult<K>& w = frame_result_;
    if (spinning_) {
        mixed_element_frame_terms<P>(el, omega_frame_, element_position(e, x), s.c,
                                     x.segment<3>(c + numbering_.P()),
                                     x.segment<3>(c + numbering_.H()), jac, w);
        q.fu += w.fu;
        q.fpsi += w.fpsi;
        q.fP += w.fP;
        q.fH += w.fH;
    }
    ++counters_.elastic_terms;
    ++counters_.inertial_terms;
    const bool follower = el.f_follower.norm() + el.m_follower.norm() > 0.0;
    if (follower || el.f_dead.norm() + el.m_dead.norm() > 0.0) ++counters_.distributed_load_terms;
    if (follower) ++counters_.follower_stiffness;
    const int a = 6 * el.start_node;
    const int b = 6 * el.end_node;
    residual.segment<3>(a) += r.fu_minus + q.fu;
    residual.segment<3>(a + 3) += r.fpsi_minus + q.fpsi;
    residual.segment<3>(b) += r.fu_plus + q.fu;
    residual.segment<3>(b + 3) += r.fpsi_plus + q.fpsi;
    // Load fields (manufactured motions): dead, so no Jacobian term.
    counters_.distributed_load_terms += add_mixed_load_fields(
        model_.load_fields, el, 1.0, mixed_load_field_rule(), a, b, residual, t);
    residual.segment<MixedElementResult<K>::kRows>(row) = r.kinematic;
    residual.segment<3>(row + numbering_.fP()) = q.fP;  // Eq. 49
    residual.segment<3>(row + numbering_.fH()) = q.fH;  // Eq. 50
    if (J_x != nullptr) {
        SparseMatrix& J = *J_x;
        for (const int node : {a, b}) {
            add_mixed_block(J, node, c + numbering_.c(), node == a ? r.J_minus : r.J_plus);
            add_mixed_block(J, node, c + numbering_.c(), q.J_x.template block<6, K>(0, 0));
            add_mixed_block(J, node, c + numbering_.P(), q.J_x.template block<6, 6>(0, K));
        }
        add_mixed_block(J, row, c, r.J_kinematic);
        add_mixed_block(J, row + numbering_.fP(), c + numbering_.c(),
                        q.J_x.template block<6, K>(6, 0));
        add_mixed_block(J, row + numbering_.fP(), c + numbering_.P(),
                        q.J_x.template block<6, 6>(6, K));
        if (spinning_) {
            // Columns of w.J_x: u (3), c (K), P, H (6); F, M lie between c and P in X.
            for (const int node : {a, b}) {
                add_mixed_block(J, node, c + numbering_.c(), w.J_x.template block<6, K>(0, 3));
                add_mixed_block(J, node, c + numbering_.P(), w.J_x.template block<6, 6>(0, 3 + K));
            }
            add_mixed_block(J, row + numbering_.fP(), c + numbering_.u(),
                            w.J_x.template block<6, 3 + K>(6, 0));
        }
    }
    if (J_xdot != nullptr) {
        SparseMatrix& Kd = *J_xdot;
        for (const int node : {a, b}) {
            add_mixed_block(Kd, node, c + numbering_.c(), q.J_xdot.template block<6, K>(0, 3));
            add_mixed_block(Kd, node, c + numbering_.P(), q.J_xdot.template block<6, 6>(0, 3 + K));
        }
        // f_P, f_H against u̇, ċ (they hold no Ṗ, Ḣ).
        add_mixed_block(Kd, row + numbering_.fP(), c + numbering_.u(),
                        q.J_xdot.template block<6, 3 + K>(6, 0));
    }
}

// The damping terms of element e (mixed_damping.hpp) into its end nodes' equilibrium rows.
template <param::RotationParameterization P>
void MixedDynamics<P>::add_damping(int e, const VecX& x, const VecX& xdot, VecX& residual,
                                   SparseMatrix* J_x, SparseMatrix* J_xdot) {
    const MixedElement& el = layout_.elements[static_cast<std::size_t>(e)];
    const int c = element_column(e);
    MixedDampingResult<K>& d = damping_result_;
    mixed_element_damping<P>(el, damping_[static_cast<std::size_t>(e)],
                             mass_inverse_[static_cast<std::size_t>(e)],
                             x.segment<K>(c + numbering_.c()), x.segment<6>(c + numbering_.F()),
                             x.segment<6>(c + numbering_.P()), xdot.segment<6>(c + numbering_.F()),
                             omega_frame_, J_x != nullptr || J_xdot != nullptr, d);
    ++counters_.damping_terms;
    const int a = 6 * el.start_node;
    const int b = 6 * el.end_node;
    residual.segment<6>(a) += d.minus;
    residual.segment<6>(b) += d.plus;
    for (const int node : {a, b}) {
        const auto& J = node == a ? d.J_minus : d.J_plus;
        if (J_x != nullptr) {
            add_mixed_block(*J_x, node, c + numbering_.c(), J.template leftCols<K>());
            add_mixed_block(*J_x, node, c + numbering_.F(), J.template middleCols<6>(K));
            add_mixed_block(*J_x, node, c + numbering_.P(), J.template rightCols<6>());
        }
        if (J_xdot != nullptr) {
            add_mixed_block(*J_xdot, node, c + numbering_.F(), node == a ? d.Jd_minus : d.Jd_plus);
        }
    }
}

// f_F^− − û_a, f_M^− − ĉ_a, f_F^+ + û_b, f_M^+ + ĉ_b (Eqs. 33–34, 37–38); a support's ĉ is given
// at time t (× ρ after the first support: ∂/∂ρ = ĉ_given).
template <param::RotationParameterization P>
void MixedDynamics<P>::add_node_terms(int e, double t, const VecX& x, VecX& residual,
                                      SparseMatrix* J_x) const {
    const MixedElement& el = layout_.elements[static_cast<std::size_t>(e)];
    const int ends[2] = {el.start_node, el.end_node};
    for (int side = 0; side < 2; ++side) {
        const double s = side == 0 ? -1.0 : 1.0;
        const int n = ends[side];
        const int r = element_row(e) + (3 + K) * side;
        Vec3 u_hat;
        Params c_hat;
        node_motion(x, t, n, u_hat, c_hat);
        residual.segment<3>(r) += s * u_hat;
        residual.segment<K>(r + 3) += s * c_hat;
        if (J_x == nullptr) continue;
        if (!supported(n)) {
            add_mixed_block(*J_x, r, node_column(n),
                            s * Eigen::Matrix<double, 3 + K, 3 + K>::Identity());
        } else if (numbering_.has_scale(n)) {
            add_mixed_block(*J_x, r + 3, node_column(n) + 6, s * given_rotation(n, t));
        }
    }
}

// Applied point loads with their time functions (Eqs. 31–32, 35–36) and the reactions of the
// supported nodes; a follower load at a free node is R(ĉ) f0, ∂(−R f0)/∂ĉ = R f̃0 H_m(ĉ).
template <param::RotationParameterization P>
void MixedDynamics<P>::add_point_loads(double t, const VecX& x, VecX& residual,
                                       SparseMatrix* J_x) const {
    for (const PointLoad& load : model_.point_loads) {
        const int r = 6 * load.point;
        const double s = mixed_time_value(load.time, t, load_time_floor_);
        Vec3 u_hat;
        Params c_hat;
        node_motion(x, t, load.point, u_hat, c_hat);
        const Mat3 R = load.frame == LoadFrame::follower ? P::matrix(c_hat) : Mat3::Identity();
        residual.segment<3>(r) -= s * (R * load.force);
        residual.segment<3>(r + 3) -= s * (R * load.moment);
        if (J_x == nullptr || load.frame == LoadFrame::dead || supported(load.point)) continue;
        const param::Tangent<K> H = P::material_tangent(c_hat);
        const int c = node_column(load.point) + 3;
        add_mixed_block(*J_x, r, c, s * R * so3::skew(load.force) * H);
        add_mixed_block(*J_x, r + 3, c, s * R * so3::skew(load.moment) * H);
    }
    for (int n = 0; n < node_count(); ++n) {
        if (!supported(n)) continue;
        residual.segment<6>(6 * n) -= x.segment<6>(node_column(n));  // − (reaction force, moment)
        if (J_x != nullptr) add_mixed_block(*J_x, 6 * n, node_column(n), -Mat6::Identity());
    }
}

template <param::RotationParameterization P>
Mat3 MixedDynamics<P>::frame_rotation(double t) const {
    return so3::exp_map(t * omega_frame_);
}

template <param::RotationParameterization P>
Vec3 MixedDynamics<P>::element_position(int e, const VecX& x) const {
    const MixedElement& el = layout_.elements[static_cast<std::size_t>(e)];
    return layout_.nodes[static_cast<std::size_t>(el.start_node)].reference + 0.5 * el.chord +
           x.segment<3>(element_column(e) + numbering_.u()) - center_;
}

template <param::RotationParameterization P>
MixedEnergy MixedDynamics<P>::energy(const VecX& x) const {
    MixedEnergy E;
    for (int e = 0; e < element_count(); ++e) {
        const MixedElement& el = layout_.elements[static_cast<std::size_t>(e)];
        const int c = element_column(e);
        const Vec6 momenta = x.segment<6>(c + numbering_.P());
        const Vec6 forces = x.segment<6>(c + numbering_.F());
        const Vec6 velocities = mass_inverse_[static_cast<std::size_t>(e)] * momenta;
        E.kinetic += 0.5 * el.length * velocities.dot(momenta);
        E.strain += 0.5 * el.length * forces.dot(el.S * forces);
        const Mat3 A = P::matrix(x.segment<K>(c + numbering_.c())) * el.Cab;
        E.angular_momentum += el.length * (element_position(e, x).cross(A * momenta.head<3>()) +
                                           A * momenta.tail<3>());
    }
    return E;
}

template <param::RotationParameterization P>
VecX MixedDynamics<P>::from_static_state(const VecX& static_state) const {
    const MixedNumbering statics =
        number_mixed_unknowns(layout_, K, kConstraintRows, false, numbering_.free_norm);
    ROTBEAM_VERIFY(static_state.size() == statics.size(), "static state size mismatch");
    VecX x = VecX::Zero(size());
    x.head(numbering_.node_unknowns) = static_state.head(numbering_.node_unknowns);
    for (int e = 0; e < element_count(); ++e) {
        x.segment<MixedElementResult<K>::kCols>(element_column(e)) =
            static_state.segment<MixedElementResult<K>::kCols>(statics.element_column(e));
    }
    if (spinning_) set_translational_momenta(x, Vec3::Zero());
    return x;
}

template <param::RotationParameterization P>
void MixedDynamics<P>::set_translational_momenta(VecX& x, const Vec3& v) const {
    for (int e = 0; e < element_count(); ++e) {
        const MixedElement& el = layout_.elements[static_cast<std::size_t>(e)];
        const int c = element_column(e);
        const Mat3 A = P::matrix(x.segment<K>(c + numbering_.c())) * el.Cab;
        const Mat6 I = mass_inverse_[static_cast<std::size_t>(e)].inverse();
        const Vec3 v_abs = v + omega_frame_.cross(element_position(e, x));
        x.segment<6>(c + numbering_.P()) =
            I * (Vec6() << A.transpose() * v_abs, A.transpose() * omega_frame_).finished();
    }
}

template <param::RotationParameterization P>
PointState MixedDynamics<P>::point_state(const VecX& x, double t, int point_index) const {
    ROTBEAM_VERIFY(point_index >= 0 && point_index < static_cast<int>(model_.points.size()),
                   "point index out of range");
    Vec3 u_hat;
    Params c_hat;
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
    Vec3 u_hat;
    Params c_hat;
    for (int e = 0; e < element_count(); ++e) {
        const MixedElement& el = layout_.elements[static_cast<std::size_t>(e)];
        if (out.empty() || out.back().member != el.member) {
            node_motion(x, t, el.start_node, u_hat, c_hat);
            out.push_back({el.member, true, P::matrix(c_hat)});
        }
        const int o = element_column(e);
        const Vec6 strain = el.S * x.segment<6>(o + numbering_.F());
        const Vec3 kappa = strain.tail<3>();
        out.push_back({el.member, false, P::matrix(x.segment<K>(o + numbering_.c())),
                       el.length * (el.Cab * kappa)});
        node_motion(x, t, el.end_node, u_hat, c_hat);
        out.push_back({el.member, true, P::matrix(c_hat)});
    }
    return out;
}

template <param::RotationParameterization P>
std::vector<StaticState::NodeFrame> MixedDynamics<P>::node_frames(const VecX& x, double t) const {
    return mixed_node_frames(layout_, element_count(), [&](int node, Vec3& u_hat, Mat3& R) {
        Params c_hat;
        node_motion(x, t, node, u_hat, c_hat);
        R = P::matrix(c_hat);
    });
}

template <param::RotationParameterization P>
std::vector<SectionResultants> MixedDynamics<P>::section_resultants(const VecX& x) const {
    return mixed_section_resultants(layout_, element_count(),
                                    [&](int e, Mat3& R, Vec3& F, Vec3& M) {
                                        const int o = element_column(e);
                                        R = P::matrix(x.segment<K>(o + numbering_.c()));
                                        F = x.segment<3>(o + numbering_.F());
                                        M = x.segment<3>(o + numbering_.M());
                                    });
}

template <param::RotationParameterization P>
double MixedDynamics<P>::max_rotation_angle(const VecX& x) const {
    double angle = 0.0;
    for (int e = 0; e < element_count(); ++e) {
        angle = std::max(angle, P::angle(x.segment<K>(element_column(e) + numbering_.c())));
    }
    return angle;
}

template <param::RotationParameterization P>
QuaternionNormDrift MixedDynamics<P>::norm_drift(const VecX& x, double t) const
    requires(param::ParameterConstraint<P>::kRows > 0) {
    QuaternionNormDrift d;
    for (int n = 0; n < node_count(); ++n) {
        Vec3 u_hat;
        Params c_hat;
        node_motion(x, t, n, u_hat, c_hat);
        d.nodes = std::max(d.nodes, std::abs(c_hat.norm() - 1.0));
    }
    for (int e = 0; e < element_count(); ++e) {
        const double norm = x.segment<K>(element_column(e) + numbering_.c()).norm();
        d.elements = std::max(d.elements, std::abs(norm - 1.0));
    }
    return d;
}

template <param::RotationParameterization P>
std::string MixedDynamics<P>::describe_state(const VecX& x) const {
    std::ostringstream s;
    s << "mixed/" << P::kName << ", largest element rotation " << max_rotation_angle(x) << " rad";
    return s.str();
}

}  // namespace rotbeam::form
