// The refinement and error estimate of quadratic eigenpairs (core/quadratic_eigenpair.hpp) on
// systems with closed-form eigenvalues, and the flutter/divergence verdict that reads the
// estimate (runs/modal_checks.cpp).
//
// The rotor: a point mass m on two springs k₁ ≠ k₂, seen in axes turning with it at Ω (an
// asymmetric shaft; Meirovitch, "Methods of Analytical Dynamics", 1970, §6.8):
//   m (ẍ − 2Ω ẏ − Ω² x) + k₁ x = 0,   m (ÿ + 2Ω ẋ − Ω² y) + k₂ y = 0,
// M = m I, G = 2mΩ [0, −1; 1, 0] (skew), K = diag(k₁ − mΩ², k₂ − mΩ²). With a = k₁/m − Ω²,
// b = k₂/m − Ω²: s⁴ + (a + b + 4Ω²) s² + ab = 0, an eigenvector [2Ω s, s² + a]. Stable (s
// imaginary) unless ab < 0, i.e. k₁/m < Ω² < k₂/m: then one real pair ±s (divergence).
// Three such rotors, mixed by an orthogonal congruence (which keeps M, K symmetric, G skew and
// every eigenvalue), make a coupled 6 × 6 system.
#include <Eigen/QR>
#include <array>
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <complex>
#include <cstdlib>
#include <vector>

#include "core/quadratic_eigenpair.hpp"
#include "runs/modal_checks.hpp"

using namespace rotbeam;

namespace {

using Complex = std::complex<double>;

struct Rotor {
    double m, k1, k2;
};

struct RotorSystem {
    SparseMatrix M, G, K;
    MatX Q;  // the orthogonal mixing: the system's unknowns are Qᵀ × the rotors'
    std::vector<Rotor> rotors;
    double omega;
};

RotorSystem rotor_system(const std::vector<Rotor>& rotors, double omega) {
    const int n = 2 * static_cast<int>(rotors.size());
    MatX M = MatX::Zero(n, n), G = MatX::Zero(n, n), K = MatX::Zero(n, n);
    for (size_t i = 0; i < rotors.size(); ++i) {
        const Rotor& r = rotors[i];
        const int j = 2 * static_cast<int>(i);
        M(j, j) = M(j + 1, j + 1) = r.m;
        G(j, j + 1) = -2.0 * r.m * omega;
        G(j + 1, j) = 2.0 * r.m * omega;
        K(j, j) = r.k1 - r.m * omega * omega;
        K(j + 1, j + 1) = r.k2 - r.m * omega * omega;
    }
    std::srand(11);
    RotorSystem s;
    s.Q = Eigen::HouseholderQR<MatX>(MatX::Random(n, n)).householderQ();
    s.M = MatX(s.Q.transpose() * M * s.Q).sparseView();
    s.G = MatX(s.Q.transpose() * G * s.Q).sparseView();
    s.K = MatX(s.Q.transpose() * K * s.Q).sparseView();
    s.rotors = rotors;
    s.omega = omega;
    return s;
}

// The closed-form eigenvalues of rotor i with Im s > 0, or the real s > 0 of a divergence, and
// their eigenvectors in the system's unknowns. The eigenvalue is formed in long double (its
// rounding, ~1e-19 relative, below any error estimate in double), so that the refined s can be
// compared with it to the estimate itself; `s` is it rounded to double.
using ComplexL = std::complex<long double>;
struct ExactPair {
    ComplexL exact;
    Complex s;
    VecXc x;
};

// |s − exact| in long double.
double distance_to(const ExactPair& e, Complex s) {
    return static_cast<double>(std::abs(ComplexL(s) - e.exact));
}

std::vector<ExactPair> exact_pairs(const RotorSystem& sys, size_t i) {
    const Rotor& r = sys.rotors[i];
    const long double W = sys.omega;
    const long double a = r.k1 / static_cast<long double>(r.m) - W * W;
    const long double b = r.k2 / static_cast<long double>(r.m) - W * W;
    const long double p = a + b + 4.0L * W * W;
    const long double root = std::sqrt(p * p - 4.0L * a * b);    // > 0 for a ≠ b
    const long double t1 = -0.5L * (p + root), t2 = a * b / t1;  // the two s², no cancellation
    std::vector<ExactPair> out;
    for (const long double t : {t1, t2}) {
        const ComplexL exact =
            t < 0.0L ? ComplexL(0.0L, std::sqrt(-t)) : ComplexL(std::sqrt(t), 0.0L);
        const Complex s(static_cast<double>(exact.real()), static_cast<double>(exact.imag()));
        VecXc v = VecXc::Zero(sys.Q.rows());
        v[2 * static_cast<Eigen::Index>(i)] = 2.0 * static_cast<double>(W) * s;
        v[2 * static_cast<Eigen::Index>(i) + 1] = s * s + static_cast<double>(a);
        out.push_back({exact, s, sys.Q.transpose().cast<Complex>() * v});
    }
    return out;
}

// (s, x) perturbed by 1e-6 relative, as the Arnoldi pairs of the spinning beams are (docs/
// rotating-frame.md): s along (1 + i), x by a fixed pseudo-random vector; a real pair (a
// divergence) by real perturbations, as the Arnoldi iteration returns a real eigenvalue of a real
// pencil with a real vector.
RefinedQuadraticPair refine_perturbed(const RotorSystem& sys, bool conservative,
                                      const ExactPair& e) {
    std::srand(5);
    const bool real = e.s.imag() == 0.0;
    const VecXc noise =
        real ? VecXc(VecX::Random(e.x.size()).cast<Complex>()) : VecXc(VecXc::Random(e.x.size()));
    const Complex s0 = e.s * (1.0 + (real ? Complex(1e-6) : Complex(1e-6, 1e-6)));
    const VecXc x0 = e.x + 1e-6 * e.x.norm() * noise;
    return refine_quadratic_pair({sys.M, sys.G, sys.K, conservative}, s0, x0);
}

const std::vector<Rotor> kRotors = {{1.0, 4.0, 9.0}, {2.0, 50.0, 70.0}, {0.5, 20.0, 32.0}};

}  // namespace

BOOST_AUTO_TEST_SUITE(quadratic_eigenpair)

// Below and above the critical band of every rotor (Ω = 1: all stable, K positive; Ω = 8.5: all
// stable again, K negative definite — gyroscopic stabilization), each perturbed pair refines to
// an s exactly on the imaginary axis (the conservative functional), within its error estimate of
// the closed form, the estimate at round-off: 1e-14 |s| (the rotors' eigenvalues have condition
// numbers of order one to ten; 50 unit round-offs) and the refinement done in at most three steps.
BOOST_AUTO_TEST_CASE(a_stable_conservative_pair_is_refined_onto_the_imaginary_axis) {
    for (const double omega : {1.0, 8.5}) {
        const RotorSystem sys = rotor_system(kRotors, omega);
        for (size_t i = 0; i < kRotors.size(); ++i) {
            for (const ExactPair& e : exact_pairs(sys, i)) {
                const RefinedQuadraticPair r = refine_perturbed(sys, true, e);
                BOOST_TEST_CONTEXT("Omega " << omega << ", rotor " << i << ", s " << e.s
                                            << ": refined " << r.s << " in " << r.steps
                                            << " steps, estimate " << r.error) {
                    BOOST_TEST(r.s.real() == 0.0);
                    BOOST_TEST(distance_to(e, r.s) <= r.error);
                    BOOST_TEST(r.error <= 1e-14 * std::abs(e.s));
                    BOOST_TEST(r.check.accepted);
                    BOOST_TEST(r.steps <= kMaxQuadraticRefinementSteps);
                }
            }
        }
    }
}

// In rotor 0's critical band (Ω = 2.5, between √(k₁/m) = 2 and √(k₂/m) = 3) its pair of lower
// |s| is a real ±s, the divergence: the refinement keeps it real and on the closed form, its
// growth rate far above its error estimate (the verdict reports it). The other rotors stay on
// the imaginary axis.
BOOST_AUTO_TEST_CASE(a_divergence_stays_real_and_is_far_above_its_error_estimate) {
    const RotorSystem sys = rotor_system(kRotors, 2.5);
    int divergences = 0;
    for (size_t i = 0; i < kRotors.size(); ++i) {
        for (const ExactPair& e : exact_pairs(sys, i)) {
            const RefinedQuadraticPair r = refine_perturbed(sys, true, e);
            BOOST_TEST_CONTEXT("rotor " << i << ", s " << e.s << ": refined " << r.s
                                        << ", estimate " << r.error) {
                BOOST_TEST(distance_to(e, r.s) <= r.error);
                BOOST_TEST(r.check.accepted);
                if (e.s.imag() == 0.0) {
                    ++divergences;
                    BOOST_TEST(r.s.imag() == 0.0);
                    BOOST_TEST(r.s.real() > 1e10 * r.error);
                } else {
                    BOOST_TEST(r.s.real() == 0.0);
                }
            }
        }
    }
    BOOST_TEST(divergences == 1);
}

// A non-conservative system takes the two-sided functional: the circulatory pair of Ziegler's
// type, M = I, G = 0, K = [k₁, c; −c, k₂] (a follower force's skew stiffness), mixed as above.
// s² = −λ for the eigenvalues λ = (k₁ + k₂)/2 ± √(((k₁ − k₂)/2)² − c²) of K: imaginary s while
// c < |k₁ − k₂|/2, flutter (complex λ) past it. Below, Re s is left at round-off — within the
// pair's error estimate, so the verdict reports no growth; past it, Re s is the closed form's to
// within the estimate and far above it.
BOOST_AUTO_TEST_CASE(a_circulatory_pair_grows_only_past_its_flutter_point) {
    const double k1 = 4.0, k2 = 9.0;
    for (const double c : {2.0, 3.0}) {  // the flutter point is c = 2.5
        const int n = 4;
        MatX K = MatX::Zero(n, n);
        K.topLeftCorner<2, 2>() << k1, c, -c, k2;
        K.bottomRightCorner<2, 2>() << 30.0, 0.0, 0.0, 40.0;  // a second, stable pair of modes
        std::srand(3);
        const MatX Q = Eigen::HouseholderQR<MatX>(MatX::Random(n, n)).householderQ();
        const SparseMatrix Ks = MatX(Q.transpose() * K * Q).sparseView();
        const SparseMatrix Ms = MatX(MatX::Identity(n, n)).sparseView();
        const SparseMatrix Gs(n, n);
        const ComplexL lambda_l =
            0.5L * (k1 + k2) + std::sqrt(ComplexL(0.25L * (k1 - k2) * (k1 - k2) - c * c));
        ComplexL exact = ComplexL(0.0L, 1.0L) * std::sqrt(lambda_l);  // −λ = s²
        if (exact.imag() < 0.0L) exact = -exact;
        const Complex lambda(static_cast<double>(lambda_l.real()),
                             static_cast<double>(lambda_l.imag()));
        const Complex s(static_cast<double>(exact.real()), static_cast<double>(exact.imag()));
        const ExactPair e{exact, s, {}};
        // Its eigenvector: (K − λ I) v = 0 in the rotor's axes.
        VecXc v = VecXc::Zero(n);
        v[0] = c;
        v[1] = lambda - k1;
        const VecXc x = Q.transpose().cast<Complex>() * v;
        std::srand(5);
        const RefinedQuadraticPair r =
            refine_quadratic_pair({Ms, Gs, Ks, false}, s * (1.0 + Complex(1e-6, 1e-6)),
                                  x + 1e-6 * x.norm() * VecXc::Random(n));
        BOOST_TEST_CONTEXT("c " << c << ": s " << s << ", refined " << r.s << ", estimate "
                                << r.error) {
            BOOST_TEST(r.check.accepted);
            BOOST_TEST(distance_to(e, r.s) <= r.error);
            if (c < 2.5) {
                BOOST_TEST(std::abs(r.s.real()) <= r.error);
            } else {
                BOOST_TEST(std::abs(r.s.real()) > 1e10 * r.error);
            }
        }
    }
}

// The run's verdict: a growth rate counts as flutter or divergence only above the eigenvalue's
// own error estimate when the pair has one; without one, above the fixed round-off fraction
// 1e-8 |s| as before. The Arnoldi iteration's 1.8e-6 1/s at |s| = 24.5 (7e-8 |s|) of a
// conservative spinning beam, with an estimate of 1e-7 |s|, is that error, not a growth. A
// decaying mode (Re s < 0, a damped structure) is no instability, however far above its estimate.
BOOST_AUTO_TEST_CASE(the_verdict_reads_the_eigenvalue_error_estimate) {
    const auto message = [](double growth, double estimate) {
        CheckedMode m{24.5 / (2.0 * 3.141592653589793), growth, Complex(growth, 24.5), {}};
        m.check.accepted = true;
        m.check.error_estimate = estimate;
        nlohmann::json result = {{"modes", nlohmann::json::array({nlohmann::json::object()})}};
        report_checked_modes({m}, "static", result);
        return result["message"].get<std::string>();
    };
    const std::string flutter = "flutter or divergence";
    BOOST_TEST(message(1.8e-6, 1e-7).find(flutter) == std::string::npos);
    BOOST_TEST(message(1.8e-6, 1e-9).find(flutter) != std::string::npos);
    BOOST_TEST(message(1.8e-6, -1.0).find(flutter) != std::string::npos);  // no estimate
    BOOST_TEST(message(1e-8, -1.0).find(flutter) == std::string::npos);
    BOOST_TEST(message(-1.0, 1e-9).find(flutter) == std::string::npos);
    BOOST_TEST(message(-1.0, -1.0).find(flutter) == std::string::npos);
}

BOOST_AUTO_TEST_SUITE_END()
