// Member definitions of MixedQuaternionStatics<P> and its explicit instantiation for the
// quaternion (the only four-parameter parameterization).
#include "formulations/mixed/mixed_quaternion_statics.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/beam_rotation.hpp"
#include "core/errors.hpp"
#include "formulations/mixed/mixed_load_fields.hpp"
#include "parameterizations/quaternion.hpp"

namespace rotbeam::form {

template <param::RotationParameterization P>
requires(P::kSize == 4) MixedQuaternionStatics<P>::MixedQuaternionStatics(const Model& model)
    : model_(model), layout_(build_mixed_quaternion_layout(model)) {
    // The reference configuration: every q̂ and q_i the identity, every ρ = 1.
    x_ = VecX::Zero(layout_.size());
    for (int n = 0; n < static_cast<int>(layout_.base.nodes.size()); ++n) {
        const int c = layout_.node_column(n);
        if (!layout_.supported(n)) x_.segment<K>(c + 3) = P::identity();
        if (layout_.has_scale(n)) x_[c + 6] = 1.0;
    }
    for (int e = 0; e < layout_.base.element_count(); ++e) {
        x_.segment<K>(layout_.element_column(e) + 3) = P::identity();
    }
    for (VecX& s : saved_) s = x_;
    mixed_quaternion_scales(layout_, residual_scale_, increment_scale_);
    pattern_ = mixed_quaternion_pattern(layout_);
}

// The support's quaternion: the identity when clamped, the prescribed rotation (scaled with the
// load factor, core/model.hpp) otherwise; from_rotation_vector follows the angle continuously.
template <param::RotationParameterization P>
requires(P::kSize == 4) typename MixedQuaternionStatics<P>::Params
    MixedQuaternionStatics<P>::given_rotation(int node) const {
    const Constraint& con = model_.constraints[static_cast<std::size_t>(
        layout_.base.nodes[static_cast<std::size_t>(node)].constraint)];
    if (con.kind == Constraint::Kind::clamped) return P::identity();
    return P::from_rotation_vector(lambda_ * con.rotation);
}

template <param::RotationParameterization P>
requires(P::kSize == 4) void MixedQuaternionStatics<P>::supported_motion(int node, Vec3& u_hat,
                                                                         Params& q_hat) const {
    const Constraint& con = model_.constraints[static_cast<std::size_t>(
        layout_.base.nodes[static_cast<std::size_t>(node)].constraint)];
    u_hat = con.kind == Constraint::Kind::clamped ? Vec3::Zero() : Vec3(lambda_ * con.displacement);
    q_hat = given_rotation(node);
    if (layout_.has_scale(node)) q_hat *= x_[layout_.node_column(node) + 6];
}

template <param::RotationParameterization P>
requires(P::kSize == 4) void MixedQuaternionStatics<P>::node_motion(int node, Vec3& u_hat,
                                                                    Params& q_hat) const {
    if (layout_.supported(node)) {
        supported_motion(node, u_hat, q_hat);
        return;
    }
    const int c = layout_.node_column(node);
    u_hat = x_.segment<3>(c);
    q_hat = x_.segment<K>(c + 3);
}

template <param::RotationParameterization P>
requires(P::kSize ==
         4) MixedHomogeneousState<P::kSize> MixedQuaternionStatics<P>::element_state(int e)
const {
    const int c = layout_.element_column(e);
    MixedHomogeneousState<K> s;
    s.u = x_.segment<3>(c);
    s.q = x_.segment<K>(c + 3);
    s.F = x_.segment<3>(c + 3 + K);
    s.M = x_.segment<3>(c + 6 + K);
    return s;
}

// Applied point loads (Eqs. 31–32, 35–36: F*, M*) and the reactions of supported nodes. A
// follower load at a free node is R(q̂) f0 with ∂(−R f0)/∂q̂ = R f̃0 H_m(q̂).
template <param::RotationParameterization P>
requires(P::kSize ==
         4) void MixedQuaternionStatics<P>::add_point_loads(VecX& residual,
                                                            SparseMatrix* jacobian) const {
    for (const PointLoad& load : model_.point_loads) {
        const int r = layout_.node_row(load.point);
        const double t = lambda_ * load.time(0.0);
        Mat3 R = Mat3::Identity();
        Vec3 u_hat;
        Params q_hat;
        if (load.frame == LoadFrame::follower) {
            node_motion(load.point, u_hat, q_hat);
            R = P::matrix(q_hat);
        }
        residual.segment<3>(r) -= t * (R * load.force);
        residual.segment<3>(r + 3) -= t * (R * load.moment);
        if (jacobian == nullptr || load.frame == LoadFrame::dead || layout_.supported(load.point)) {
            continue;  // R(ρ q_given) does not depend on ρ
        }
        const int c = layout_.node_column(load.point) + 3;
        const param::Tangent<K> H = P::material_tangent(q_hat);
        const param::Tangent<K> dF = t * R * so3::skew(load.force) * H;
        const param::Tangent<K> dM = t * R * so3::skew(load.moment) * H;
        add_block(*jacobian, r, c, dF);
        add_block(*jacobian, r + 3, c, dM);
    }
    for (int n = 0; n < static_cast<int>(layout_.base.nodes.size()); ++n) {
        if (!layout_.supported(n)) continue;
        const int r = layout_.node_row(n);
        residual.segment<6>(r) -= x_.segment<6>(layout_.node_column(n));  // − reaction
        if (jacobian != nullptr) add_block(*jacobian, r, layout_.node_column(n), -Mat6::Identity());
    }
}

template <param::RotationParameterization P>
requires(P::kSize == 4) void MixedQuaternionStatics<P>::evaluate(VecX& residual,
                                                                 SparseMatrix* jacobian) {
    residual.setZero(layout_.size());
    if (jacobian != nullptr) {
        if (jacobian->rows() != pattern_.rows() || jacobian->nonZeros() != pattern_.nonZeros()) {
            *jacobian = pattern_;  // first call only: afterwards the pattern is reused
        }
        std::fill(jacobian->valuePtr(), jacobian->valuePtr() + jacobian->nonZeros(), 0.0);
        ++counters_.jacobian_evaluations;
    }
    ++counters_.residual_evaluations;
    for (int e = 0; e < layout_.base.element_count(); ++e) {
        assemble_element(e, residual, jacobian);
    }
    add_point_loads(residual, jacobian);
    for (const PointLoad& load : model_.point_loads) {
        if (load.frame == LoadFrame::follower) ++counters_.follower_stiffness;
    }
}

// One element's f_u, f_ψ into its end nodes' equilibrium rows (Eqs. 39–40) and its own kinematic
// rows; add_node_terms adds the node terms.
template <param::RotationParameterization P>
requires(P::kSize == 4) void MixedQuaternionStatics<P>::assemble_element(int e, VecX& residual,
                                                                         SparseMatrix* jacobian) {
    const MixedElement& el = layout_.base.elements[static_cast<std::size_t>(e)];
    MixedHomogeneousResult<K>& r = element_result_;
    mixed_homogeneous_element_statics<P>(el, element_state(e), lambda_, jacobian != nullptr, r);
    ++counters_.elastic_terms;
    const bool follower = el.f_follower.norm() + el.m_follower.norm() > 0.0;
    if (follower || el.f_dead.norm() + el.m_dead.norm() > 0.0) ++counters_.distributed_load_terms;
    if (follower) ++counters_.follower_stiffness;
    const int a = layout_.node_row(el.start_node);
    const int b = layout_.node_row(el.end_node);
    residual.segment<3>(a) += r.fu_minus;
    residual.segment<3>(a + 3) += r.fpsi_minus;
    residual.segment<3>(b) += r.fu_plus;
    residual.segment<3>(b + 3) += r.fpsi_plus;
    counters_.distributed_load_terms += add_mixed_load_fields(
        model_.load_fields, el, lambda_, mixed_load_field_rule(), a, b, residual);
    residual.segment<MixedHomogeneousResult<K>::kRows>(layout_.element_row(e)) = r.kinematic;
    if (jacobian != nullptr) {
        const int c = layout_.element_column(e);
        add_block(*jacobian, a, c + 3, r.J_minus);
        add_block(*jacobian, b, c + 3, r.J_plus);
        add_block(*jacobian, layout_.element_row(e), c, r.J_kinematic);
    }
    add_node_terms(e, residual, jacobian);
}

// f_F^− − û_a, f_M^− − q̂_a, f_F^+ + û_b, f_M^+ + q̂_b (Eqs. 33–34, 37–38, 41–42 before
// eliminating û, q̂). A support's q̂ is given (× ρ after the first support: ∂/∂ρ = q_given).
template <param::RotationParameterization P>
requires(P::kSize ==
         4) void MixedQuaternionStatics<P>::add_node_terms(int e, VecX& residual,
                                                           SparseMatrix* jacobian) const {
    const MixedElement& el = layout_.base.elements[static_cast<std::size_t>(e)];
    const int ends[2] = {el.start_node, el.end_node};
    for (int side = 0; side < 2; ++side) {
        const double s = side == 0 ? -1.0 : 1.0;
        const int n = ends[side];
        const int r = layout_.element_row(e) + (3 + K) * side;
        Vec3 u_hat;
        Params q_hat;
        node_motion(n, u_hat, q_hat);
        residual.segment<3>(r) += s * u_hat;
        residual.segment<K>(r + 3) += s * q_hat;
        if (jacobian == nullptr) continue;
        const int c = layout_.node_column(n);
        if (!layout_.supported(n)) {
            add_block(*jacobian, r, c, s * Eigen::Matrix<double, 3 + K, 3 + K>::Identity());
        } else if (layout_.has_scale(n)) {
            add_block(*jacobian, r + 3, c + 6, s * given_rotation(n));
        }
    }
}

template <param::RotationParameterization P>
requires(P::kSize == 4) PointState MixedQuaternionStatics<P>::point_state(int point_index)
const {
    ROTBEAM_VERIFY(point_index >= 0 && point_index < static_cast<int>(model_.points.size()),
                   "point index out of range");
    Vec3 u_hat;
    Params q_hat;
    node_motion(point_index, u_hat, q_hat);
    PointState s;
    s.displacement = u_hat;
    s.rotation = P::matrix(q_hat);  // the relative rotation R^c R^rᵀ, C(q)/|q|²
    return s;
}

template <param::RotationParameterization P>
requires(P::kSize == 4) double MixedQuaternionStatics<P>::max_rotation_angle() const {
    double angle = 0.0;
    for (int e = 0; e < layout_.base.element_count(); ++e) {
        angle = std::max(angle, P::angle(x_.segment<K>(layout_.element_column(e) + 3)));
    }
    return angle;
}

// Start node, then per element its q_i and its end node (elements are numbered member by member
// in arc-length order, mixed_layout.cpp). Every rotation is C(q)/|q|².
template <param::RotationParameterization P>
requires(P::kSize == 4)
    std::vector<StaticProblem::RotationStation> MixedQuaternionStatics<P>::rotation_stations()
const {
    std::vector<RotationStation> out;
    Vec3 u_hat;
    Params q_hat;
    for (int e = 0; e < layout_.base.element_count(); ++e) {
        const MixedElement& el = layout_.base.elements[static_cast<std::size_t>(e)];
        if (out.empty() || out.back().member != el.member) {
            node_motion(el.start_node, u_hat, q_hat);
            out.push_back({el.member, true, P::matrix(q_hat)});
        }
        const MixedHomogeneousState<K> st = element_state(e);
        const Vec6 strain = el.S * (Vec6() << st.F, st.M).finished();
        const Vec3 kappa = strain.tail<3>();
        out.push_back({el.member, false, P::matrix(st.q), el.length * (el.Cab * kappa)});
        node_motion(el.end_node, u_hat, q_hat);
        out.push_back({el.member, true, P::matrix(q_hat)});
    }
    return out;
}

template <param::RotationParameterization P>
requires(P::kSize == 4) QuaternionNormDrift MixedQuaternionStatics<P>::norm_drift()
const {
    QuaternionNormDrift d;
    for (int n = 0; n < static_cast<int>(layout_.base.nodes.size()); ++n) {
        Vec3 u_hat;
        Params q_hat;
        node_motion(n, u_hat, q_hat);
        d.nodes = std::max(d.nodes, std::abs(q_hat.norm() - 1.0));
    }
    for (int e = 0; e < layout_.base.element_count(); ++e) {
        const double norm = x_.segment<K>(layout_.element_column(e) + 3).norm();
        d.elements = std::max(d.elements, std::abs(norm - 1.0));
    }
    return d;
}

template <param::RotationParameterization P>
requires(P::kSize == 4) std::string MixedQuaternionStatics<P>::describe_state()
const {
    const QuaternionNormDrift d = norm_drift();
    std::ostringstream s;
    s << "mixed/" << P::kName << ", load factor " << lambda_ << ", largest rotation "
      << largest_continued_angle(model_, rotation_stations())
      << " rad (continued along the beam), max ||q| - 1|: nodes " << d.nodes
      << ", elements (midpoint averages, O(dL^2)) " << d.elements;
    return s.str();
}

// F and M are element unknowns in the deformed material frame (seed 002 Eq. 45's b axes).
template <param::RotationParameterization P>
requires(P::kSize ==
         4) std::vector<SectionResultants> MixedQuaternionStatics<P>::section_resultants()
const {
    std::vector<SectionResultants> out;
    for (int e = 0; e < layout_.base.element_count(); ++e) {
        const MixedElement& el = layout_.base.elements[static_cast<std::size_t>(e)];
        const MixedHomogeneousState<K> st = element_state(e);
        const Mat3 A = P::matrix(st.q) * el.Cab;
        out.push_back({el.member, el.s_mid, A * st.F, A * st.M, st.F, st.M});
    }
    return out;
}

template class MixedQuaternionStatics<param::Quaternion>;

}  // namespace rotbeam::form
