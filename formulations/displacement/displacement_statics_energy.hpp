// DisplacementStatics<P>: the potential energy of the discretized beam, its gradient and its
// Hessian — what the stability of a static equilibrium is read from (core/static_stability.hpp,
// docs/solver-convergence.md, Stability of the equilibrium). Included only by
// displacement_statics.cpp.
//
// The energy is U_h = Σ_q w_q ½ Eᵀ C* E (material strains E = 𝓡ᵀ [ε; κ] of the interpolated
// fields, 𝓡 = diag(R R^r, R R^r)) minus the potential of the conservative loads (dead forces,
// gravity with its centre-of-mass offset).
//
// One energy for every parameterization: U_h interpolates the nodal rotations as the quaternion
// does (interpolate_rotation.hpp, with the run's `relative` or `direct` strategy), whatever P the
// nodes are stored in, so it is a function of the nodal displacements and rotations R_j alone and
// its Hessian along exp(ψ) R_j is the same matrix in every parameterization. Interpolated in P
// itself it is not: P's field R(s) between nodes is another function of the same R_j, and its
// second derivative across a planar state is large where P's chart is curved. Measured on the
// BeamDyn gravity cantilever (one element of order 5, tip rotation 1.54 rad about y: the Euler
// angles' middle angle 0.03 rad from gimbal lock): the Euler angles and the rotation vector
// interpolate the planar state alike (same equilibrium to 10 digits, same energy −360.9503), it
// is a stationary point of both energies (scaled gradient 1e-10, equal to central differences of
// the energy to 1e-9), yet the smallest eigenvalue of the scaled Hessian is −18.8 in the Euler
// angles and +6.2 in the rotation vector (largest 3.2e6, difference errors 2e-8 and 8e-12): the
// Euler-angle discrete energy has a saddle there that the beam has not (docs/solver-convergence.md,
// Stability of the equilibrium). The quaternion interpolation has no singular set and is the
// default parameterization's.
//
// Its exact variation with respect to a node's spatial increment δψ_a tests with the variation
// of the interpolated rotation, δψ(s) = Σ A_a δψ_a and δκ(s) = Σ K_a δψ_a, so that
//   ∂U_h/∂u_a = Σ w N_a′ N,    ∂U_h/∂ψ_a = Σ w [A_aᵀ (N × x′) + (K_a + κ̃ A_a)ᵀ M]
// (δE = 𝓡ᵀ [δε − δψ × ε; δκ − δψ × κ], δε = δu′ + (R x^r′) × δψ). The residual the Newton solve
// drives to zero tests with the interpolated spin instead, A_a = N_a I and K_a + κ̃ A_a = N_a′ I
// (a Petrov–Galerkin weak form), in P's interpolation: its Jacobian is not this Hessian and is
// not symmetric at its own equilibrium.
//
// The Hessian is formed element by element: the element's energy gradient is differentiated by
// central differences along the retraction q ← exp(h e_k) ⊗ q of each of its nodes' unknowns
// (the second derivatives of the rotation interpolation are not available in closed form). That
// matrix J_e differs from the Hessian of U_h in the chart ψ ↦ exp(ψ) R (normal coordinates of
// the bi-invariant metric on SO(3)) only by the commutator of two increments of one node,
// ½ g_a·(δψ × Δψ), which is antisymmetric: the Hessian is the symmetric part of J_e. Between two
// different nodes increments commute, so the asymmetry of J_e's off-diagonal node blocks is
// the difference error alone, and measures it.
#pragma once

#include <cmath>
#include <limits>
#include <type_traits>
#include <vector>

#include "core/errors.hpp"
#include "core/so3.hpp"
#include "formulations/displacement/calculate_elastic_forces.hpp"
#include "formulations/displacement/calculate_strain.hpp"
#include "formulations/displacement/displacement_statics.hpp"
#include "formulations/displacement/rotate_section.hpp"
#include "parameterizations/quaternion.hpp"

namespace rotbeam::form {

// Why U_h is not the potential of the current loads (empty: it is).
template <param::RotationParameterization P>
std::string DisplacementStatics<P>::no_potential_reason() const {
    if (model_.rotating_frame.active())
        return "a rotating frame: its inertial forces are not in the potential";
    return non_conservative_load_reason();
}

// Why the loads (the frame's aside) have no potential (empty: they have one).
template <param::RotationParameterization P>
std::string DisplacementStatics<P>::non_conservative_load_reason() const {
    for (const NodeLoad& l : point_loads_) {
        if (l.follower) return "follower loads: not conservative, no potential energy";
        if (l.moment.squaredNorm() > 0.0) {
            return "a dead moment: its virtual work m·δψ has no potential for 3-D rotations (not "
                   "conservative)";
        }
    }
    for (const DistributedLoad& l : model_.distributed_loads) {
        if (l.frame == LoadFrame::follower)
            return "follower loads: not conservative, no potential energy";
        if (l.moment.squaredNorm() > 0.0) {
            return "a dead distributed moment: no potential for 3-D rotations (not conservative)";
        }
    }
    return {};
}

// Element k's energy (elastic minus the distributed conservative loads) and its gradient with
// respect to [δu_a; δψ_a] of every element node (constrained ones too), at the current state.
// Returns false when a load field carries a moment (no potential).
template <param::RotationParameterization P>
bool DisplacementStatics<P>::element_energy(int k, double& energy, VecX& gradient) {
    using Q = param::Quaternion;
    const MeshElement& e = mesh_.elements[k];
    const int nn = static_cast<int>(e.nodes.size());
    // The nodes' quaternions (the stored ones when P is the quaternion), aligned or relative as
    // interpolate_rotation.hpp interpolates them, and their H_s⁺.
    std::vector<param::Params<4>> qe(nn);
    std::vector<param::TangentInverse<4>> Mq(nn);
    for (int j = 0; j < nn; ++j) {
        ue_[j] = u_[e.nodes[j]];
        if constexpr (std::is_same_v<P, Q>) {
            qe[j] = p_[e.nodes[j]];
        } else {
            qe[j] = Q::from_matrix(P::matrix(p_[e.nodes[j]]));
        }
    }
    Mat3 R0 = Mat3::Identity();
    if (relative_) {
        R0 = Q::matrix(qe[0]);
        relative_parameters<Q>(qe.data(), nn, qe.data());
    } else {
        for (int j = 1; j < nn; ++j) qe[j] *= chart_sign<Q>(qe[j], qe[0]);
    }
    for (int j = 0; j < nn; ++j) Mq[j] = Q::spatial_tangent_inverse(qe[j]);
    energy = 0.0;
    gradient.setZero(6 * nn);
    for (int q = 0; q < static_cast<int>(e.qp.size()); ++q) {
        const QuadraturePoint& qp = e.qp[q];
        const double* N = e.N.col(q).data();
        const double* dN = e.dN.col(q).data();
        InterpolatedRotation<Q> rot;
        if (relative_) {
            interpolate_relative<Q>(qe.data(), N, dN, nn, R0, rot);
        } else {
            interpolate_rotation<Q>(qe.data(), N, dN, nn, rot);
        }
        Vec3 up = Vec3::Zero();
        Vec3 u = Vec3::Zero();
        for (int j = 0; j < nn; ++j) {
            up += dN[j] * ue_[j];
            u += N[j] * ue_[j];
        }
        const Vec3 xp = qp.x0_prime + up;
        const Vec6 strain = calculate_strain(qp.x0_prime, up, rot.R, rot.kappa);
        const ElasticForces F =
            calculate_elastic_forces(rotate_section(qp.C_star, rot.R * qp.Rr), strain, xp);
        // Conservative distributed loads: a force density f (potential −f·u) and a moment about
        // the point, m_c, from a force at an offset (gravity at the centre of mass η).
        Vec3 f = Vec3::Zero();
        Vec3 m_c = Vec3::Zero();
        double load_potential = 0.0;
        for (size_t i = 0; i < model_.distributed_loads.size(); ++i) {
            const DistributedLoad& l = model_.distributed_loads[i];
            if (l.member == e.member) f += lambda_ * distributed_factor_[i] * l.force;
        }
        for (const LoadField& l : model_.load_fields) {
            if (l.member != e.member) continue;
            Vec3 force, moment;
            l.evaluate(qp.s, lambda_, time_, force, moment);
            if (moment.squaredNorm() > 0.0) return false;
            f += force;
        }
        if (model_.gravity.squaredNorm() > 0.0) {
            const Vec3 weight = lambda_ * qp.mass * model_.gravity;
            const Vec3 eta = rot.R * (qp.Rr * qp.eta_star);
            const Vec3 eta0 = qp.Rr * qp.eta_star;
            f += weight;
            m_c += eta.cross(weight);
            load_potential -= weight.dot(eta - eta0);
        }
        load_potential -= f.dot(u);
        energy += qp.weight * (0.5 * strain.dot(F.FE1) + load_potential);
        const param::Tangent<4> T = curvature_tangent<Q>(rot);
        for (int b = 0; b < nn; ++b) rotation_maps<Q>(rot, T, Mq[b], N[b], dN[b], A_[b], K_[b]);
        if (relative_) relative_maps(R0, rot.kappa, nn, A_.data(), K_.data());
        const Mat3 kt = so3::skew(rot.kappa);
        for (int a = 0; a < nn; ++a) {
            gradient.segment<3>(6 * a) += qp.weight * (dN[a] * F.FE1.head<3>() - N[a] * f);
            gradient.segment<3>(6 * a + 3) +=
                qp.weight * (A_[a].transpose() * (F.FE2 - m_c) +
                             (K_[a] + kt * A_[a]).transpose() * F.FE1.tail<3>());
        }
    }
    return true;
}

template <param::RotationParameterization P>
std::optional<double> DisplacementStatics<P>::potential_energy() {
    if (!no_potential_reason().empty()) return std::nullopt;
    double total = 0.0;
    VecX g;
    for (int k = 0; k < static_cast<int>(mesh_.elements.size()); ++k) {
        double energy = 0.0;
        if (!element_energy(k, energy, g)) return std::nullopt;
        total += energy;
    }
    for (const NodeLoad& l : point_loads_) total -= lambda_ * l.factor * l.force.dot(u_[l.node]);
    return total;
}

template <param::RotationParameterization P>
bool DisplacementStatics<P>::potential_gradient(VecX& g) {
    if (!no_potential_reason().empty()) return false;
    g.setZero(mesh_.unknowns);
    VecX ge;
    for (int k = 0; k < static_cast<int>(mesh_.elements.size()); ++k) {
        double energy = 0.0;
        if (!element_energy(k, energy, ge)) return false;
        const MeshElement& e = mesh_.elements[k];
        for (size_t a = 0; a < e.nodes.size(); ++a) {
            const int d = mesh_.nodes[e.nodes[a]].dof;
            if (d >= 0) g.segment<6>(d) += ge.segment<6>(6 * static_cast<int>(a));
        }
    }
    for (const NodeLoad& l : point_loads_) {
        const int d = mesh_.nodes[l.node].dof;
        if (d >= 0) g.segment<3>(d) -= lambda_ * l.factor * l.force;
    }
    return true;
}

// The Hessian's chart: u + δu, and p ← exp(δψ) ⊗ p as its columns perturb the nodes (no
// rescaling, which would not change R). All new parameters are computed before any is stored.
template <param::RotationParameterization P>
void DisplacementStatics<P>::move_along_potential_chart(const Eigen::Ref<const VecX>& dx) {
    std::vector<Params> moved = p_;
    for (size_t i = 0; i < mesh_.nodes.size(); ++i) {
        const int d = mesh_.nodes[i].dof;
        if (d < 0) continue;
        moved[i] = P::compose(P::from_rotation_vector(dx.segment<3>(d + 3)), p_[i]);
        if constexpr (P::kSize == 4) moved[i].normalize();
    }
    for (size_t i = 0; i < mesh_.nodes.size(); ++i) {
        const int d = mesh_.nodes[i].dof;
        if (d >= 0) u_[i] += dx.segment<3>(d);
    }
    p_ = std::move(moved);
    mip_.drop();
}

// Element by element: column (b, c) of J_e from the element gradient at the node's state moved
// by ±h along unknown c (h = ε^(1/3) of its increment scale: the central difference's truncation
// and round-off errors balance there, ~ε^(2/3) of the entries), the node restored bit for bit.
// The dead point forces' potential is linear in u: no Hessian.
template <param::RotationParameterization P>
PotentialHessian DisplacementStatics<P>::potential_hessian() {
    PotentialHessian out;
    out.unavailable = no_potential_reason();
    if (!out.unavailable.empty()) return out;
    SparseMatrix& H = out.matrix;
    H = pattern_;
    std::fill(H.valuePtr(), H.valuePtr() + H.nonZeros(), 0.0);
    const double h0 = std::cbrt(std::numeric_limits<double>::epsilon());
    VecX plus, minus, plus2, minus2;
    double asymmetry = 0.0;
    double difference = 0.0;
    for (int k = 0; k < static_cast<int>(mesh_.elements.size()); ++k) {
        const MeshElement& e = mesh_.elements[k];
        const int nn = static_cast<int>(e.nodes.size());
        Eigen::MatrixXd Je = Eigen::MatrixXd::Zero(6 * nn, 6 * nn);
        Eigen::MatrixXd Je2 = Eigen::MatrixXd::Zero(6 * nn, 6 * nn);
        Eigen::VectorXd scale = Eigen::VectorXd::Zero(6 * nn);
        for (int b = 0; b < nn; ++b) {
            const int node = e.nodes[b];
            const int d = mesh_.nodes[node].dof;
            if (d < 0) continue;
            const Vec3 u0 = u_[node];
            const Params p0 = p_[node];
            for (int c = 0; c < 6; ++c) {
                const double h = h0 * increment_scale_(d + c);
                scale(6 * b + c) = increment_scale_(d + c);
                double energy = 0.0;
                bool potential = true;
                try {
                    for (const double step : {h, -h, 2.0 * h, -2.0 * h}) {
                        if (c < 3) {
                            u_[node] = u0 + step * Vec3::Unit(c);
                        } else {
                            p_[node] =
                                P::compose(P::from_rotation_vector(step * Vec3::Unit(c - 3)), p0);
                        }
                        VecX& g = step == h    ? plus
                                  : step == -h ? minus
                                  : step > 0.0 ? plus2
                                               : minus2;
                        potential = potential && element_energy(k, energy, g);
                    }
                } catch (const SingularityError& error) {
                    u_[node] = u0;
                    p_[node] = p0;
                    out.unavailable = std::string(
                                          "the rotation chart is singular next to the "
                                          "state: ") +
                                      error.what();
                    return out;
                }
                u_[node] = u0;
                p_[node] = p0;
                if (!potential) {
                    out.unavailable = "a load field with a moment: no potential for 3-D rotations";
                    return out;
                }
                Je.col(6 * b + c) = (plus - minus) / (2.0 * h);
                Je2.col(6 * b + c) = (plus2 - minus2) / (4.0 * h);
            }
        }
        // Rows and columns of constrained nodes are left out (their scale stays 0).
        const Eigen::MatrixXd S = scale.asDiagonal() * Je * scale.asDiagonal();
        // The truncation error of the central difference, O(h²): the same difference at 2h moves
        // by three times it. Its bound enters the pivot threshold, so that a small eigenvalue's
        // sign is not taken from a difference that cannot resolve it.
        difference =
            std::max(difference,
                     (scale.asDiagonal() * (Je - Je2) * scale.asDiagonal()).cwiseAbs().maxCoeff());
        for (int a = 0; a < nn; ++a) {
            for (int b = 0; b < nn; ++b) {
                if (a == b) continue;
                asymmetry = std::max(asymmetry, (S.block<6, 6>(6 * a, 6 * b) -
                                                 S.block<6, 6>(6 * b, 6 * a).transpose())
                                                    .cwiseAbs()
                                                    .maxCoeff());
            }
        }
        const Eigen::MatrixXd Hs = 0.5 * (Je + Je.transpose());
        for (int a = 0; a < nn; ++a) {
            if (mesh_.nodes[e.nodes[a]].dof < 0) continue;
            for (int b = 0; b < nn; ++b) {
                if (mesh_.nodes[e.nodes[b]].dof < 0) continue;
                add_block(H, k, a, b, Hs.block<6, 6>(6 * a, 6 * b));
            }
        }
    }
    out.scaled_error = std::max(asymmetry, difference);
    return out;
}

}  // namespace rotbeam::form
