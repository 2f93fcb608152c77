// DisplacementStatics<P>: residual and exact Jacobian assembly. Included only by
// displacement_statics.cpp. The quadrature-point work is the kernel chain
// interpolate_rotation → calculate_strain → rotate_section → calculate_elastic_forces →
// calculate_stiffness_blocks; this file only scatters the results with the nodal maps.
#pragma once

#include <algorithm>

#include "core/so3.hpp"
#include "formulations/displacement/calculate_elastic_forces.hpp"
#include "formulations/displacement/calculate_rotating_frame_forces.hpp"
#include "formulations/displacement/calculate_stiffness_blocks.hpp"
#include "formulations/displacement/calculate_strain.hpp"
#include "formulations/displacement/displacement_statics.hpp"
#include "formulations/displacement/rotate_section.hpp"

namespace rotbeam::form {

template <param::RotationParameterization P>
void DisplacementStatics<P>::evaluate(VecX& r, SparseMatrix* J) {
    const int n = mesh_.unknowns;
    if (r.size() != n) r.resize(n);
    r.setZero();
    ++counters_.residual_evaluations;
    if (J != nullptr) {
        ++counters_.jacobian_evaluations;
        if (J->rows() != n || J->cols() != n || J->nonZeros() != pattern_.nonZeros() ||
            !J->isCompressed()) {
            *J = pattern_;
        }
        std::fill(J->valuePtr(), J->valuePtr() + J->nonZeros(), 0.0);
    }
    for (int k = 0; k < static_cast<int>(mesh_.elements.size()); ++k) assemble_element(k, r, J);
    if (J != nullptr) mip_.maps_recorded();
    assemble_point_loads(r, J);
    if (additive_ && J != nullptr) apply_parameter_tangent(*J);
}

// direct: nodal parameters aligned to the element's first node (σ_j); relative: the parameters
// r_j of R_0ᵀ R_j. Displacements, and M_j = H_s⁺ of what is interpolated (σ_j included).
template <param::RotationParameterization P>
void DisplacementStatics<P>::gather_element(const MeshElement& e, bool jacobian) {
    const int nn = static_cast<int>(e.nodes.size());
    for (int j = 0; j < nn; ++j) {
        ue_[j] = u_[e.nodes[j]];
        pe_[j] = p_[e.nodes[j]];
    }
    if (relative_) {
        R0_ = P::matrix(pe_[0]);
        relative_parameters<P>(pe_.data(), nn, pe_.data());
    } else {
        for (int j = 1; j < nn; ++j) pe_[j] *= chart_sign<P>(pe_[j], pe_[0]);
    }
    if (!jacobian) return;
    for (int j = 0; j < nn; ++j) Me_[j] = P::spatial_tangent_inverse(pe_[j]);
}

template <param::RotationParameterization P>
void DisplacementStatics<P>::distributed_load(const MeshElement& e, const QuadraturePoint& qp,
                                              const Mat3& R, bool jacobian, Vec6& f,
                                              Eigen::Matrix<double, 6, 3>& df_dpsi) {
    f.setZero();
    df_dpsi.setZero();
    for (size_t i = 0; i < model_.distributed_loads.size(); ++i) {
        const DistributedLoad& l = model_.distributed_loads[i];
        if (l.member != e.member) continue;
        ++counters_.distributed_load_terms;
        const double lambda = lambda_ * distributed_factor_[i];
        if (l.frame == LoadFrame::dead) {
            f.head<3>() += lambda * l.force;
            f.tail<3>() += lambda * l.moment;
            continue;
        }
        // f = λ R f0: δf = δψ × f = −f̃ δψ.
        const Vec3 fr = lambda * (R * l.force);
        const Vec3 mr = lambda * (R * l.moment);
        f.head<3>() += fr;
        f.tail<3>() += mr;
        if (jacobian) {
            ++counters_.follower_stiffness;
            df_dpsi.topRows<3>() -= so3::skew(fr);
            df_dpsi.bottomRows<3>() -= so3::skew(mr);
        }
    }
    for (const LoadField& l : model_.load_fields) {
        if (l.member != e.member) continue;
        ++counters_.distributed_load_terms;
        Vec3 force, moment;
        l.evaluate(qp.s, lambda_, time_, force, moment);  // dead: no load stiffness
        f.head<3>() += force;
        f.tail<3>() += moment;
    }
    if (model_.gravity.squaredNorm() > 0.0) {
        ++counters_.gravity_terms;
        // Weight m g at the centre of mass η = R R^r η*: moment m η × g, δ(η × g) = g̃ η̃ δψ.
        const Vec3 eta = R * (qp.Rr * qp.eta_star);
        f.head<3>() += lambda_ * qp.mass * model_.gravity;
        f.tail<3>() += lambda_ * qp.mass * eta.cross(model_.gravity);
        if (jacobian) {
            df_dpsi.bottomRows<3>() +=
                lambda_ * qp.mass * so3::skew(model_.gravity) * so3::skew(eta);
        }
    }
}

// The inertial force of the steady rotating frame at quadrature point qp (zero without one): the
// point's position and section frame from the element's nodes (its δx = Σ N_b δu_b, its
// δθ = Σ A_b δψ_b as for every other term of the point).
template <param::RotationParameterization P>
RotatingFrameForces DisplacementStatics<P>::rotating_frame_forces(const MeshElement& e,
                                                                  const QuadraturePoint& qp,
                                                                  const double* N, const Mat3& R) {
    if (!spin_forces_ || !model_.rotating_frame.active()) return {};
    Vec3 x = Vec3::Zero();
    for (size_t j = 0; j < e.nodes.size(); ++j) x += N[j] * (mesh_.nodes[e.nodes[j]].x0 + ue_[j]);
    const RotatingFrame& f = model_.rotating_frame;
    return calculate_rotating_frame_forces(qp.M_star, R * qp.Rr, x - f.center, f.angular_velocity,
                                           lambda_);
}

template <param::RotationParameterization P>
void DisplacementStatics<P>::assemble_element(int k, VecX& r, SparseMatrix* J) {
    const MeshElement& e = mesh_.elements[k];
    const int nn = static_cast<int>(e.nodes.size());
    const bool jac = J != nullptr;
    const bool loads = !model_.distributed_loads.empty() || !model_.load_fields.empty() ||
                       model_.gravity.squaredNorm() > 0.0;
    const bool spinning = spin_forces_ && model_.rotating_frame.active();
    gather_element(e, jac);
    InterpolatedRotation<P> rot;
    Vec6 f_ext = Vec6::Zero();
    Eigen::Matrix<double, 6, 3> df_ext = Eigen::Matrix<double, 6, 3>::Zero();
    for (int q = 0; q < static_cast<int>(e.qp.size()); ++q) {
        const QuadraturePoint& qp = e.qp[q];
        const double* N = e.N.col(q).data();
        const double* dN = e.dN.col(q).data();
        if (relative_) {
            interpolate_relative<P>(pe_.data(), N, dN, nn, R0_, rot);
        } else {
            interpolate_rotation<P>(pe_.data(), N, dN, nn, rot);
        }
        Vec3 up = Vec3::Zero();
        for (int j = 0; j < nn; ++j) up += dN[j] * ue_[j];
        const Vec3 xp = qp.x0_prime + up;
        const Vec6 strain = calculate_strain(qp.x0_prime, up, rot.R, rot.kappa);
        const Mat6 C = rotate_section(qp.C_star, rot.R * qp.Rr);
        const ElasticForces F = calculate_elastic_forces(C, strain, xp);
        ++counters_.elastic_terms;
        if (loads) distributed_load(e, qp, rot.R, jac, f_ext, df_ext);
        const RotatingFrameForces spin = rotating_frame_forces(e, qp, N, rot.R);
        for (int a = 0; a < nn; ++a) {
            const int d = mesh_.nodes[e.nodes[a]].dof;
            if (d < 0) continue;
            r.segment<6>(d) += qp.weight * (dN[a] * F.FE1 - N[a] * f_ext);
            r.segment<3>(d + 3) += qp.weight * N[a] * F.FE2;
            if (spinning) r.segment<6>(d) += qp.weight * N[a] * spin.F;
        }
        if (!jac) {
            if (absent_motion_) assemble_rest_terms(k, q, rot, xp, r, nullptr);
            continue;
        }
        // solver.mip: the geometric part from the predicted resultants (mip_stresses.hpp).
        const int g = mip_.enabled() ? mip_.first_point(k) + q : -1;
        const Mat3 Q = mip_.enabled() ? Mat3(rot.R * qp.Rr) : Mat3::Identity();
        const Vec6 F_geometric = mip_.enabled() ? mip_.geometric_force(g, Q, F.FE1) : F.FE1;
        const StiffnessBlocks B = calculate_stiffness_blocks(C, F_geometric, xp, rot.kappa);
        const param::Tangent<P::kSize> T = curvature_tangent<P>(rot);
        for (int b = 0; b < nn; ++b) rotation_maps<P>(rot, T, Me_[b], N[b], dN[b], A_[b], K_[b]);
        if (relative_) relative_maps(R0_, rot.kappa, nn, A_.data(), K_.data());
        for (int b = 0; b < nn; ++b) {
            D_[b].leftCols<3>() = C.leftCols<3>() * dN[b];
            D_[b].rightCols<3>() = C.rightCols<3>() * K_[b] + B.O * A_[b];
            E_[b].leftCols<3>() = B.Pu * dN[b];
            E_[b].rightCols<3>() = B.Pk * K_[b] + B.Qp * A_[b];
        }
        if (mip_.enabled()) record_mip_maps(g, Q, F.FE1, F_geometric, nn);
        for (int a = 0; a < nn; ++a) {
            if (mesh_.nodes[e.nodes[a]].dof < 0) continue;
            for (int b = 0; b < nn; ++b) {
                if (mesh_.nodes[e.nodes[b]].dof < 0) continue;
                Mat6 blk = qp.weight * dN[a] * D_[b];
                blk.bottomRows<3>() += qp.weight * N[a] * E_[b];
                if (loads) blk.rightCols<3>() -= qp.weight * N[a] * df_ext * A_[b];
                if (spinning) {
                    blk.leftCols<3>() += qp.weight * N[a] * N[b] * spin.dF_dx;
                    blk.rightCols<3>() += qp.weight * N[a] * spin.dF_dtheta * A_[b];
                }
                add_block(*J, k, a, b, blk);
            }
        }
        if (absent_motion_) assemble_rest_terms(k, q, rot, xp, r, J);
    }
}

// S_b = D_b without the resultants' own rotation (the geometric −F̃ of O): the material part of
// δF^E1 (mip_stresses.hpp).
template <param::RotationParameterization P>
void DisplacementStatics<P>::record_mip_maps(int g, const Mat3& Q, const Vec6& FE1,
                                             const Vec6& F_geometric, int nn) {
    Eigen::Matrix<double, 6, 3> geometric;
    geometric.topRows<3>() = so3::skew(F_geometric.head<3>());
    geometric.bottomRows<3>() = so3::skew(F_geometric.tail<3>());
    for (int b = 0; b < nn; ++b) {
        Mat6 S = D_[b];
        S.rightCols<3>().noalias() += geometric * A_[b];
        mip_.record(g, Q, FE1, b, S);
    }
}

template <param::RotationParameterization P>
void DisplacementStatics<P>::add_block(SparseMatrix& J, int element, int a, int b,
                                       const Mat6& block) const {
    const int nn = static_cast<int>(mesh_.elements[element].nodes.size());
    const int* idx = &block_index_[element][(a * nn + b) * 6];
    double* v = J.valuePtr();
    for (int c = 0; c < 6; ++c) {
        for (int i = 0; i < 6; ++i) v[idx[c] + i] += block(i, c);
    }
}

// Point loads: r_a −= λ f (dead) or λ R f0 (follower, with the load stiffness +λ (R f0)~).
template <param::RotationParameterization P>
void DisplacementStatics<P>::assemble_point_loads(VecX& r, SparseMatrix* J) {
    for (const NodeLoad& l : point_loads_) {
        const int d = mesh_.nodes[l.node].dof;
        if (d < 0) continue;
        const double lambda = lambda_ * l.factor;
        if (!l.follower) {
            r.segment<3>(d) -= lambda * l.force;
            r.segment<3>(d + 3) -= lambda * l.moment;
            if (absent_load_stiffness_ && J != nullptr) {
                const Mat3 R = P::matrix(p_[l.node]);
                add_load_stiffness(l.node, lambda * (R * l.force), lambda * (R * l.moment), 0.0,
                                   *J);
            }
            continue;
        }
        const Mat3 R = P::matrix(p_[l.node]);
        const Vec3 f = lambda * (R * l.force);
        const Vec3 m = lambda * (R * l.moment);
        r.segment<3>(d) -= f;
        r.segment<3>(d + 3) -= m;
        if (J != nullptr) add_load_stiffness(l.node, f, m, 1.0, *J);
    }
}

template <param::RotationParameterization P>
void DisplacementStatics<P>::add_load_stiffness(int node, const Vec3& f, const Vec3& m,
                                                double factor, SparseMatrix& J) {
    ++counters_.follower_stiffness;
    const Mat3 ft = factor * so3::skew(f);
    const Mat3 mt = factor * so3::skew(m);
    double* v = J.valuePtr();
    const int* idx = &diagonal_index_[static_cast<size_t>(node) * 6];
    for (int c = 0; c < 3; ++c) {
        for (int i = 0; i < 3; ++i) {
            v[idx[3 + c] + i] += ft(i, c);
            v[idx[3 + c] + 3 + i] += mt(i, c);
        }
    }
}

}  // namespace rotbeam::form
