#include "formulations/displacement/rotate_section.hpp"

namespace rotbeam::form {

Mat6 rotate_section(const Mat6& C_star, const Mat3& Q) {
    const Mat3 Qt = Q.transpose();
    Mat6 C;
    C.block<3, 3>(0, 0) = Q * C_star.block<3, 3>(0, 0) * Qt;
    C.block<3, 3>(0, 3) = Q * C_star.block<3, 3>(0, 3) * Qt;
    C.block<3, 3>(3, 0) = Q * C_star.block<3, 3>(3, 0) * Qt;
    C.block<3, 3>(3, 3) = Q * C_star.block<3, 3>(3, 3) * Qt;
    return C;
}

}  // namespace rotbeam::form
