// Linearization of the elastic forces at a quadrature point with respect to the point's own
// variations: δu′, the spatial rotation variation δψ (δR Rᵀ = δψ~) and the curvature variation
// δκ, taken as independent. The map from nodal increments to (δψ, δκ) is the rotation
// interpolation's business (interpolate_rotation.hpp); keeping δκ separate is what makes the
// element Jacobian exact for any interpolation.
//
// With C = 𝓡 C* 𝓡ᵀ, δC = Ψ C − C Ψ (Ψ = diag(δψ~, δψ~)), δε = δu′ + (R x^r′)~ δψ:
//   δF^E1 = C [δu′; δκ] + O δψ,
//   O = [ −Ñ + C11 x̃p + C12 κ̃ ;  −M̃ + C21 x̃p + C22 κ̃ ],   xp = x^r′ + u′ = ε + R x^r′
//   δF^E2 = Pu δu′ + Pk δκ + Qp δψ  (moment row),
//   Pu = Ñ − x̃p C11,  Pk = −x̃p C12,  Qp = −x̃p O_top.
// Seed 000's K^E1, P^E2, K^E2 are these blocks after substituting the continuum relation
// δκ = δψ′ − κ̃ δψ (the C12 κ̃, C22 κ̃ terms then cancel): O − C[:,3:6] κ̃ = K^E1,
// [Pu Pk] = P^E2, Qp − Pk κ̃ = K^E2.
#pragma once

#include "core/types.hpp"

namespace rotbeam::form {

struct StiffnessBlocks {
    Eigen::Matrix<double, 6, 3> O = Eigen::Matrix<double, 6, 3>::Zero();
    Mat3 Pu = Mat3::Zero();
    Mat3 Pk = Mat3::Zero();
    Mat3 Qp = Mat3::Zero();
};

// C: inertial section stiffness; FE1 = [N; M]; xp = x^r′ + u′; kappa = κ.
StiffnessBlocks calculate_stiffness_blocks(const Mat6& C, const Vec6& FE1, const Vec3& xp,
                                           const Vec3& kappa);

}  // namespace rotbeam::form
