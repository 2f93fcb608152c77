// Sectional damping forces of the displacement formulation (seed 000 Eq. 10, F^D2 per the errata
// in docs/benchmarks.md) and their tangent blocks, derived from the forces and checked by central
// differences (tests/displacement/test_damping.cpp), not transcribed from the damaged printed text.
//
//   ε˙ = u˙′ − ω̃ (R x⁰′),  κ˙ = ω̃ κ + ω′,  F^D1 = D [ε˙; κ˙] = [f; m],
//   F^D2 = [0; (x̃′)ᵀ f]  with x′ = x^r′ + u′ (mirrors F^E2),  D = (R R^r) μ C* (R R^r)ᵀ.
// Variations (rotation perturbed on the left, δR = δθ̃ R, so D, R x⁰′ and κ rotate with δθ and
// δκ = δθ′ − κ̃ δθ; velocities are independent unknowns):
//   δF^D1 = D δv′ + G1 δv + P1 δq′ + K1 δq,
//     G1 = [0, D_i1 (Rx⁰′)~ − D_i2 κ̃],  P1 = [0, D_i2 ω̃],
//     K1 = [0, −(D_i1 ε˙)~ + D_i1 ε˙~ − (D_i2 κ˙)~ + D_i2 κ˙~ + D_i1 ω̃ (Rx⁰′)~ − D_i2 ω̃ κ̃]
//     (row i = 1, 2; the printed second row has D₂₂ in the ω̃(Rx⁰′)~ term: it is D₂₁),
//   δF^D2 = x̃′ᵀ(row 1 of the F^D1 blocks) in the moment rows, plus +f̃ δu′ (P^D2 (2,1): the printed
//   sign is wrong, it mirrors P^E2's +Ñ) — the printed D^D2, G^D2, K^D2, P^D2 (2,2) drop x̃′ᵀ.
// Header-only, fixed-size, no heap.
#pragma once

#include "core/so3.hpp"
#include "core/types.hpp"

namespace rotbeam::form {

struct DampingState {
    Mat6 D = Mat6::Zero();        // damping matrix in inertial axes
    Vec3 x_prime = Vec3::Zero();  // x^r′ + u′
    Vec3 Rx0p = Vec3::Zero();     // R x⁰′ (R: rotation from the reference)
    Vec3 kappa = Vec3::Zero();    // curvature κ, inertial axes
    Vec3 omega = Vec3::Zero();
    Vec3 omega_prime = Vec3::Zero();
    Vec3 u_dot_prime = Vec3::Zero();
};

struct DampingBlocks {
    Vec6 F1 = Vec6::Zero(), F2 = Vec6::Zero();  // F^D1, F^D2
    // Columns: ∂/∂v′ = (u˙′, ω′), ∂/∂v = (u˙, ω), ∂/∂q′ = (u′, θ′), ∂/∂q = (u, θ).
    Mat6 D1 = Mat6::Zero(), G1 = Mat6::Zero(), P1 = Mat6::Zero(), K1 = Mat6::Zero();
    Mat6 D2 = Mat6::Zero(), G2 = Mat6::Zero(), P2 = Mat6::Zero(), K2 = Mat6::Zero();
};

inline DampingBlocks calculate_damping_blocks(const DampingState& s) {
    DampingBlocks b;
    const Mat3 w = so3::skew(s.omega);
    const Mat3 k = so3::skew(s.kappa);
    const Mat3 r = so3::skew(s.Rx0p);
    Vec6 rates;
    rates.head<3>() = s.u_dot_prime - w * s.Rx0p;
    rates.tail<3>() = w * s.kappa + s.omega_prime;
    const Mat3 ed = so3::skew(rates.head<3>());
    const Mat3 kd = so3::skew(rates.tail<3>());
    b.F1 = s.D * rates;
    b.D1 = s.D;
    for (int i = 0; i < 2; ++i) {
        const Mat3 Di1 = s.D.block<3, 3>(3 * i, 0);
        const Mat3 Di2 = s.D.block<3, 3>(3 * i, 3);
        b.G1.block<3, 3>(3 * i, 3) = Di1 * r - Di2 * k;
        b.P1.block<3, 3>(3 * i, 3) = Di2 * w;
        b.K1.block<3, 3>(3 * i, 3) =
            -so3::skew(b.F1.segment<3>(3 * i)) + Di1 * ed + Di2 * kd + Di1 * w * r - Di2 * w * k;
    }
    const Mat3 xt = so3::skew(s.x_prime).transpose();
    const Vec3 f = b.F1.head<3>();
    b.F2.tail<3>() = xt * f;
    b.D2.bottomRows<3>() = xt * b.D1.topRows<3>();
    b.G2.bottomRows<3>() = xt * b.G1.topRows<3>();
    b.P2.bottomRows<3>() = xt * b.P1.topRows<3>();
    b.P2.block<3, 3>(3, 0) += so3::skew(f);
    b.K2.bottomRows<3>() = xt * b.K1.topRows<3>();
    return b;
}

}  // namespace rotbeam::form
