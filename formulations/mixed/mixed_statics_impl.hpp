// Member definitions of MixedStatics<P>; included only by mixed_statics.cpp, which instantiates
// the template for every three-parameter parameterization.
#pragma once

#include <algorithm>
#include <sstream>

#include "core/beam_rotation.hpp"
#include "core/errors.hpp"
#include "formulations/mixed/mixed_statics.hpp"

namespace rotbeam::form {

template <param::RotationParameterization P>
MixedStatics<P>::MixedStatics(const Model& model)
    : model_(model), layout_(build_mixed_layout(model)) {
    x_ = VecX::Zero(layout_.size());  // the reference configuration: c = 0 is the identity
    for (VecX& s : saved_) s = x_;
    mixed_scales(layout_, residual_scale_, increment_scale_);
    pattern_ = mixed_pattern(layout_);
    ROTBEAM_VERIFY(P::identity().norm() == 0.0,
                   "the mixed formulation needs parameters that vanish at the identity");
    if (model.solver.assemble_all_terms) prepare_rest_terms();
}

template <param::RotationParameterization P>
void MixedStatics<P>::supported_motion(int node, Vec3& u_hat, Vec3& c_hat) const {
    const Constraint& con = model_.constraints[static_cast<std::size_t>(
        layout_.nodes[static_cast<std::size_t>(node)].constraint)];
    if (con.kind == Constraint::Kind::clamped) {
        u_hat.setZero();
        c_hat.setZero();
        return;
    }
    // Prescribed motion scales with the load factor (core/model.hpp).
    u_hat = lambda_ * con.displacement;
    c_hat = P::from_rotation_vector(lambda_ * con.rotation);
}

template <param::RotationParameterization P>
void MixedStatics<P>::node_motion(int node, Vec3& u_hat, Vec3& c_hat) const {
    if (layout_.supported(node)) {
        supported_motion(node, u_hat, c_hat);
        return;
    }
    const int o = layout_.node_offset(node);
    u_hat = x_.segment<3>(o);
    c_hat = x_.segment<3>(o + 3);
}

template <param::RotationParameterization P>
MixedElementState MixedStatics<P>::element_state(int e) const {
    const int o = layout_.element_offset(e);
    MixedElementState s;
    s.u = x_.segment<3>(o);
    s.c = x_.segment<3>(o + 3);
    s.F = x_.segment<3>(o + 6);
    s.M = x_.segment<3>(o + 9);
    return s;
}

// Applied point loads (Eqs. 31–32, 35–36: F*, M*) and the reactions of supported nodes.
template <param::RotationParameterization P>
void MixedStatics<P>::add_point_loads(VecX& residual, SparseMatrix* jacobian) const {
    for (const PointLoad& load : model_.point_loads) {
        const int o = layout_.node_offset(load.point);
        const double t = lambda_ * load.time(0.0);
        if (load.frame == LoadFrame::dead || layout_.supported(load.point)) {
            Mat3 R = Mat3::Identity();
            if (load.frame == LoadFrame::follower) {
                Vec3 u_hat, c_hat;
                supported_motion(load.point, u_hat, c_hat);
                R = P::matrix(c_hat);
            }
            residual.segment<3>(o) -= t * (R * load.force);
            residual.segment<3>(o + 3) -= t * (R * load.moment);
            continue;
        }
        // Follower: f = R(ĉ) f0 (core/model.hpp), ∂(−R f0)/∂ĉ = R f̃0 H_m(ĉ).
        const Vec3 c_hat = x_.segment<3>(o + 3);
        const Mat3 R = P::matrix(c_hat);
        residual.segment<3>(o) -= t * (R * load.force);
        residual.segment<3>(o + 3) -= t * (R * load.moment);
        if (jacobian == nullptr) continue;
        const Mat3 H = P::material_tangent(c_hat);
        const Mat3 dF = t * R * so3::skew(load.force) * H;
        const Mat3 dM = t * R * so3::skew(load.moment) * H;
        add_block(*jacobian, o, o + 3, dF);
        add_block(*jacobian, o + 3, o + 3, dM);
    }
    for (int n = 0; n < static_cast<int>(layout_.nodes.size()); ++n) {
        if (!layout_.supported(n)) continue;
        const int o = layout_.node_offset(n);
        residual.segment<6>(o) -= x_.segment<6>(o);  // − (reaction force, moment)
        if (jacobian != nullptr) add_block(*jacobian, o, o, -Mat6::Identity());
    }
}

template <param::RotationParameterization P>
void MixedStatics<P>::evaluate(VecX& residual, SparseMatrix* jacobian) {
    residual.setZero(layout_.size());
    if (jacobian != nullptr) {
        if (jacobian->rows() != pattern_.rows() || jacobian->nonZeros() != pattern_.nonZeros()) {
            *jacobian = pattern_;  // first call only: afterwards the pattern is reused
        }
        std::fill(jacobian->valuePtr(), jacobian->valuePtr() + jacobian->nonZeros(), 0.0);
        ++counters_.jacobian_evaluations;
    }
    ++counters_.residual_evaluations;
    for (int e = 0; e < layout_.element_count(); ++e) assemble_element(e, residual, jacobian);
    add_point_loads(residual, jacobian);
    for (const PointLoad& load : model_.point_loads) {
        if (load.frame == LoadFrame::follower) ++counters_.follower_stiffness;
    }
}

// One element's f_u, f_ψ into its end nodes' equilibrium rows and its kinematic rows with the
// node terms: f_F^− − û_a, f_M^− − ĉ_a, f_F^+ + û_b, f_M^+ + ĉ_b (Eqs. 33–34, 37–38, 41–42).
template <param::RotationParameterization P>
void MixedStatics<P>::assemble_element(int e, VecX& residual, SparseMatrix* jacobian) {
    const MixedElement& el = layout_.elements[static_cast<std::size_t>(e)];
    MixedElementResult& r = element_result_;
    mixed_element_statics<P>(el, element_state(e), lambda_, jacobian != nullptr, r);
    ++counters_.elastic_terms;
    const bool follower = el.f_follower.norm() + el.m_follower.norm() > 0.0;
    if (follower || el.f_dead.norm() + el.m_dead.norm() > 0.0) ++counters_.distributed_load_terms;
    if (follower) ++counters_.follower_stiffness;
    const int o = layout_.element_offset(e);
    const int a = layout_.node_offset(el.start_node);
    const int b = layout_.node_offset(el.end_node);
    residual.segment<3>(a) += r.fu_minus;
    residual.segment<3>(a + 3) += r.fpsi_minus;
    residual.segment<3>(b) += r.fu_plus;
    residual.segment<3>(b + 3) += r.fpsi_plus;
    counters_.distributed_load_terms += add_mixed_load_fields(
        model_.load_fields, el, lambda_, mixed_load_field_rule(), a, b, residual);
    Vec3 ua, ca, ub, cb;
    node_motion(el.start_node, ua, ca);
    node_motion(el.end_node, ub, cb);
    residual.segment<12>(o) = r.kinematic;
    residual.segment<3>(o) -= ua;
    residual.segment<3>(o + 3) -= ca;
    residual.segment<3>(o + 6) += ub;
    residual.segment<3>(o + 9) += cb;
    if (jacobian == nullptr) {
        if (!rest_mass_inverse_.empty()) assemble_rest_terms(e, a, b, residual, nullptr);
        return;
    }
    add_block(*jacobian, a, o + 3, r.J_minus);
    add_block(*jacobian, b, o + 3, r.J_plus);
    add_block(*jacobian, o, o, r.J_kinematic);
    if (!layout_.supported(el.start_node)) add_block(*jacobian, o, a, -Mat6::Identity());
    if (!layout_.supported(el.end_node)) add_block(*jacobian, o + 6, b, Mat6::Identity());
    if (!rest_mass_inverse_.empty()) assemble_rest_terms(e, a, b, residual, jacobian);
}

template <param::RotationParameterization P>
PointState MixedStatics<P>::point_state(int point_index) const {
    ROTBEAM_VERIFY(point_index >= 0 && point_index < static_cast<int>(model_.points.size()),
                   "point index out of range");
    Vec3 u_hat, c_hat;
    node_motion(point_index, u_hat, c_hat);
    PointState s;
    s.displacement = u_hat;
    s.rotation = P::matrix(c_hat);  // the relative rotation R^c R^rᵀ
    return s;
}

template <param::RotationParameterization P>
double MixedStatics<P>::max_rotation_angle() const {
    double angle = 0.0;
    for (int e = 0; e < layout_.element_count(); ++e) {
        angle = std::max(angle, P::angle(x_.segment<3>(layout_.element_offset(e) + 3)));
    }
    return angle;
}

// Start node, then per element its rotation c_i and its end node (elements are numbered member by
// member in arc-length order, mixed_layout.cpp).
template <param::RotationParameterization P>
std::vector<StaticProblem::RotationStation> MixedStatics<P>::rotation_stations() const {
    std::vector<RotationStation> out;
    Vec3 u_hat, c_hat;
    for (int e = 0; e < layout_.element_count(); ++e) {
        const MixedElement& el = layout_.elements[static_cast<std::size_t>(e)];
        if (out.empty() || out.back().member != el.member) {
            node_motion(el.start_node, u_hat, c_hat);
            out.push_back({el.member, true, P::matrix(c_hat)});
        }
        const MixedElementState st = element_state(e);
        const Vec6 strain = el.S * (Vec6() << st.F, st.M).finished();
        const Vec3 kappa = strain.tail<3>();
        out.push_back({el.member, false, P::matrix(st.c), el.length * (el.Cab * kappa)});
        node_motion(el.end_node, u_hat, c_hat);
        out.push_back({el.member, true, P::matrix(c_hat)});
    }
    return out;
}

template <param::RotationParameterization P>
std::string MixedStatics<P>::describe_state() const {
    std::ostringstream s;
    s << "mixed/" << P::kName << ", load factor " << lambda_ << ", largest rotation "
      << largest_continued_angle(model_, rotation_stations())
      << " rad (continued along the beam), largest element parameter angle "
      << max_rotation_angle() << " rad";
    return s.str();
}

template <param::RotationParameterization P>
std::vector<MixedElementResultants> MixedStatics<P>::resultants() const {
    std::vector<MixedElementResultants> out;
    for (int e = 0; e < layout_.element_count(); ++e) {
        const MixedElement& el = layout_.elements[static_cast<std::size_t>(e)];
        const MixedElementState s = element_state(e);
        const Mat3 A = P::matrix(s.c) * el.Cab;
        out.push_back({el.member, el.s_mid, A * s.F, A * s.M});
    }
    return out;
}

// F and M are element unknowns in the deformed material frame (seed 002 Eq. 45's b axes).
template <param::RotationParameterization P>
std::vector<SectionResultants> MixedStatics<P>::section_resultants() const {
    std::vector<SectionResultants> out;
    for (int e = 0; e < layout_.element_count(); ++e) {
        const MixedElement& el = layout_.elements[static_cast<std::size_t>(e)];
        const MixedElementState st = element_state(e);
        const Mat3 A = P::matrix(st.c) * el.Cab;
        out.push_back({el.member, el.s_mid, A * st.F, A * st.M, st.F, st.M});
    }
    return out;
}

}  // namespace rotbeam::form
