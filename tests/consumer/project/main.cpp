// A project outside rotbeam using the installed library.
#include <cmath>
#include <iostream>

#include "core/quadrature.hpp"
#include "core/so3.hpp"
#include "core/version.hpp"

int main() {
    const rotbeam::Vec3 psi(0.1, -0.2, 0.3);
    const rotbeam::Vec3 back = rotbeam::so3::log_map(rotbeam::so3::exp_map(psi));
    const rotbeam::QuadratureRule rule = rotbeam::gauss_legendre(4);
    double sum = 0.0;
    for (double w : rule.weights) sum += w;
    if ((back - psi).norm() > 1e-14 || std::abs(sum - 2.0) > 1e-14) return 1;
    std::cout << "consumer ok (rotbeam " << rotbeam::kGitDescribe << ")\n";
    return 0;
}
