// Tangent operators of every parameterization on the shared hard sample set:
// H H⁺ = I, both tangents against finite differences of R, the inverses against finite
// differences along H⁺ w, the contracted derivatives against finite differences of H v and H⁺ w,
// and the order check (halving the step cuts the linearization remainder ~4×).
#include <boost/test/unit_test.hpp>
#include <functional>

#include "tests/harness/coverage.hpp"
#include "tests/parameterizations/samples.hpp"

namespace rotbeam::test {
namespace {

template <class P>
using Vp = typename P::P;

// Sample parameters (the quaternion also off the unit sphere, scaled by 1.7: its R and tangents
// are homogeneous and must stay consistent there).
template <class P>
std::vector<std::pair<std::string, Vp<P>>> tangent_samples() {
    std::vector<std::pair<std::string, Vp<P>>> out;
    for (const Sample& s : hard_samples()) {
        if (!chart_contains<P>(s.angle)) continue;
        const Vp<P> p = P::from_rotation_vector(s.angle * generic_axis());
        out.emplace_back(s.label, p);
        if constexpr (P::kSize == 4) out.emplace_back(s.label + " x1.7", Vp<P>(1.7 * p));
    }
    if constexpr (std::is_same_v<P, param::EulerAngles>) {
        // Euler angles' singular set is gimbal lock (a2 = ±π/2), which no sample about the generic
        // axis comes near: approach it from both sides, and take a parameter on the second branch
        // (|a2| > π/2) and one past 2π.
        out.emplace_back("a2 = pi/2 - 1e-3", Vp<P>(0.4, 0.5 * kPi - 1e-3, -1.1));
        out.emplace_back("a2 = -pi/2 + 1e-6", Vp<P>(-2.9, -0.5 * kPi + 1e-6, 2.5));
        out.emplace_back("a2 = pi/2 + 0.3", Vp<P>(0.7, 0.5 * kPi + 0.3, 0.2));
        out.emplace_back("a1, a3 past 2pi", Vp<P>(7.0, -0.4, -6.9));
    }
    for (const auto& sample : out) checked("identity", P::kName, sample.first);
    return out;
}

template <class P>
Vp<P> generic_direction() {
    Vp<P> d;
    if constexpr (P::kSize == 4) {
        d << 0.3, -0.5, 0.7, 0.4;
    } else {
        d << 0.6, 0.2, -0.77;
    }
    return d.normalized();
}

inline Vec3 generic_increment() { return Vec3(-0.4, 0.9, 0.3).normalized(); }

// axial(δR Rᵀ) (spatial) or axial(Rᵀ δR) (material) of a matrix increment dR at R.
Vec3 rotation_of(const Mat3& dR, const Mat3& R, bool spatial) {
    return spatial ? so3::axial(dR * R.transpose()) : so3::axial(R.transpose() * dR);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(parameterization_tangents)

BOOST_AUTO_TEST_CASE_TEMPLATE(tangent_times_inverse_is_identity, P, AllParameterizationTypes) {
    for (const auto& [label, p] : tangent_samples<P>()) {
        BOOST_TEST_CONTEXT(P::kName << " at " << label) {
            for (bool spatial : {true, false}) {
                const param::Tangent<P::kSize> H =
                    spatial ? P::spatial_tangent(p) : P::material_tangent(p);
                const param::TangentInverse<P::kSize> Hi =
                    spatial ? P::spatial_tangent_inverse(p) : P::material_tangent_inverse(p);
                // Round-off of a product: ε ‖H‖ ‖H⁺‖ per entry.
                const double tol = 16.0 * kEps * H.norm() * Hi.norm();
                BOOST_TEST((H * Hi - Mat3::Identity()).norm() <= tol);
                if constexpr (P::kSize == 4) {
                    const Mat4 projector = Mat4::Identity() - p * p.transpose() / p.squaredNorm();
                    BOOST_TEST((Hi * H - projector).norm() <= tol);
                } else {
                    BOOST_TEST((Hi * H - Mat3::Identity()).norm() <= tol);
                }
            }
        }
    }
}

BOOST_AUTO_TEST_CASE_TEMPLATE(material_tangent_is_Rt_times_spatial_tangent, P,
                              AllParameterizationTypes) {
    for (const auto& [label, p] : tangent_samples<P>()) {
        BOOST_TEST_CONTEXT(P::kName << " at " << label) {
            const param::Tangent<P::kSize> Hs = P::spatial_tangent(p);
            const param::Tangent<P::kSize> Hm = P::material_tangent(p);
            BOOST_TEST((Hm - P::matrix(p).transpose() * Hs).norm() <= 8.0 * kEps * Hs.norm());
        }
    }
}

BOOST_AUTO_TEST_CASE_TEMPLATE(tangents_match_finite_differences_of_R, P, AllParameterizationTypes) {
    for (const auto& [label, p] : tangent_samples<P>()) {
        const double h = std::cbrt(kEps) * variation_length<P>(p, false);
        const Mat3 R = P::matrix(p);
        for (bool spatial : {true, false}) {
            const param::Tangent<P::kSize> H =
                spatial ? P::spatial_tangent(p) : P::material_tangent(p);
            for (int j = 0; j < P::kSize; ++j) {
                BOOST_TEST_CONTEXT(P::kName << " at " << label << (spatial ? " H_s" : " H_m")
                                            << " column " << j) {
                    const Vp<P> e = Vp<P>::Unit(j);
                    const Mat3 dR =
                        central_difference([](const Vp<P>& x) { return P::matrix(x); }, p, e, h);
                    const Vec3 column = rotation_of(dR, R, spatial);
                    BOOST_TEST((column - H.col(j)).norm() <=
                               fd_tolerance(H.norm(), std::sqrt(3.0), h, p.norm()));
                }
            }
        }
    }
}

BOOST_AUTO_TEST_CASE_TEMPLATE(inverse_tangents_match_finite_differences_of_R, P,
                              AllParameterizationTypes) {
    // Moving p along H⁺ w rotates R by w (spatially or materially) to first order.
    const Vec3 w = generic_increment();
    for (const auto& [label, p] : tangent_samples<P>()) {
        const Mat3 R = P::matrix(p);
        for (bool spatial : {true, false}) {
            BOOST_TEST_CONTEXT(P::kName << " at " << label << (spatial ? " H_s+" : " H_m+")) {
                const Vp<P> d = spatial ? P::spatial_tangent_inverse(p) * w
                                        : P::material_tangent_inverse(p) * w;
                const double h = std::cbrt(kEps) * variation_length<P>(p, false) / d.norm();
                const Mat3 dR =
                    central_difference([](const Vp<P>& x) { return P::matrix(x); }, p, d, h);
                BOOST_TEST((rotation_of(dR, R, spatial) - w).norm() <=
                           fd_tolerance(1.0, std::sqrt(3.0), h, p.norm() / d.norm()));
            }
        }
    }
}

BOOST_AUTO_TEST_CASE_TEMPLATE(tangent_derivatives_match_finite_differences, P,
                              AllParameterizationTypes) {
    const Vp<P> v = generic_direction<P>().reverse();
    for (const auto& [label, p] : tangent_samples<P>()) {
        const double h = std::cbrt(kEps) * variation_length<P>(p, false);
        for (bool spatial : {true, false}) {
            const param::Tangent<P::kSize> D = spatial ? P::spatial_tangent_derivative(p, v)
                                                       : P::material_tangent_derivative(p, v);
            const auto Hv = [&](const Vp<P>& x) -> Vec3 {
                return spatial ? Vec3(P::spatial_tangent(x) * v) : Vec3(P::material_tangent(x) * v);
            };
            const double value = Hv(p).norm();
            for (int j = 0; j < P::kSize; ++j) {
                BOOST_TEST_CONTEXT(P::kName << " at " << label << (spatial ? " dH_s" : " dH_m")
                                            << " column " << j) {
                    const Vec3 fd = central_difference(Hv, p, Vp<P>(Vp<P>::Unit(j)), h);
                    BOOST_TEST((fd - D.col(j)).norm() <=
                               fd_tolerance(D.norm(), value, h, p.norm()));
                }
            }
        }
    }
}

BOOST_AUTO_TEST_CASE_TEMPLATE(inverse_tangent_derivatives_match_finite_differences, P,
                              AllParameterizationTypes) {
    const Vec3 w = generic_increment();
    using Square = Eigen::Matrix<double, P::kSize, P::kSize>;
    for (const auto& [label, p] : tangent_samples<P>()) {
        const double h = std::cbrt(kEps) * variation_length<P>(p, true);
        for (bool spatial : {true, false}) {
            const Square D = spatial ? P::spatial_tangent_inverse_derivative(p, w)
                                     : P::material_tangent_inverse_derivative(p, w);
            const auto Hiw = [&](const Vp<P>& x) -> Vp<P> {
                return spatial ? Vp<P>(P::spatial_tangent_inverse(x) * w)
                               : Vp<P>(P::material_tangent_inverse(x) * w);
            };
            const double value = Hiw(p).norm();
            for (int j = 0; j < P::kSize; ++j) {
                BOOST_TEST_CONTEXT(P::kName << " at " << label << (spatial ? " dH_s+" : " dH_m+")
                                            << " column " << j) {
                    const Vp<P> fd = central_difference(Hiw, p, Vp<P>(Vp<P>::Unit(j)), h);
                    BOOST_TEST((fd - D.col(j)).norm() <=
                               fd_tolerance(D.norm(), value, h, p.norm()));
                }
            }
        }
    }
}

// r(t) = ‖f(p + t d) − f(p) − t f'(p) d‖ is O(t²) when f' is right: halving t divides it by 4
// (by 8 where the t² term vanishes by symmetry, e.g. at p = 0), while a wrong f' leaves an O(t)
// term and a ratio of 2. A remainder below the round-off floor means f is linear along d (the
// quaternion's H⁺) and its linearization exact, which is checked by the floor itself.
void check_second_order(const std::function<double(double)>& remainder, double t, double floor) {
    const double r1 = remainder(t);
    const double r2 = remainder(0.5 * t);
    if (r1 <= floor) {
        BOOST_TEST(r2 <= floor);
        return;
    }
    BOOST_TEST(r1 / r2 >= 3.6, "r(t) = " << r1 << ", r(t/2) = " << r2);
}

BOOST_AUTO_TEST_CASE_TEMPLATE(linearization_remainders_drop_fourfold_when_the_step_halves, P,
                              AllParameterizationTypes) {
    // t = 1e-2 L keeps r ≫ round-off and the O(t/L) correction of the ratio at the percent level.
    const Vp<P> d = generic_direction<P>();
    const Vp<P> v = d.reverse();
    const Vec3 w = generic_increment();
    for (const auto& sample : tangent_samples<P>()) {
        // Named, not a structured binding: clang 14 cannot capture a binding in a lambda.
        const std::string& label = sample.first;
        const Vp<P>& p = sample.second;
        const Mat3 R = P::matrix(p);
        const auto rotation_remainder = [&](double t) {
            const Vec3 psi = so3::log_map(P::matrix(Vp<P>(p + t * d)) * R.transpose());
            return (psi - t * P::spatial_tangent(p) * d).norm();
        };
        const auto tangent_remainder = [&](double t) {
            const Vec3 dv = P::material_tangent(Vp<P>(p + t * d)) * v - P::material_tangent(p) * v;
            return (dv - t * P::material_tangent_derivative(p, v) * d).norm();
        };
        const auto inverse_remainder = [&](double t) {
            const Vp<P> dw = P::spatial_tangent_inverse(Vp<P>(p + t * d)) * w -
                             P::spatial_tangent_inverse(p) * w;
            return (dw - t * P::spatial_tangent_inverse_derivative(p, w) * d).norm();
        };
        const double t = 1e-2 * variation_length<P>(p, false);
        const double ti = 1e-2 * variation_length<P>(p, true);
        // Round-off floor: 64 ε times the size of the values that are differenced.
        const double floor_rotation = 64.0 * kEps * (1.0 + t * P::spatial_tangent(p).norm());
        const double floor_tangent = 64.0 * kEps * P::material_tangent(p).norm();
        const double floor_inverse = 64.0 * kEps * P::spatial_tangent_inverse(p).norm();
        BOOST_TEST_CONTEXT(P::kName << " at " << label << ", R") {
            check_second_order(rotation_remainder, t, floor_rotation);
        }
        BOOST_TEST_CONTEXT(P::kName << " at " << label << ", H_m v") {
            check_second_order(tangent_remainder, t, floor_tangent);
        }
        BOOST_TEST_CONTEXT(P::kName << " at " << label << ", H_s+ w") {
            check_second_order(inverse_remainder, ti, floor_inverse);
        }
    }
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace rotbeam::test
