// The central-difference Jacobian helper every Jacobian test relies on: its accuracy on a smooth
// map is ~ε^(2/3) (step ∛ε · max(1, |x|)), and it reproduces a known Jacobian to that level.
#include <boost/test/unit_test.hpp>

#include <cmath>

#include "core/finite_difference.hpp"
#include "core/so3.hpp"

using namespace rotbeam;

BOOST_AUTO_TEST_SUITE(finite_difference)

BOOST_AUTO_TEST_CASE(central_differences_match_an_analytic_jacobian_to_eps_two_thirds) {
    // f(x) = (sin x0 · x1², exp(x2) − x0, x1 x2 / 30); entries of x up to 30 exercise the
    // relative step.
    auto f = [](const VecX& x) {
        VecX y(3);
        y << std::sin(x[0]) * x[1] * x[1], std::exp(x[2]) - x[0], x[1] * x[2] / 30.0;
        return y;
    };
    VecX x(3);
    x << 0.7, 30.0, -1.2;
    MatX J(3, 3);
    J << std::cos(x[0]) * x[1] * x[1], 2.0 * std::sin(x[0]) * x[1], 0.0,  //
        -1.0, 0.0, std::exp(x[2]),                                       //
        0.0, x[2] / 30.0, x[1] / 30.0;
    const MatX Jfd = central_difference_jacobian(f, x);
    // Truncation h²|f'''|/6 with h = ∛ε·30 ≈ 1.8e-4 and |f'''| ~ 900 gives ~5e-6 on an entry of
    // size ~700: relative 1e-8.
    BOOST_TEST((Jfd - J).norm() / J.norm() < 1e-8);
}

BOOST_AUTO_TEST_CASE(differences_through_a_retraction_give_the_spatial_tangent) {
    // g(δ) = exp(δ) R0 a: its derivative at δ = 0 is −(R0 a)~ (spatial increment).
    const Mat3 R0 = so3::exp_map(Vec3(0.4, -1.1, 2.0));
    const Vec3 a(1.0, 2.0, -0.5);
    auto g = [&](const VecX& d) -> VecX { return so3::exp_map(Vec3(d)) * R0 * a; };
    const MatX J = central_difference_jacobian_retraction(g, 3);
    const Mat3 expected = -so3::skew(R0 * a);
    BOOST_TEST((J - expected).norm() < 1e-9);
}

BOOST_AUTO_TEST_SUITE_END()
