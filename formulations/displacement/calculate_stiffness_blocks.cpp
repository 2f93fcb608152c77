#include "formulations/displacement/calculate_stiffness_blocks.hpp"

#include "core/so3.hpp"

namespace rotbeam::form {

StiffnessBlocks calculate_stiffness_blocks(const Mat6& C, const Vec6& FE1, const Vec3& xp,
                                           const Vec3& kappa) {
    const Mat3 xp_t = so3::skew(xp);
    const Mat3 k_t = so3::skew(kappa);
    const Mat3 N_t = so3::skew(FE1.head<3>());
    const Mat3 M_t = so3::skew(FE1.tail<3>());
    StiffnessBlocks b;
    b.O.topRows<3>() = -N_t + C.block<3, 3>(0, 0) * xp_t + C.block<3, 3>(0, 3) * k_t;
    b.O.bottomRows<3>() = -M_t + C.block<3, 3>(3, 0) * xp_t + C.block<3, 3>(3, 3) * k_t;
    b.Pu = N_t - xp_t * C.block<3, 3>(0, 0);
    b.Pk = -xp_t * C.block<3, 3>(0, 3);
    b.Qp = -xp_t * b.O.topRows<3>();
    return b;
}

}  // namespace rotbeam::form
