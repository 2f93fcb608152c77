#include "formulations/displacement/calculate_elastic_forces.hpp"

namespace rotbeam::form {

ElasticForces calculate_elastic_forces(const Mat6& C, const Vec6& e, const Vec3& xp) {
    ElasticForces f;
    f.FE1 = C * e;
    f.FE2 = f.FE1.head<3>().cross(xp);
    return f;
}

}  // namespace rotbeam::form
