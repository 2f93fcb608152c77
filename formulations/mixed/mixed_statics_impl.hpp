// Member definitions of MixedStatics<P>; included only by mixed_statics.cpp, which instantiates
// the template for every parameterization.
#pragma once

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/beam_rotation.hpp"
#include "core/errors.hpp"
#include "formulations/displacement/calculate_rotating_frame_forces.hpp"
#include "formulations/mixed/mixed_dynamic_common.hpp"
#include "formulations/mixed/mixed_node_frames.hpp"
#include "formulations/mixed/mixed_statics.hpp"
#include "formulations/mixed/mixed_support_rotation.hpp"

namespace rotbeam::form {

template <param::RotationParameterization P>
MixedStatics<P>::MixedStatics(const Model& model)
    : model_(model),
      layout_(build_mixed_layout(model)),
      numbering_(number_mixed_unknowns(layout_, K, kConstraintRows, false)) {
    // The reference configuration: every ĉ and c_i the identity, every ρ = 1.
    x_ = VecX::Zero(numbering_.size());
    for (int n = 0; n < numbering_.node_count(); ++n) {
        const int c = numbering_.node_column(n);
        if (!numbering_.supported(n)) x_.segment<K>(c + 3) = P::identity();
        if (numbering_.has_scale(n)) x_[c + 6] = 1.0;
    }
    for (int e = 0; e < numbering_.element_count; ++e) {
        x_.segment<K>(numbering_.element_column(e) + 3) = P::identity();
    }
    for (VecX& s : saved_) s = x_;
    mixed_scales(layout_, numbering_, residual_scale_, increment_scale_);
    pattern_ = mixed_pattern(layout_, numbering_);
    if (model.solver.assemble_all_terms) prepare_rest_terms();
    if (model.rotating_frame.active()) {
        for (const MixedElement& el : layout_.elements) {
            spin_mass_.push_back(mixed_element_mass(model_, el));
        }
    }
}

// The inertial force of the steady rotating frame on element e, taken at its mid-point like the
// element's other distributed loads (Eqs. 51–54: h f to each end node, with f = −F^I here):
// F^I of the mid-point's position x^r + u_i and frame R(c_i) C^ab
// (calculate_rotating_frame_forces.hpp), spatial spin δθ = R H_m(c_i) δc_i.
template <param::RotationParameterization P>
void MixedStatics<P>::add_rotating_frame(int e, int a, int b, VecX& residual,
                                         SparseMatrix* jacobian) {
    const MixedElement& el = layout_.elements[static_cast<std::size_t>(e)];
    const MixedElementState<K> st = element_state(e);
    const Mat3 R = P::matrix(st.c);
    const Vec3 x =
        layout_.nodes[static_cast<std::size_t>(el.start_node)].reference + 0.5 * el.chord + st.u;
    const RotatingFrame& f = model_.rotating_frame;
    const RotatingFrameForces spin =
        calculate_rotating_frame_forces(spin_mass_[static_cast<std::size_t>(e)], R * el.Cab,
                                        x - f.center, f.angular_velocity, lambda_);
    const double h = 0.5 * el.length;
    residual.segment<6>(a) += h * spin.F;
    residual.segment<6>(b) += h * spin.F;
    if (jacobian == nullptr) return;
    Eigen::Matrix<double, 6, 3 + K> block;
    block.template leftCols<3>() = h * spin.dF_dx;
    block.template rightCols<K>() = h * spin.dF_dtheta * R * P::material_tangent(st.c);
    const int c = numbering_.element_column(e);
    add_mixed_block(*jacobian, a, c, block);
    add_mixed_block(*jacobian, b, c, block);
}

// A support's rotation: the identity when clamped, the prescribed rotation (scaled with the load
// factor, core/model.hpp) otherwise, on the sheet reached continuously from the identity
// (mixed_support_rotation.hpp).
template <param::RotationParameterization P>
typename MixedStatics<P>::Params MixedStatics<P>::given_rotation(int node) const {
    const Constraint& con = model_.constraints[static_cast<std::size_t>(
        layout_.nodes[static_cast<std::size_t>(node)].constraint)];
    if (con.kind == Constraint::Kind::clamped) return P::identity();
    return continued_support_rotation<P>(lambda_ * con.rotation);
}

template <param::RotationParameterization P>
void MixedStatics<P>::supported_motion(int node, Vec3& u_hat, Params& c_hat) const {
    const Constraint& con = model_.constraints[static_cast<std::size_t>(
        layout_.nodes[static_cast<std::size_t>(node)].constraint)];
    u_hat = con.kind == Constraint::Kind::clamped ? Vec3::Zero() : Vec3(lambda_ * con.displacement);
    c_hat = given_rotation(node);
    if (numbering_.has_scale(node)) c_hat *= x_[numbering_.node_column(node) + 6];
}

template <param::RotationParameterization P>
void MixedStatics<P>::node_motion(int node, Vec3& u_hat, Params& c_hat) const {
    if (numbering_.supported(node)) {
        supported_motion(node, u_hat, c_hat);
        return;
    }
    const int c = numbering_.node_column(node);
    u_hat = x_.segment<3>(c);
    c_hat = x_.segment<K>(c + 3);
}

template <param::RotationParameterization P>
MixedElementState<MixedStatics<P>::K> MixedStatics<P>::element_state(int e) const {
    const int c = numbering_.element_column(e);
    MixedElementState<K> s;
    s.u = x_.segment<3>(c);
    s.c = x_.segment<K>(c + 3);
    s.F = x_.segment<3>(c + 3 + K);
    s.M = x_.segment<3>(c + 6 + K);
    return s;
}

// Applied point loads (Eqs. 31–32, 35–36: F*, M*) and the reactions of supported nodes. A
// follower load at a free node is R(ĉ) f0 with ∂(−R f0)/∂ĉ = R f̃0 H_m(ĉ).
template <param::RotationParameterization P>
void MixedStatics<P>::add_point_loads(VecX& residual, SparseMatrix* jacobian) const {
    for (const PointLoad& load : model_.point_loads) {
        const int r = numbering_.node_row(load.point);
        const double t = lambda_ * load.time(0.0);
        Mat3 R = Mat3::Identity();
        Vec3 u_hat;
        Params c_hat;
        if (load.frame == LoadFrame::follower) {
            node_motion(load.point, u_hat, c_hat);
            R = P::matrix(c_hat);
        }
        residual.segment<3>(r) -= t * (R * load.force);
        residual.segment<3>(r + 3) -= t * (R * load.moment);
        if (jacobian == nullptr || load.frame == LoadFrame::dead ||
            numbering_.supported(load.point)) {
            continue;  // R(ρ ĉ_given) does not depend on ρ
        }
        const int c = numbering_.node_column(load.point) + 3;
        const param::Tangent<K> H = P::material_tangent(c_hat);
        const param::Tangent<K> dF = t * R * so3::skew(load.force) * H;
        const param::Tangent<K> dM = t * R * so3::skew(load.moment) * H;
        add_mixed_block(*jacobian, r, c, dF);
        add_mixed_block(*jacobian, r + 3, c, dM);
    }
    for (int n = 0; n < numbering_.node_count(); ++n) {
        if (!numbering_.supported(n)) continue;
        const int r = numbering_.node_row(n);
        residual.segment<6>(r) -= x_.segment<6>(numbering_.node_column(n));  // − reaction
        if (jacobian != nullptr) {
            add_mixed_block(*jacobian, r, numbering_.node_column(n), -Mat6::Identity());
        }
    }
}

template <param::RotationParameterization P>
void MixedStatics<P>::evaluate(VecX& residual, SparseMatrix* jacobian) {
    residual.setZero(numbering_.size());
    if (jacobian != nullptr) {
        if (jacobian->rows() != pattern_.rows() || jacobian->nonZeros() != pattern_.nonZeros()) {
            *jacobian = pattern_;  // first call only: afterwards the pattern is reused
        }
        std::fill(jacobian->valuePtr(), jacobian->valuePtr() + jacobian->nonZeros(), 0.0);
        ++counters_.jacobian_evaluations;
    }
    ++counters_.residual_evaluations;
    for (int e = 0; e < numbering_.element_count; ++e) assemble_element(e, residual, jacobian);
    add_point_loads(residual, jacobian);
    for (const PointLoad& load : model_.point_loads) {
        if (load.frame == LoadFrame::follower) ++counters_.follower_stiffness;
    }
}

// One element's f_u, f_ψ into its end nodes' equilibrium rows (Eqs. 39–40) and its own kinematic
// rows with the node terms (add_node_terms).
template <param::RotationParameterization P>
void MixedStatics<P>::assemble_element(int e, VecX& residual, SparseMatrix* jacobian) {
    const MixedElement& el = layout_.elements[static_cast<std::size_t>(e)];
    MixedElementResult<K>& r = element_result_;
    mixed_element_statics<P>(el, element_state(e), lambda_, jacobian != nullptr, r);
    ++counters_.elastic_terms;
    const bool follower = el.f_follower.norm() + el.m_follower.norm() > 0.0;
    if (follower || el.f_dead.norm() + el.m_dead.norm() > 0.0) ++counters_.distributed_load_terms;
    if (follower) ++counters_.follower_stiffness;
    const int a = numbering_.node_row(el.start_node);
    const int b = numbering_.node_row(el.end_node);
    residual.segment<3>(a) += r.fu_minus;
    residual.segment<3>(a + 3) += r.fpsi_minus;
    residual.segment<3>(b) += r.fu_plus;
    residual.segment<3>(b + 3) += r.fpsi_plus;
    counters_.distributed_load_terms += add_mixed_load_fields(
        model_.load_fields, el, lambda_, mixed_load_field_rule(), a, b, residual);
    residual.segment<MixedElementResult<K>::kRows>(numbering_.element_row(e)) = r.kinematic;
    if (jacobian != nullptr) {
        const int c = numbering_.element_column(e);
        add_mixed_block(*jacobian, a, c + 3, r.J_minus);
        add_mixed_block(*jacobian, b, c + 3, r.J_plus);
        add_mixed_block(*jacobian, numbering_.element_row(e), c, r.J_kinematic);
    }
    add_node_terms(e, residual, jacobian);
    if (!rest_mass_inverse_.empty()) assemble_rest_terms(e, a, b, residual, jacobian);
    if (!spin_mass_.empty()) add_rotating_frame(e, a, b, residual, jacobian);
}

// f_F^− − û_a, f_M^− − ĉ_a, f_F^+ + û_b, f_M^+ + ĉ_b (Eqs. 33–34, 37–38, 41–42 before
// eliminating û, ĉ). A support's ĉ is given (× ρ after the first support: ∂/∂ρ = ĉ_given).
template <param::RotationParameterization P>
void MixedStatics<P>::add_node_terms(int e, VecX& residual, SparseMatrix* jacobian) const {
    const MixedElement& el = layout_.elements[static_cast<std::size_t>(e)];
    const int ends[2] = {el.start_node, el.end_node};
    for (int side = 0; side < 2; ++side) {
        const double s = side == 0 ? -1.0 : 1.0;
        const int n = ends[side];
        const int r = numbering_.element_row(e) + (3 + K) * side;
        Vec3 u_hat;
        Params c_hat;
        node_motion(n, u_hat, c_hat);
        residual.segment<3>(r) += s * u_hat;
        residual.segment<K>(r + 3) += s * c_hat;
        if (jacobian == nullptr) continue;
        const int c = numbering_.node_column(n);
        if (!numbering_.supported(n)) {
            add_mixed_block(*jacobian, r, c, s * Eigen::Matrix<double, 3 + K, 3 + K>::Identity());
        } else if (numbering_.has_scale(n)) {
            add_mixed_block(*jacobian, r + 3, c + 6, s * given_rotation(n));
        }
    }
}

template <param::RotationParameterization P>
PointState MixedStatics<P>::point_state(int point_index) const {
    ROTBEAM_VERIFY(point_index >= 0 && point_index < static_cast<int>(model_.points.size()),
                   "point index out of range");
    Vec3 u_hat;
    Params c_hat;
    node_motion(point_index, u_hat, c_hat);
    PointState s;
    s.displacement = u_hat;
    s.rotation = P::matrix(c_hat);  // the relative rotation R^c R^rᵀ
    return s;
}

template <param::RotationParameterization P>
double MixedStatics<P>::max_rotation_angle() const {
    double angle = 0.0;
    for (int e = 0; e < numbering_.element_count; ++e) {
        angle = std::max(angle, P::angle(x_.segment<K>(numbering_.element_column(e) + 3)));
    }
    return angle;
}

// Start node, then per element its rotation c_i and its end node (elements are numbered member by
// member in arc-length order, mixed_layout.cpp).
template <param::RotationParameterization P>
std::vector<StaticProblem::RotationStation> MixedStatics<P>::rotation_stations() const {
    const auto node_rotation = [this](int node) {
        Vec3 u_hat;
        Params c_hat;
        node_motion(node, u_hat, c_hat);
        return P::matrix(c_hat);
    };
    std::vector<RotationStation> out;
    for (int e = 0; e < numbering_.element_count; ++e) {
        const MixedElement& el = layout_.elements[static_cast<std::size_t>(e)];
        if (out.empty() || out.back().member != el.member) {
            out.push_back({el.member, true, node_rotation(el.start_node)});
        }
        const MixedElementState<K> st = element_state(e);
        const Vec6 strain = el.S * (Vec6() << st.F, st.M).finished();
        const Vec3 kappa = strain.tail<3>();
        out.push_back({el.member, false, P::matrix(st.c), el.length * (el.Cab * kappa)});
        out.push_back({el.member, true, node_rotation(el.end_node)});
    }
    return out;
}

// The node frames in the order of mixed_frame_nodes (mixed_node_frames.hpp).
template <param::RotationParameterization P>
std::vector<StaticProblem::NodeFrame> MixedStatics<P>::node_frames() const {
    return mixed_node_frames(layout_, numbering_.element_count,
                             [this](int node, Vec3& u_hat, Mat3& R) {
                                 Params c_hat;
                                 node_motion(node, u_hat, c_hat);
                                 R = P::matrix(c_hat);
                             });
}

template <param::RotationParameterization P>
QuaternionNormDrift MixedStatics<P>::norm_drift() const
    requires(param::ParameterConstraint<P>::kRows > 0) {
    QuaternionNormDrift d;
    for (int n = 0; n < numbering_.node_count(); ++n) {
        Vec3 u_hat;
        Params c_hat;
        node_motion(n, u_hat, c_hat);
        d.nodes = std::max(d.nodes, std::abs(c_hat.norm() - 1.0));
    }
    for (int e = 0; e < numbering_.element_count; ++e) {
        const double norm = x_.segment<K>(numbering_.element_column(e) + 3).norm();
        d.elements = std::max(d.elements, std::abs(norm - 1.0));
    }
    return d;
}

template <param::RotationParameterization P>
std::string MixedStatics<P>::describe_state() const {
    std::ostringstream s;
    s << "mixed/" << P::kName << ", load factor " << lambda_ << ", largest rotation "
      << largest_continued_angle(model_, rotation_stations())
      << " rad (continued along the beam), ";
    if constexpr (kConstraintRows > 0) {
        const QuaternionNormDrift d = norm_drift();
        s << "max ||q| - 1|: nodes " << d.nodes << ", elements (midpoint averages, O(dL^2)) "
          << d.elements;
    } else {
        s << "largest element parameter angle " << max_rotation_angle() << " rad";
    }
    return s.str();
}

template <param::RotationParameterization P>
std::vector<MixedElementResultants> MixedStatics<P>::resultants() const {
    std::vector<MixedElementResultants> out;
    for (const SectionResultants& r : section_resultants()) {
        out.push_back({r.member, r.s, r.force, r.moment});
    }
    return out;
}

// F and M are element unknowns in the deformed material frame (seed 002 Eq. 45's b axes).
template <param::RotationParameterization P>
std::vector<SectionResultants> MixedStatics<P>::section_resultants() const {
    return mixed_section_resultants(layout_, numbering_.element_count,
                                    [this](int e, Mat3& R, Vec3& F, Vec3& M) {
                                        const MixedElementState<K> st = element_state(e);
                                        R = P::matrix(st.c);
                                        F = st.F;
                                        M = st.M;
                                    });
}

}  // namespace rotbeam::form
