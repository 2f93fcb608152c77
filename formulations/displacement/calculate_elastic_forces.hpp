// Elastic forces at a quadrature point (seed 000, the F^E1/F^E2 definitions under Eq. 9):
//   F^E1 = C [ε; κ] = [N; M]                       (section force and moment, inertial)
//   F^E2 = [0; (x̃^r′ + ũ′)ᵀ N] = [0; N × (x^r′ + u′)]
// The weak-form residual of a node with shape function N_a is ∫ (N_a′ F^E1 + N_a F^E2) ds.
#pragma once

#include "core/types.hpp"

namespace rotbeam::form {

struct ElasticForces {
    Vec6 FE1 = Vec6::Zero();
    Vec3 FE2 = Vec3::Zero();  // the moment part of F^E2 (its force part is zero)
};

// C: inertial section stiffness; e = [ε; κ]; xp = x^r′ + u′.
ElasticForces calculate_elastic_forces(const Mat6& C, const Vec6& e, const Vec3& xp);

}  // namespace rotbeam::form
