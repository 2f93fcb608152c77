// Fixed-size Eigen aliases used throughout rotbeam.
#pragma once

#include <Eigen/Dense>  // Core + Geometry (cross) + LU (determinant, inverse) + SVD

namespace rotbeam {

using Vec3 = Eigen::Vector3d;
using Vec4 = Eigen::Vector4d;
using Vec6 = Eigen::Matrix<double, 6, 1>;
using Mat3 = Eigen::Matrix3d;
using Mat4 = Eigen::Matrix4d;
using Mat6 = Eigen::Matrix<double, 6, 6>;
using VecX = Eigen::VectorXd;
using MatX = Eigen::MatrixXd;

inline constexpr double kPi = 3.14159265358979323846;

}  // namespace rotbeam
