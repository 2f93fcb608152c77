// DisplacementDynamics<P>: residual and iteration matrix (the static part from
// DisplacementStatics, the inertial and damping parts here), energy and support reactions.
// Included only by displacement_dynamics.cpp. Kernel chain per point: interpolate_rotation →
// calculate_inertial_blocks (mass points; calculate_inertial_force, the same F^I without the
// tangent blocks, for a residual alone) / calculate_damping_blocks (stiffness points).
#pragma once

#include "core/so3.hpp"
#include "formulations/displacement/calculate_damping_forces.hpp"
#include "formulations/displacement/calculate_elastic_forces.hpp"
#include "formulations/displacement/calculate_inertial_forces.hpp"
#include "formulations/displacement/calculate_strain.hpp"
#include "formulations/displacement/displacement_dynamics.hpp"
#include "formulations/displacement/rotate_section.hpp"
#include "formulations/displacement/rotation_columns.hpp"

namespace rotbeam::form {

template <param::RotationParameterization P>
void DisplacementDynamics<P>::evaluate(VecX& r, SparseMatrix* J) {
    statics_.evaluate(r, J);
    if (J != nullptr) {
        for (size_t i = 0; i < mesh().nodes.size(); ++i) {
            const int d = mesh().nodes[i].dof;
            if (d >= 0) T_[i] = param::RotationVector::spatial_tangent(delta_.segment<3>(d + 3));
        }
        apply_exp_tangent(*J);
    }
    assemble_inertia(r, J, 1.0, cv_, ca_);
    if (damped_) assemble_damping(r, J, 1.0, cv_);
}

template <param::RotationParameterization P>
void DisplacementDynamics<P>::stage_matrices(const Eigen::Ref<const VecX>& delta,
                                             const Eigen::Ref<const VecX>& v,
                                             const Eigen::Ref<const VecX>& v_dot, double t, VecX& r,
                                             SparseMatrix& K, SparseMatrix& C, SparseMatrix& M) {
    set_stage(delta, v, v_dot, t, 0.0, 0.0);
    evaluate(r, &K);
    for (SparseMatrix* X : {&C, &M}) {
        if (X->nonZeros() != K.nonZeros()) *X = K;  // the first call: K's pattern
        std::fill(X->valuePtr(), X->valuePtr() + X->nonZeros(), 0.0);
    }
    rate_residual_.setZero(size());
    assemble_inertia(rate_residual_, &C, 0.0, 1.0, 0.0);
    if (damped_) assemble_damping(rate_residual_, &C, 0.0, 1.0);
    assemble_inertia(rate_residual_, &M, 0.0, 0.0, 1.0);
}

// J's rotation columns of node i times T_i = dexp(ψ_i): δθ_i = T_i δψ_i.
template <param::RotationParameterization P>
void DisplacementDynamics<P>::apply_exp_tangent(SparseMatrix& J) const {
    right_multiply_rotation_columns(J, mesh(), [&](size_t i) { return T_[i]; });
}

// Nodal parameters of element e as the interpolation needs them (DisplacementStatics::
// gather_element): relative to the first node (R0_) or sign-aligned; M_j = H_s⁺.
template <param::RotationParameterization P>
void DisplacementDynamics<P>::gather(const MeshElement& e, PointNeeds needs) {
    const int nn = static_cast<int>(e.nodes.size());
    for (int j = 0; j < nn; ++j) pe_[j] = statics_.node_rotation(e.nodes[j]);
    if (statics_.relative_interpolation()) {
        R0_ = P::matrix(pe_[0]);
        relative_parameters<P>(pe_.data(), nn, pe_.data());
    } else {
        for (int j = 1; j < nn; ++j) pe_[j] *= chart_sign<P>(pe_[j], pe_[0]);
    }
    if (needs == PointNeeds::rotation) return;
    for (int j = 0; j < nn; ++j) Me_[j] = P::spatial_tangent_inverse(pe_[j]);
}

// interpolate_relative / interpolate_rotation, or with PointNeeds::rotation R alone by the same
// arithmetic (interpolated_rotation_matrix, then R_0 R for the relative strategy).
template <param::RotationParameterization P>
void DisplacementDynamics<P>::interpolate(const MeshElement& e, int q, InterpolatedRotation<P>& rot,
                                          PointNeeds needs) const {
    const int nn = static_cast<int>(e.nodes.size());
    if (needs == PointNeeds::rotation) {
        rot.R = interpolated_rotation_matrix<P>(pe_.data(), e.N.col(q).data(), nn);
        if (statics_.relative_interpolation()) rot.R = R0_ * rot.R;
        return;
    }
    if (statics_.relative_interpolation()) {
        interpolate_relative<P>(pe_.data(), e.N.col(q).data(), e.dN.col(q).data(), nn, R0_, rot);
    } else {
        interpolate_rotation<P>(pe_.data(), e.N.col(q).data(), e.dN.col(q).data(), nn, rot);
    }
}

template <param::RotationParameterization P>
template <class Point>
void DisplacementDynamics<P>::for_each_point(const std::vector<MeshElement>& elements,
                                             Point&& point, PointNeeds needs) {
    for (int k = 0; k < static_cast<int>(elements.size()); ++k) {
        const MeshElement& e = elements[k];
        gather(e, needs);
        InterpolatedRotation<P> rot;
        for (int q = 0; q < static_cast<int>(e.qp.size()); ++q) {
            interpolate(e, q, rot, needs);
            point(k, e, q, rot);
        }
    }
}

// Σ_q w N_a F^I on the mass rule's points; block (a, b) of the iteration matrix:
//   w N_a N_b (cv G^I + ca M) + kq w N_a K^I [0, 0; 0, A_b T_b],
// A_b the spin map δθ(s) = Σ A_b δθ_b of the interpolation (K^I has no δu columns). Without the
// ∂/∂q columns (no J, or kq = 0) the kernel reads the interpolated rotation R alone.
template <param::RotationParameterization P>
void DisplacementDynamics<P>::assemble_inertia(VecX& r, SparseMatrix* J, double kq, double cv,
                                               double ca) {
    const bool relative = statics_.relative_interpolation();
    const PointNeeds needs =
        J != nullptr && kq != 0.0 ? PointNeeds::everything : PointNeeds::rotation;
    const auto point = [&](int k, const MeshElement& e, int q, const InterpolatedRotation<P>& rot) {
        const int nn = static_cast<int>(e.nodes.size());
        const QuadraturePoint& qp = e.qp[q];
        const double* N = e.N.col(q).data();
        InertialState s;
        s.Q = rot.R * qp.Rr;
        s.u_ddot.setZero();
        s.omega.setZero();
        s.omega_dot.setZero();
        Vec3 v_u = Vec3::Zero(), x = Vec3::Zero();
        for (int j = 0; j < nn; ++j) {
            s.u_ddot += N[j] * vd_[e.nodes[j]].head<3>();
            s.omega += N[j] * v_[e.nodes[j]].tail<3>();
            s.omega_dot += N[j] * vd_[e.nodes[j]].tail<3>();
            if (spinning_) {
                v_u += N[j] * v_[e.nodes[j]].head<3>();
                x += N[j] * (mesh().nodes[e.nodes[j]].x0 + statics_.node_displacement(e.nodes[j]));
            }
        }
        add_frame_motion(s, v_u, x);
        ++inertial_terms_;
        const auto add_force = [&](const Vec6& F) {
            for (int a = 0; a < nn; ++a) {
                const int d = mesh().nodes[e.nodes[a]].dof;
                if (d >= 0) r.segment<6>(d) += qp.weight * N[a] * F;
            }
        };
        // A residual alone (the stage iterations' evaluations): F^I without its tangent blocks.
        if (J == nullptr) {
            add_force(calculate_inertial_force(qp.M_star, s));
            return;
        }
        const InertialBlocks B = calculate_inertial_blocks(qp.M_star, s);
        add_force(B.F);
        if (kq != 0.0) {
            Mat3 sum = Mat3::Zero();
            for (int b = 0; b < nn; ++b) {
                A_[b] = N[b] * rot.Hs * Me_[b];
                if (relative) A_[b] = R0_ * A_[b] * R0_.transpose();
                sum += A_[b];
            }
            if (relative) A_[0] += Mat3::Identity() - sum;
        }
        Mat6 GM = cv * B.G + ca * B.M;
        if (spinning_) {
            // Coriolis through v_u and ω, centrifugal through the position (header comment).
            GM.leftCols<3>() +=
                (2.0 * cv) * B.M.leftCols<3>() * W_ + kq * B.M.leftCols<3>() * W_ * W_;
            GM.rightCols<3>() += cv * B.M.rightCols<3>() * W_;
        }
        for (int a = 0; a < nn; ++a) {
            if (mesh().nodes[e.nodes[a]].dof < 0) continue;
            for (int b = 0; b < nn; ++b) {
                if (mesh().nodes[e.nodes[b]].dof < 0) continue;
                Mat6 blk = (qp.weight * N[a] * N[b]) * GM;
                if (kq != 0.0) {
                    blk.rightCols<3>() +=
                        (kq * qp.weight * N[a]) * B.K.rightCols<3>() * A_[b] * T_[e.nodes[b]];
                }
                statics_.add_block(*J, k, a, b, blk);
            }
        }
    };
    for_each_point(mass_mesh_.elements, point, needs);
}

// Σ_q w (N_a′ F^D1 + N_a F^D2) on the stiffness points (seed 000 Eq. 10, errata). Nodal columns
// of node b: δv = cv N_b, δv′ = cv N_b′, δq = [N_b I, 0; 0, A_b T_b],
// δq′ = [N_b′ I, 0; 0, (K_b + κ̃ A_b) T_b] (δθ′ = δκ + κ̃ δθ, δκ = Σ K_b δθ_b).
// Long for the same reason as DisplacementStatics::assemble_element: gather, kernel, scatter.
template <param::RotationParameterization P>
void DisplacementDynamics<P>::assemble_damping(VecX& r, SparseMatrix* J, double kq, double cv) {
    const bool relative = statics_.relative_interpolation();
    for_each_point(mesh().elements, [&](int k, const MeshElement& e, int q,
                                        const InterpolatedRotation<P>& rot) {
        const int nn = static_cast<int>(e.nodes.size());
        const QuadraturePoint& qp = e.qp[q];
        const double* N = e.N.col(q).data();
        const double* dN = e.dN.col(q).data();
        DampingState s;
        s.D = rotate_section(qp.D_star, rot.R * qp.Rr);
        Vec3 up = Vec3::Zero();
        for (int j = 0; j < nn; ++j) {
            const int node = e.nodes[j];
            up += dN[j] * statics_.node_displacement(node);
            s.omega += N[j] * v_[node].tail<3>();
            s.omega_prime += dN[j] * v_[node].tail<3>();
            s.u_dot_prime += dN[j] * v_[node].head<3>();
        }
        s.x_prime = qp.x0_prime + up;
        s.Rx0p = rot.R * qp.x0_prime;
        s.kappa = rot.kappa;
        const DampingBlocks B = calculate_damping_blocks(s);
        ++damping_terms_;
        for (int a = 0; a < nn; ++a) {
            const int d = mesh().nodes[e.nodes[a]].dof;
            if (d >= 0) r.segment<6>(d) += qp.weight * (dN[a] * B.F1 + N[a] * B.F2);
        }
        if (J == nullptr) return;
        const param::Tangent<P::kSize> T = curvature_tangent<P>(rot);
        for (int b = 0; b < nn; ++b) rotation_maps<P>(rot, T, Me_[b], N[b], dN[b], A_[b], K_[b]);
        if (relative) relative_maps(R0_, rot.kappa, nn, A_.data(), K_.data());
        const Mat3 kt = so3::skew(rot.kappa);
        for (int b = 0; b < nn; ++b) {
            const Mat3& Tb = T_[e.nodes[b]];
            const Mat3 At = A_[b] * Tb;
            const Mat3 Kt = (K_[b] + kt * A_[b]) * Tb;
            X1_[b] = cv * (dN[b] * B.D1 + N[b] * B.G1);
            X2_[b] = cv * (dN[b] * B.D2 + N[b] * B.G2);
            if (kq == 0.0) continue;
            X1_[b].leftCols<3>() += kq * (dN[b] * B.P1.leftCols<3>() + N[b] * B.K1.leftCols<3>());
            X1_[b].rightCols<3>() += kq * (B.P1.rightCols<3>() * Kt + B.K1.rightCols<3>() * At);
            X2_[b].leftCols<3>() += kq * (dN[b] * B.P2.leftCols<3>() + N[b] * B.K2.leftCols<3>());
            X2_[b].rightCols<3>() += kq * (B.P2.rightCols<3>() * Kt + B.K2.rightCols<3>() * At);
        }
        for (int a = 0; a < nn; ++a) {
            if (mesh().nodes[e.nodes[a]].dof < 0) continue;
            for (int b = 0; b < nn; ++b) {
                if (mesh().nodes[e.nodes[b]].dof < 0) continue;
                const Mat6 blk = qp.weight * (dN[a] * X1_[b] + N[a] * X2_[b]);
                statics_.add_block(*J, k, a, b, blk);
            }
        }
    });
}

template <param::RotationParameterization P>
double DisplacementDynamics<P>::damping_dissipation() {
    double power = 0.0;
    for_each_point(mesh().elements,
                   [&](int, const MeshElement& e, int q, const InterpolatedRotation<P>& rot) {
                       const int nn = static_cast<int>(e.nodes.size());
                       Vec3 omega = Vec3::Zero(), omega_p = Vec3::Zero(), udot_p = Vec3::Zero();
                       for (int j = 0; j < nn; ++j) {
                           omega += e.N(j, q) * v_[e.nodes[j]].tail<3>();
                           omega_p += e.dN(j, q) * v_[e.nodes[j]].tail<3>();
                           udot_p += e.dN(j, q) * v_[e.nodes[j]].head<3>();
                       }
                       Vec6 rates;
                       rates.head<3>() = udot_p - omega.cross(rot.R * e.qp[q].x0_prime);
                       rates.tail<3>() = omega.cross(rot.kappa) + omega_p;
                       const Mat6 D = rotate_section(e.qp[q].D_star, rot.R * e.qp[q].Rr);
                       power += e.qp[q].weight * rates.dot(D * rates);
                   });
    return power;
}

template <param::RotationParameterization P>
void DisplacementDynamics<P>::external_load(VecX& f) {
    f.setZero(size());
    for (const PointLoad& l : model_.point_loads) {
        const int node = mesh().point_node[static_cast<size_t>(l.point)];
        const int d = mesh().nodes[node].dof;
        if (d < 0) continue;
        const double factor = l.time(time_);
        const Mat3 R = l.frame == LoadFrame::follower ? P::matrix(statics_.node_rotation(node))
                                                      : Mat3::Identity();
        f.segment<3>(d) += factor * (R * l.force);
        f.segment<3>(d + 3) += factor * (R * l.moment);
    }
    for_each_point(mesh().elements,
                   [&](int, const MeshElement& e, int q, const InterpolatedRotation<P>& rot) {
                       const QuadraturePoint& qp = e.qp[q];
                       Vec6 load = Vec6::Zero();
                       for (const DistributedLoad& l : model_.distributed_loads) {
                           if (l.member != e.member) continue;
                           const Mat3 R = l.frame == LoadFrame::follower ? rot.R : Mat3::Identity();
                           load.head<3>() += l.time(time_) * (R * l.force);
                           load.tail<3>() += l.time(time_) * (R * l.moment);
                       }
                       for (const LoadField& l : model_.load_fields) {
                           if (l.member != e.member) continue;
                           Vec3 force, moment;
                           l.evaluate(qp.s, 1.0, time_, force, moment);
                           load.head<3>() += force;
                           load.tail<3>() += moment;
                       }
                       if (gravity_.squaredNorm() > 0.0) {
                           const Vec3 eta = rot.R * (qp.Rr * qp.eta_star);
                           load.head<3>() += qp.mass * gravity_;
                           load.tail<3>() += qp.mass * eta.cross(gravity_);
                       }
                       for (int a = 0; a < static_cast<int>(e.nodes.size()); ++a) {
                           const int d = mesh().nodes[e.nodes[a]].dof;
                           if (d >= 0) f.segment<6>(d) += qp.weight * e.N(a, q) * load;
                       }
                   });
}

template <param::RotationParameterization P>
bool DisplacementDynamics<P>::energy_terms(EnergyTerms& terms) {
    const BeamEnergy E = energy();
    terms.energy = E.total() - omega_frame_.dot(E.angular_momentum);
    terms.potential = E.frame_kinetic;
    external_load(terms.load);
    terms.velocity.setZero(size());
    for (size_t i = 0; i < mesh().nodes.size(); ++i) {
        const int d = mesh().nodes[i].dof;
        if (d >= 0) terms.velocity.segment<6>(d) = v_[i];
    }
    terms.dissipation = damped_ ? damping_dissipation() : 0.0;
    return true;
}

// Kinetic energy on the mass points (the quadratic form of the assembled mass matrix), strain
// energy on the stiffness points. Both section matrices are X = T X* Tᵀ with T = diag(Q, Q)
// (rotate_mass, rotate_section), so each quadratic form is taken in the material frame, aᵀ X a =
// a*ᵀ X* a* with a* = Tᵀ a, and the momentum M v = T (M* v*): two rotations of a vector instead of
// the rotated 6 × 6 matrix (the energy is evaluated at every time step, for the energy balance).
template <param::RotationParameterization P>
BeamEnergy DisplacementDynamics<P>::energy() {
    BeamEnergy E;
    const auto material = [](const Mat3& Q, const Vec6& a) {
        Vec6 out;
        out.head<3>().noalias() = Q.transpose() * a.head<3>();
        out.tail<3>().noalias() = Q.transpose() * a.tail<3>();
        return out;
    };
    for_each_point(mass_mesh_.elements, [&](int, const MeshElement& e, int q,
                                            const InterpolatedRotation<P>& rot) {
        const int nn = static_cast<int>(e.nodes.size());
        Vec6 v = Vec6::Zero();
        Vec3 x = Vec3::Zero();
        for (int j = 0; j < nn; ++j) v += e.N(j, q) * v_[e.nodes[j]];
        const Mat3 Q = rot.R * e.qp[q].Rr;
        const Mat6& M_star = e.qp[q].M_star;
        if (!spinning_) {
            // The frame at rest: the velocity is absolute, and the angular momentum is not
            // reported (the energy balance weighs it by the frame's Ω = 0).
            const Vec6 v_star = material(Q, v);
            E.kinetic += 0.5 * e.qp[q].weight * v_star.dot(M_star * v_star);
            return;
        }
        for (int j = 0; j < nn; ++j) {
            x += e.N(j, q) * (mesh().nodes[e.nodes[j]].x0 + statics_.node_displacement(e.nodes[j]));
        }
        const Vec6 v_f = material(Q, absolute_velocity(Vec6::Zero(), x));
        E.frame_kinetic += 0.5 * e.qp[q].weight * v_f.dot(M_star * v_f);
        const Vec6 v_star = material(Q, absolute_velocity(v, x));
        const Vec6 momentum_star = M_star * v_star;
        E.kinetic += 0.5 * e.qp[q].weight * v_star.dot(momentum_star);
        const Vec3 linear = Q * momentum_star.head<3>();
        const Vec3 angular = Q * momentum_star.tail<3>();
        E.angular_momentum += e.qp[q].weight * ((x - center_).cross(linear) + angular);
    });
    for_each_point(mesh().elements, [&](int, const MeshElement& e, int q,
                                        const InterpolatedRotation<P>& rot) {
        const int nn = static_cast<int>(e.nodes.size());
        Vec3 up = Vec3::Zero();
        for (int j = 0; j < nn; ++j) up += e.dN(j, q) * statics_.node_displacement(e.nodes[j]);
        const Mat3 Q = rot.R * e.qp[q].Rr;
        const Vec6 strain = material(Q, calculate_strain(e.qp[q].x0_prime, up, rot.R, rot.kappa));
        E.strain += 0.5 * e.qp[q].weight * strain.dot(e.qp[q].C_star * strain);
    });
    return E;
}

template <param::RotationParameterization P>
double DisplacementDynamics<P>::frame_energy() {
    const BeamEnergy E = energy();
    return E.total() - omega_frame_.dot(E.angular_momentum);
}

// The residual rows a constrained node would have: its elements' elastic, damping and inertial
// terms minus distributed loads and gravity (point loads on a support are carried by it
// directly and are not included): the support's force and moment on the beam. One function,
// though long: it is the residual's chain (elastic, damping, loads, inertia) restricted to one
// row, and splitting it would hand the interpolated state between four functions.
template <param::RotationParameterization P>
Vec6 DisplacementDynamics<P>::reaction(int node) {
    Vec6 out = Vec6::Zero();
    InterpolatedRotation<P> rot;
    for (int k = 0; k < static_cast<int>(mesh().elements.size()); ++k) {
        const MeshElement& e = mesh().elements[k];
        const int nn = static_cast<int>(e.nodes.size());
        const auto it = std::find(e.nodes.begin(), e.nodes.end(), node);
        if (it == e.nodes.end()) continue;
        const int a = static_cast<int>(it - e.nodes.begin());
        gather(e);
        for (int q = 0; q < static_cast<int>(e.qp.size()); ++q) {
            const QuadraturePoint& qp = e.qp[q];
            interpolate(e, q, rot);
            Vec3 up = Vec3::Zero(), omega = Vec3::Zero(), omega_p = Vec3::Zero();
            Vec3 udot_p = Vec3::Zero();
            for (int j = 0; j < nn; ++j) {
                up += e.dN(j, q) * statics_.node_displacement(e.nodes[j]);
                omega += e.N(j, q) * v_[e.nodes[j]].tail<3>();
                omega_p += e.dN(j, q) * v_[e.nodes[j]].tail<3>();
                udot_p += e.dN(j, q) * v_[e.nodes[j]].head<3>();
            }
            const Vec3 xp = qp.x0_prime + up;
            const Mat3 Q = rot.R * qp.Rr;
            const Vec6 strain = calculate_strain(qp.x0_prime, up, rot.R, rot.kappa);
            const ElasticForces F =
                calculate_elastic_forces(rotate_section(qp.C_star, Q), strain, xp);
            out += qp.weight * e.dN(a, q) * F.FE1;
            out.tail<3>() += qp.weight * e.N(a, q) * F.FE2;
            if (damped_) {
                DampingState s;
                s.D = rotate_section(qp.D_star, Q);
                s.x_prime = xp;
                s.Rx0p = rot.R * qp.x0_prime;
                s.kappa = rot.kappa;
                s.omega = omega;
                s.omega_prime = omega_p;
                s.u_dot_prime = udot_p;
                const DampingBlocks B = calculate_damping_blocks(s);
                out += qp.weight * (e.dN(a, q) * B.F1 + e.N(a, q) * B.F2);
            }
            for (size_t l = 0; l < model_.distributed_loads.size(); ++l) {
                const DistributedLoad& d = model_.distributed_loads[l];
                if (d.member != e.member) continue;
                const double f = d.time(time_);
                const Mat3 R = d.frame == LoadFrame::follower ? rot.R : Mat3::Identity();
                out.head<3>() -= qp.weight * e.N(a, q) * f * (R * d.force);
                out.tail<3>() -= qp.weight * e.N(a, q) * f * (R * d.moment);
            }
            if (gravity_.squaredNorm() > 0.0) {
                const Vec3 eta = Q * qp.eta_star;
                out.head<3>() -= qp.weight * e.N(a, q) * qp.mass * gravity_;
                out.tail<3>() -= qp.weight * e.N(a, q) * qp.mass * eta.cross(gravity_);
            }
        }
        const MeshElement& em = mass_mesh_.elements[k];
        for (int q = 0; q < static_cast<int>(em.qp.size()); ++q) {
            interpolate(em, q, rot);
            InertialState s;
            s.Q = rot.R * em.qp[q].Rr;
            Vec3 v_u = Vec3::Zero(), x = Vec3::Zero();
            for (int j = 0; j < nn; ++j) {
                s.u_ddot += em.N(j, q) * vd_[em.nodes[j]].head<3>();
                s.omega += em.N(j, q) * v_[em.nodes[j]].tail<3>();
                s.omega_dot += em.N(j, q) * vd_[em.nodes[j]].tail<3>();
                v_u += em.N(j, q) * v_[em.nodes[j]].head<3>();
                x += em.N(j, q) *
                     (mesh().nodes[em.nodes[j]].x0 + statics_.node_displacement(em.nodes[j]));
            }
            add_frame_motion(s, v_u, x);
            out += em.qp[q].weight * em.N(a, q) * calculate_inertial_force(em.qp[q].M_star, s);
        }
    }
    return out;
}

}  // namespace rotbeam::form
