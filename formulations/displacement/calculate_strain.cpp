#include "formulations/displacement/calculate_strain.hpp"

namespace rotbeam::form {

Vec6 calculate_strain(const Vec3& x0_prime, const Vec3& u_prime, const Mat3& R, const Vec3& kappa) {
    Vec6 e;
    e.head<3>() = x0_prime + u_prime - R * x0_prime;
    e.tail<3>() = kappa;
    return e;
}

}  // namespace rotbeam::form
