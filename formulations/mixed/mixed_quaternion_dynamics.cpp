// Member definitions of MixedQuaternionDynamics<P>, its pattern, and the explicit instantiation
// for the quaternion (the only four-parameter parameterization).
#include "formulations/mixed/mixed_quaternion_dynamics.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/errors.hpp"
#include "formulations/mixed/mixed_dynamic_common.hpp"
#include "formulations/mixed/mixed_load_fields.hpp"
#include "parameterizations/quaternion.hpp"

namespace rotbeam::form {

namespace {

using Block = MixedQuaternionDynamicBlock;

template <class Derived>
void add_block(SparseMatrix& J, int r0, int c0, const Eigen::MatrixBase<Derived>& b) {
    for (Eigen::Index j = 0; j < b.cols(); ++j) {
        for (Eigen::Index i = 0; i < b.rows(); ++i) {
            J.coeffRef(r0 + static_cast<int>(i), c0 + static_cast<int>(j)) += b(i, j);
        }
    }
}

void reset_to_pattern(const SparseMatrix& pattern, SparseMatrix& J) {
    if (J.rows() != pattern.rows() || J.nonZeros() != pattern.nonZeros()) J = pattern;
    std::fill(J.valuePtr(), J.valuePtr() + J.nonZeros(), 0.0);
}

int dynamic_size(const MixedQuaternionLayout& layout) {
    return layout.node_unknowns + Block::kUnknowns * layout.base.element_count();
}

}  // namespace

SparseMatrix mixed_quaternion_dynamic_pattern(const MixedQuaternionLayout& layout) {
    using Triplet = Eigen::Triplet<double, int>;
    std::vector<Triplet> t;
    auto block = [&t](int r0, int c0, int rows, int cols) {
        for (int j = 0; j < cols; ++j) {
            for (int i = 0; i < rows; ++i) t.emplace_back(r0 + i, c0 + j, 0.0);
        }
    };
    const int nodes = static_cast<int>(layout.base.nodes.size());
    for (int n = 0; n < nodes; ++n) {
        // Reactions (supported) or the follower point-load stiffness against q̂ (free).
        block(6 * n, layout.node_column(n), 6, layout.supported(n) ? 6 : 7);
    }
    for (int e = 0; e < layout.base.element_count(); ++e) {
        const MixedElement& el = layout.base.elements[static_cast<std::size_t>(e)];
        const int r = 6 * nodes + Block::kRows * e;
        const int c = layout.node_unknowns + Block::kUnknowns * e;
        // f_u, f_ψ against q, F, M, P, H and their rates.
        block(6 * el.start_node, c + Block::q, 6, Block::kUnknowns - Block::q);
        block(6 * el.end_node, c + Block::q, 6, Block::kUnknowns - Block::q);
        block(r, c, Block::kRows, Block::kUnknowns);  // kinematic and momentum rows
        const int ends[2] = {el.start_node, el.end_node};
        for (int side = 0; side < 2; ++side) {
            const int n = ends[side];
            const int rn = r + 7 * side;
            if (!layout.supported(n)) block(rn, layout.node_column(n), 7, 7);  // ∓û, ∓q̂
            if (layout.has_scale(n)) block(rn + 3, layout.node_column(n) + 6, 4, 1);  // ∓ρ q_given
        }
    }
    const int n = dynamic_size(layout);
    if (layout.free_norm) block(n - 1, layout.node_column(0) + 3, 1, 4);  // the norm row, q̂_0
    SparseMatrix J(n, n);
    J.setFromTriplets(t.begin(), t.end());  // duplicates are summed (all zero)
    J.makeCompressed();
    return J;
}

template <param::RotationParameterization P>
requires(P::kSize == 4) MixedQuaternionDynamics<P>::MixedQuaternionDynamics(const Model& model,
                                                                            double time_scale,
                                                                            double load_time_floor)
    : model_(model),
      layout_(build_mixed_quaternion_layout(without_distributed_loads(model), true)),
      load_time_floor_(load_time_floor) {
    refuse_mixed_damping(model);
    size_ = dynamic_size(layout_);
    // The force scale with the distributed loads (removed from the layout), as MixedDynamics.
    layout_.base.force_scale = build_mixed_layout(model).force_scale;
    layout_.base.has_follower = model.has_follower_loads();
    const MixedMassInverses masses = mixed_mass_inverses(model_, layout_.base);
    mass_inverse_ = masses.inverse;
    pattern_ = mixed_quaternion_dynamic_pattern(layout_);
    differential_ = VecX::Zero(size_);
    for (int e = 0; e < element_count(); ++e) {
        const int c = element_column(e);
        differential_.segment<3 + K>(c + Block::u).setOnes();  // u, q (all four components)
        differential_.segment<6>(c + Block::P).setOnes();      // P, H
    }
    build_scales(time_scale, masses.mass_scale, masses.inertia_scale);
}

// The statics' scales (mixed_quaternion_scales) for nodes and the kinematic part of elements; the
// momentum rows and unknowns as MixedDynamics (velocity length / time_scale); F, M increments and
// supported reactions raised to the resolution of the strain they cause.
template <param::RotationParameterization P>
requires(P::kSize == 4) void MixedQuaternionDynamics<P>::build_scales(double time_scale,
                                                                      double mass_scale,
                                                                      double inertia_scale) {
    VecX static_rows, static_increments;
    mixed_quaternion_scales(layout_, static_rows, static_increments);
    residual_scale_ = VecX::Zero(size_);
    state_scale_ = VecX::Zero(size_);
    const int node_rows = 6 * node_count();
    residual_scale_.head(node_rows) = static_rows.head(node_rows);
    state_scale_.head(layout_.node_unknowns) = static_increments.head(layout_.node_unknowns);
    const double Ls = layout_.base.length_scale;
    const double Vs = Ls / (time_scale > 0.0 ? time_scale : 1.0);
    for (int e = 0; e < element_count(); ++e) {
        const int r = element_row(e), c = element_column(e);
        residual_scale_.segment<Block::kinematic_rows>(r) =
            static_rows.segment<Block::kinematic_rows>(layout_.element_row(e));
        state_scale_.segment<Block::P>(c) =
            static_increments.segment<Block::P>(layout_.element_column(e));
        residual_scale_.segment<3>(r + Block::fP).setConstant(Vs);       // velocity
        residual_scale_.segment<3>(r + Block::fH).setConstant(Vs / Ls);  // angular velocity
        state_scale_.segment<3>(c + Block::P).setConstant(mass_scale * Vs);
        state_scale_.segment<3>(c + Block::H).setConstant(inertia_scale * Vs / Ls);
    }
    if (layout_.free_norm) residual_scale_[size_ - 1] = 1.0;  // the norm row, dimensionless
    increment_scale_ = state_scale_;
    for (int e = 0; e < element_count(); ++e) {
        const MixedElement& el = layout_.base.elements[static_cast<std::size_t>(e)];
        const int o = element_column(e) + Block::F;
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
requires(P::kSize ==
         4) VecX MixedQuaternionDynamics<P>::initial_condition_differential(const VecX& x)
const {
    VecX d = differential_;
    for (int e = 0; e < element_count(); ++e) {
        const int c = element_column(e) + Block::q;
        Eigen::Index k = 0;
        x.segment<K>(c).cwiseAbs().maxCoeff(&k);
        d[c + static_cast<int>(k)] = 0.0;
    }
    return d;
}

template <param::RotationParameterization P>
requires(P::kSize == 4) void MixedQuaternionDynamics<P>::complete_initial_rates(const VecX& x,
                                                                                VecX& xdot) const {
    for (int e = 0; e < element_count(); ++e) {
        const int c = element_column(e) + Block::q;
        const Params q = x.segment<K>(c);
        xdot.segment<K>(c) -= q * (q.dot(xdot.segment<K>(c)) / q.squaredNorm());
    }
}

// A support's quaternion at time t: the identity when clamped, the prescribed rotation otherwise.
template <param::RotationParameterization P>
requires(P::kSize == 4) typename MixedQuaternionDynamics<P>::Params
    MixedQuaternionDynamics<P>::given_rotation(int node, double t) const {
    const Constraint& con = model_.constraints[static_cast<std::size_t>(
        layout_.base.nodes[static_cast<std::size_t>(node)].constraint)];
    if (con.kind == Constraint::Kind::clamped) return P::identity();
    return P::from_rotation_vector(mixed_time_value(con.time, t, load_time_floor_) * con.rotation);
}

template <param::RotationParameterization P>
requires(P::kSize == 4) void MixedQuaternionDynamics<P>::node_motion(const VecX& x, double t,
                                                                     int node, Vec3& u_hat,
                                                                     Params& q_hat) const {
    const int c = node_column(node);
    if (!supported(node)) {
        u_hat = x.segment<3>(c);
        q_hat = x.segment<K>(c + 3);
        return;
    }
    const Constraint& con = model_.constraints[static_cast<std::size_t>(
        layout_.base.nodes[static_cast<std::size_t>(node)].constraint)];
    u_hat = con.kind == Constraint::Kind::clamped
                ? Vec3::Zero()
                : Vec3(mixed_time_value(con.time, t, load_time_floor_) * con.displacement);
    q_hat = given_rotation(node, t);
    if (layout_.has_scale(node)) q_hat *= x[c + 6];
}

template <param::RotationParameterization P>
requires(P::kSize == 4) void MixedQuaternionDynamics<P>::evaluate(double t, const VecX& x,
                                                                  const VecX& xdot, VecX& residual,
                                                                  SparseMatrix* J_x,
                                                                  SparseMatrix* J_xdot) {
    ROTBEAM_VERIFY(x.size() == size_ && xdot.size() == size_, "state size mismatch");
    residual.setZero(size_);
    if (J_x != nullptr) reset_to_pattern(pattern_, *J_x);
    if (J_xdot != nullptr) reset_to_pattern(pattern_, *J_xdot);
    if (J_x != nullptr || J_xdot != nullptr) ++counters_.jacobian_evaluations;
    ++counters_.residual_evaluations;
    for (int e = 0; e < element_count(); ++e) {
        assemble_element(e, t, x, xdot, residual, J_x, J_xdot);
        add_node_terms(e, t, x, residual, J_x);
    }
    add_point_loads(t, x, residual, J_x);
    // The follower point loads' stiffness blocks add_point_loads assembled (free nodes only).
    if (J_x != nullptr) {
        for (const PointLoad& load : model_.point_loads) {
            if (load.frame == LoadFrame::follower && !supported(load.point))
                ++counters_.follower_stiffness;
        }
    }
    if (layout_.free_norm) {
        // A free tree: ½(|q̂_0|² − 1) = 0 fixes the norm the Cayley relations carry to every node.
        const Params q0 = x.segment<K>(node_column(0) + 3);
        residual[size_ - 1] = 0.5 * (q0.squaredNorm() - 1.0);
        if (J_x != nullptr) add_block(*J_x, size_ - 1, node_column(0) + 3, q0.transpose());
    }
}

// The statics' element (Eqs. 45–48, Eq. 48 in four components) plus the momentum terms
// (Eqs. 45–46, 49–50) into the end nodes' equilibrium rows and the element's own rows.
template <param::RotationParameterization P>
requires(P::kSize ==
         4) void MixedQuaternionDynamics<P>::assemble_element(int e, double t, const VecX& x,
                                                              const VecX& xdot, VecX& residual,
                                                              SparseMatrix* J_x,
                                                              SparseMatrix* J_xdot) {
    const MixedElement el = mixed_loaded_element(
        model_, layout_.base.elements[static_cast<std::size_t>(e)], t, load_time_floor_);
    const int c = element_column(e);
    const int row = element_row(e);
    MixedHomogeneousState<K> s;
    s.u = x.segment<3>(c + Block::u);
    s.q = x.segment<K>(c + Block::q);
    s.F = x.segment<3>(c + Block::F);
    s.M = x.segment<3>(c + Block::M);
    MixedElementRates<K> rate;
    rate.u_dot = xdot.segment<3>(c + Block::u);
    rate.c_dot = xdot.segment<K>(c + Block::q);
    rate.P_dot = xdot.segment<3>(c + Block::P);
    rate.H_dot = xdot.segment<3>(c + Block::H);
    const bool jac = J_x != nullptr || J_xdot != nullptr;
    MixedHomogeneousResult<K>& r = static_result_;
    MixedInertiaResult<K>& q = inertia_result_;
    mixed_homogeneous_element_statics<P>(el, s, 1.0, jac, r);
    mixed_element_inertia<P>(el, mass_inverse_[static_cast<std::size_t>(e)], s.q,
                             x.segment<3>(c + Block::P), x.segment<3>(c + Block::H), rate, jac, q);
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
    // Load fields (manufactured motions): dead, so no Jacobian term (as MixedDynamics).
    counters_.distributed_load_terms += add_mixed_load_fields(
        model_.load_fields, el, 1.0, mixed_load_field_rule(), a, b, residual, t);
    residual.segment<Block::kinematic_rows>(row) = r.kinematic;
    residual.segment<3>(row + Block::fP) = q.fP;  // Eq. 49
    residual.segment<3>(row + Block::fH) = q.fH;  // Eq. 50
    if (J_x != nullptr) {
        SparseMatrix& J = *J_x;
        for (const int node : {a, b}) {
            add_block(J, node, c + Block::q, node == a ? r.J_minus : r.J_plus);
            add_block(J, node, c + Block::q, q.J_x.template block<6, K>(0, 0));
            add_block(J, node, c + Block::P, q.J_x.template block<6, 6>(0, K));
        }
        add_block(J, row, c, r.J_kinematic);
        add_block(J, row + Block::fP, c + Block::q, q.J_x.template block<6, K>(6, 0));
        add_block(J, row + Block::fP, c + Block::P, q.J_x.template block<6, 6>(6, K));
    }
    if (J_xdot != nullptr) {
        SparseMatrix& Kd = *J_xdot;
        for (const int node : {a, b}) {
            add_block(Kd, node, c + Block::q, q.J_xdot.template block<6, K>(0, 3));
            add_block(Kd, node, c + Block::P, q.J_xdot.template block<6, 6>(0, 3 + K));
        }
        // f_P, f_H against u̇, q̇ (they hold no Ṗ, Ḣ).
        add_block(Kd, row + Block::fP, c + Block::u, q.J_xdot.template block<6, 3 + K>(6, 0));
    }
}

// f_F^− − û_a, f_M^− − q̂_a, f_F^+ + û_b, f_M^+ + q̂_b (Eqs. 33–34, 37–38); a support's q̂ is given
// at time t (× ρ after the first support: ∂/∂ρ = q_given).
template <param::RotationParameterization P>
requires(P::kSize == 4) void MixedQuaternionDynamics<P>::add_node_terms(int e, double t,
                                                                        const VecX& x,
                                                                        VecX& residual,
                                                                        SparseMatrix* J_x) const {
    const MixedElement& el = layout_.base.elements[static_cast<std::size_t>(e)];
    const int ends[2] = {el.start_node, el.end_node};
    for (int side = 0; side < 2; ++side) {
        const double s = side == 0 ? -1.0 : 1.0;
        const int n = ends[side];
        const int r = element_row(e) + (3 + K) * side;
        Vec3 u_hat;
        Params q_hat;
        node_motion(x, t, n, u_hat, q_hat);
        residual.segment<3>(r) += s * u_hat;
        residual.segment<K>(r + 3) += s * q_hat;
        if (J_x == nullptr) continue;
        if (!supported(n)) {
            add_block(*J_x, r, node_column(n), s * Eigen::Matrix<double, 3 + K, 3 + K>::Identity());
        } else if (layout_.has_scale(n)) {
            add_block(*J_x, r + 3, node_column(n) + 6, s * given_rotation(n, t));
        }
    }
}

// Applied point loads with their time functions (Eqs. 31–32, 35–36) and the reactions of the
// supported nodes; a follower load at a free node is R(q̂) f0, ∂(−R f0)/∂q̂ = R f̃0 H_m(q̂).
template <param::RotationParameterization P>
requires(P::kSize == 4) void MixedQuaternionDynamics<P>::add_point_loads(double t, const VecX& x,
                                                                         VecX& residual,
                                                                         SparseMatrix* J_x) const {
    for (const PointLoad& load : model_.point_loads) {
        const int r = 6 * load.point;
        const double s = mixed_time_value(load.time, t, load_time_floor_);
        Vec3 u_hat;
        Params q_hat;
        node_motion(x, t, load.point, u_hat, q_hat);
        const Mat3 R = load.frame == LoadFrame::follower ? P::matrix(q_hat) : Mat3::Identity();
        residual.segment<3>(r) -= s * (R * load.force);
        residual.segment<3>(r + 3) -= s * (R * load.moment);
        if (J_x == nullptr || load.frame == LoadFrame::dead || supported(load.point)) continue;
        const param::Tangent<K> H = P::material_tangent(q_hat);
        const int c = node_column(load.point) + 3;
        add_block(*J_x, r, c, s * R * so3::skew(load.force) * H);
        add_block(*J_x, r + 3, c, s * R * so3::skew(load.moment) * H);
    }
    for (int n = 0; n < node_count(); ++n) {
        if (!supported(n)) continue;
        residual.segment<6>(6 * n) -= x.segment<6>(node_column(n));  // − (reaction force, moment)
        if (J_x != nullptr) add_block(*J_x, 6 * n, node_column(n), -Mat6::Identity());
    }
}

template <param::RotationParameterization P>
requires(P::kSize == 4) VecX MixedQuaternionDynamics<P>::from_static_state(const VecX& static_state)
const {
    ROTBEAM_VERIFY(static_state.size() == layout_.size(), "static state size mismatch");
    VecX x = VecX::Zero(size_);
    x.head(layout_.node_unknowns) = static_state.head(layout_.node_unknowns);
    for (int e = 0; e < element_count(); ++e) {
        x.segment<MixedQuaternionLayout::kElementUnknowns>(element_column(e)) =
            static_state.segment<MixedQuaternionLayout::kElementUnknowns>(
                layout_.element_column(e));
    }
    return x;
}

template <param::RotationParameterization P>
requires(P::kSize ==
         4) void MixedQuaternionDynamics<P>::set_translational_momenta(VecX& x,
                                                                       const Vec3& v) const {
    for (int e = 0; e < element_count(); ++e) {
        const MixedElement& el = layout_.base.elements[static_cast<std::size_t>(e)];
        const int c = element_column(e);
        const Mat3 A = P::matrix(x.segment<K>(c + Block::q)) * el.Cab;
        const Mat6 I = mass_inverse_[static_cast<std::size_t>(e)].inverse();
        x.segment<6>(c + Block::P) = I * (Vec6() << A.transpose() * v, Vec3::Zero()).finished();
    }
}

template <param::RotationParameterization P>
requires(P::kSize == 4) PointState MixedQuaternionDynamics<P>::point_state(const VecX& x, double t,
                                                                           int point_index)
const {
    ROTBEAM_VERIFY(point_index >= 0 && point_index < static_cast<int>(model_.points.size()),
                   "point index out of range");
    Vec3 u_hat;
    Params q_hat;
    node_motion(x, t, point_index, u_hat, q_hat);
    PointState s;
    s.displacement = u_hat;
    s.rotation = P::matrix(q_hat);  // C(q)/|q|²
    return s;
}

template <param::RotationParameterization P>
requires(P::kSize == 4)
    std::vector<StaticProblem::RotationStation> MixedQuaternionDynamics<P>::rotation_stations(
        const VecX& x, double t)
const {
    std::vector<StaticProblem::RotationStation> out;
    Vec3 u_hat;
    Params q_hat;
    for (int e = 0; e < element_count(); ++e) {
        const MixedElement& el = layout_.base.elements[static_cast<std::size_t>(e)];
        if (out.empty() || out.back().member != el.member) {
            node_motion(x, t, el.start_node, u_hat, q_hat);
            out.push_back({el.member, true, P::matrix(q_hat)});
        }
        const int o = element_column(e);
        const Vec6 strain = el.S * x.segment<6>(o + Block::F);
        const Vec3 kappa = strain.tail<3>();
        out.push_back({el.member, false, P::matrix(x.segment<K>(o + Block::q)),
                       el.length * (el.Cab * kappa)});
        node_motion(x, t, el.end_node, u_hat, q_hat);
        out.push_back({el.member, true, P::matrix(q_hat)});
    }
    return out;
}

template <param::RotationParameterization P>
requires(P::kSize == 4) double MixedQuaternionDynamics<P>::max_rotation_angle(const VecX& x) const {
    double angle = 0.0;
    for (int e = 0; e < element_count(); ++e) {
        angle = std::max(angle, P::angle(x.segment<K>(element_column(e) + Block::q)));
    }
    return angle;
}

template <param::RotationParameterization P>
requires(P::kSize == 4) QuaternionNormDrift MixedQuaternionDynamics<P>::norm_drift(const VecX& x,
                                                                                   double t)
const {
    QuaternionNormDrift d;
    for (int n = 0; n < node_count(); ++n) {
        Vec3 u_hat;
        Params q_hat;
        node_motion(x, t, n, u_hat, q_hat);
        d.nodes = std::max(d.nodes, std::abs(q_hat.norm() - 1.0));
    }
    for (int e = 0; e < element_count(); ++e) {
        const double norm = x.segment<K>(element_column(e) + Block::q).norm();
        d.elements = std::max(d.elements, std::abs(norm - 1.0));
    }
    return d;
}

template <param::RotationParameterization P>
requires(P::kSize == 4) std::string MixedQuaternionDynamics<P>::describe_state(const VecX& x)
const {
    std::ostringstream s;
    s << "mixed/" << P::kName << ", largest element rotation " << max_rotation_angle(x) << " rad";
    return s.str();
}

template class MixedQuaternionDynamics<param::Quaternion>;

}  // namespace rotbeam::form
