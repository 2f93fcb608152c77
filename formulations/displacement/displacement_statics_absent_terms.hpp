// DisplacementStatics<P> under solver.assemble_all_terms: the terms a static scene does not need,
// assembled as a formulation that ignores the scene would (included only by
// displacement_statics.cpp). At rest (u˙ = u¨ = ω = ω˙ = 0, zero strain rates) the inertial force
// F^I (calculate_inertial_forces.hpp) and the damping force F^D (seed 000 Eq. 10,
// calculate_damping_forces.hpp) vanish, and so do their stiffness blocks K^I, P^D, K^D; the mass
// M, gyroscopic G^I and damping D^D, G^D blocks enter a static Jacobian with zero velocity and
// acceleration coefficients. Every kernel is evaluated and every block scattered, so the cost is
// real and the result is the default's: exact zeros are added.
//
// The inertial kernel uses the stiffness quadrature here (the dynamics use the mass rule's): the
// point is the cost of evaluating and scattering the terms, not a mass matrix.
#pragma once

#include "formulations/displacement/calculate_damping_forces.hpp"
#include "formulations/displacement/calculate_inertial_forces.hpp"
#include "formulations/displacement/displacement_statics.hpp"
#include "formulations/displacement/rotate_section.hpp"

namespace rotbeam::form {

template <param::RotationParameterization P>
void DisplacementStatics<P>::assemble_rest_terms(int k, int q, const InterpolatedRotation<P>& rot,
                                                 const Vec3& xp, VecX& r, SparseMatrix* J) {
    // A static analysis: the generalized-α slopes of velocity and acceleration are zero.
    constexpr double kVelocityCoefficient = 0.0, kAccelerationCoefficient = 0.0;
    const MeshElement& e = mesh_.elements[k];
    const QuadraturePoint& qp = e.qp[q];
    const int nn = static_cast<int>(e.nodes.size());
    const double* N = e.N.col(q).data();
    const double* dN = e.dN.col(q).data();
    InertialState rest;
    rest.Q = rot.R * qp.Rr;
    const InertialBlocks I = calculate_inertial_blocks(qp.M_star, rest);
    DampingState still;
    still.D = rotate_section(qp.D_star, rest.Q);
    still.x_prime = xp;
    still.Rx0p = rot.R * qp.x0_prime;
    still.kappa = rot.kappa;
    const DampingBlocks B = calculate_damping_blocks(still);
    ++counters_.inertial_terms;
    ++counters_.damping_terms;
    for (int a = 0; a < nn; ++a) {
        const int d = mesh_.nodes[e.nodes[a]].dof;
        if (d >= 0) r.segment<6>(d) += qp.weight * (N[a] * (I.F + B.F2) + dN[a] * B.F1);
    }
    if (J == nullptr) return;
    // Block (a, b) as DisplacementDynamics::assemble_inertia / assemble_damping build it, with
    // A_b, K_b the nodal maps assemble_element left for this point.
    const Mat6 GM = kVelocityCoefficient * I.G + kAccelerationCoefficient * I.M;
    const Mat3 kt = so3::skew(rot.kappa);
    for (int a = 0; a < nn; ++a) {
        if (mesh_.nodes[e.nodes[a]].dof < 0) continue;
        for (int b = 0; b < nn; ++b) {
            if (mesh_.nodes[e.nodes[b]].dof < 0) continue;
            const Mat3 Kt = K_[b] + kt * A_[b];
            Mat6 X1 = kVelocityCoefficient * (dN[b] * B.D1 + N[b] * B.G1);
            X1.leftCols<3>() += dN[b] * B.P1.leftCols<3>() + N[b] * B.K1.leftCols<3>();
            X1.rightCols<3>() += B.P1.rightCols<3>() * Kt + B.K1.rightCols<3>() * A_[b];
            Mat6 X2 = kVelocityCoefficient * (dN[b] * B.D2 + N[b] * B.G2);
            X2.leftCols<3>() += dN[b] * B.P2.leftCols<3>() + N[b] * B.K2.leftCols<3>();
            X2.rightCols<3>() += B.P2.rightCols<3>() * Kt + B.K2.rightCols<3>() * A_[b];
            Mat6 blk = (qp.weight * N[a] * N[b]) * GM + qp.weight * (dN[a] * X1 + N[a] * X2);
            blk.rightCols<3>() += (qp.weight * N[a]) * I.K.rightCols<3>() * A_[b];
            add_block(*J, k, a, b, blk);
        }
    }
}

}  // namespace rotbeam::form
