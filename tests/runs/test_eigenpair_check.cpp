// The a posteriori checks of computed eigenpairs (core/eigenpair_check.hpp) on pencils whose
// eigenpairs are known exactly: K = Q diag(k) Qᵀ, M = Q diag(m) Qᵀ with Q orthogonal have the
// eigenpairs (k_i / m_i, Q e_i).
#include <Eigen/Eigenvalues>
#include <boost/test/unit_test.hpp>
#include <cmath>

#include "core/eigenpair_check.hpp"

using namespace rotbeam;

namespace {

constexpr int kN = 8;

MatX orthogonal() {
    std::srand(7);
    const MatX a = MatX::Random(kN, kN);
    return Eigen::HouseholderQR<MatX>(a).householderQ();
}

struct Pencil {
    SparseMatrix K, M;
    VecX k, m;
    MatX Q;
};

Pencil pencil(const VecX& m) {
    Pencil p;
    p.Q = orthogonal();
    p.k = VecX::LinSpaced(kN, 1.0, 8.0).array().square();  // 1, 4, 9, …: distinct
    p.m = m;
    p.K = MatX(p.Q * p.k.asDiagonal() * p.Q.transpose()).sparseView();
    p.M = MatX(p.Q * p.m.asDiagonal() * p.Q.transpose()).sparseView();
    return p;
}

std::vector<double> exact_spectrum(const Pencil& p) {
    std::vector<double> s;
    for (int i = 0; i < kN; ++i) s.push_back(p.k[i] / p.m[i]);
    std::sort(s.begin(), s.end());
    return s;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(eigenpair_check)

// Exact pairs pass with round-off-sized measures; the reported eigenvalue is the Rayleigh
// quotient (equal to k_i/m_i to round-off).
BOOST_AUTO_TEST_CASE(exact_pairs_are_accepted) {
    const Pencil p = pencil(VecX::LinSpaced(kN, 1.0, 2.0));
    const Eigen::LLT<MatX> llt{MatX(p.M)};
    std::vector<SymmetricPair> pairs;
    for (int i = 0; i < 3; ++i) pairs.push_back({0.0, p.Q.col(i)});
    const std::vector<EigenpairCheck> c =
        check_symmetric_definite(p.K, p.M, llt, pairs, exact_spectrum(p));
    for (int i = 0; i < 3; ++i) {
        BOOST_TEST_MESSAGE("exact pair " << i << ": " << describe(c[i]));
        BOOST_TEST(c[i].accepted);
        BOOST_TEST(c[i].backward_error < 1e-14);
        BOOST_TEST(c[i].error_bound < 1e-14);
        BOOST_TEST(c[i].mass_orthogonality < 1e-14);
        BOOST_TEST(std::abs(pairs[i].lambda - p.k[i] / p.m[i]) < 1e-13 * pairs[i].lambda);
    }
}

// The bound is a bound: for eigenvectors perturbed by 1e-9 … 1e-2 the Rayleigh quotient's true
// relative error never exceeds it, and a pair whose bound exceeds the tolerance is rejected. The
// pencil itself is formed in floating point (Q diag Qᵀ), so its eigenvalues differ from k_i/m_i by
// ~kN ε: 1e-14 is added to the bound for that, not for the check.
BOOST_AUTO_TEST_CASE(the_error_bound_bounds_the_true_error_and_rejects_poor_pairs) {
    const Pencil p = pencil(VecX::LinSpaced(kN, 1.0, 2.0));
    const Eigen::LLT<MatX> llt{MatX(p.M)};
    const VecX noise = VecX::Random(kN);
    for (double eps : {1e-9, 1e-6, 1e-4, 1e-2}) {
        std::vector<SymmetricPair> pairs = {{0.0, p.Q.col(1) + eps * noise}};
        const EigenpairCheck c =
            check_symmetric_definite(p.K, p.M, llt, pairs, exact_spectrum(p)).front();
        const double exact = p.k[1] / p.m[1];
        const double error = std::abs(pairs[0].lambda - exact) / exact;
        BOOST_TEST_MESSAGE("perturbation " << eps << ": true error " << error << ", "
                                           << describe(c));
        BOOST_TEST(error <= c.error_bound + 1e-14);
        BOOST_TEST(c.accepted == (c.error_bound <= kEigenvalueErrorTolerance));
        if (eps >= 1e-2) BOOST_TEST(!c.accepted);
    }
}

// The failure class of a rank-deficient mass rule: M singular to working precision (two
// eigenvalues 1e-15, null space not along the axes), whose Cholesky factor exists. The
// Cholesky-based solver then returns eigenvalues of L⁻¹KL⁻ᵀ, of norm ~‖K‖/round-off, with absolute
// errors of that size: the finite ones (1 … 36) come out wrong. Every pair the check accepts is
// within the tolerance of an exact finite eigenvalue, and the wrong ones are rejected.
BOOST_AUTO_TEST_CASE(a_near_singular_mass_cannot_pass_a_wrong_eigenvalue) {
    VecX m = VecX::Ones(kN);
    m[kN - 1] = 1e-15;  // two masses at round-off of the others: a Cholesky factor exists
    m[kN - 2] = 1e-15;
    const Pencil p = pencil(m);
    const MatX Md(p.M);
    const Eigen::LLT<MatX> llt(Md);
    BOOST_TEST_REQUIRE((llt.info() == Eigen::Success));  // round-off pivots, not an exact zero
    const Eigen::GeneralizedSelfAdjointEigenSolver<MatX> es(MatX(p.K), Md);
    std::vector<SymmetricPair> pairs;
    std::vector<double> spectrum;
    for (int i = 0; i < kN; ++i) {
        pairs.push_back({es.eigenvalues()[i], es.eigenvectors().col(i)});
        spectrum.push_back(es.eigenvalues()[i]);
    }
    const std::vector<EigenpairCheck> c = check_symmetric_definite(p.K, p.M, llt, pairs, spectrum);
    int rejected = 0;
    for (int i = 0; i < kN; ++i) {
        double nearest = std::numeric_limits<double>::infinity();
        for (int j = 0; j < kN; ++j) {
            const double exact = p.k[j] / p.m[j];
            nearest = std::min(nearest, std::abs(pairs[i].lambda - exact) / exact);
        }
        BOOST_TEST_MESSAGE("computed " << es.eigenvalues()[i] << ", Rayleigh quotient "
                                       << pairs[i].lambda << ", nearest finite eigenvalue at "
                                       << nearest << ": " << describe(c[i]));
        if (c[i].accepted) {
            BOOST_TEST(nearest <= kEigenvalueErrorTolerance);
        } else {
            ++rejected;
        }
    }
    // Here every computed pair is wrong by ≥ 1 %, the lowest by 34 %: all rejected, although the
    // two large ones have a backward error of round-off (2.5e-17): the backward error alone
    // cannot see this failure, the B⁻¹-norm bound does.
    BOOST_TEST(rejected == kN);
}

// A general pencil: an exact pair has a round-off backward error; a perturbed eigenvector is
// rejected; an eigenvector of an infinite eigenvalue (B x = 0) is rejected by its participation.
BOOST_AUTO_TEST_CASE(general_pairs_are_checked_by_backward_error_and_participation) {
    MatX A = MatX::Zero(4, 4);
    A << 2, 1, 0, 0, 0, 3, 1, 0, 0, 0, 5, 1, 0, 0, 0, 7;  // upper triangular: λ = diag
    const SparseMatrix As = A.sparseView();
    const SparseMatrix I = MatX(MatX::Identity(4, 4)).sparseView();
    const Eigen::EigenSolver<MatX> es(A);
    for (int i = 0; i < 4; ++i) {
        const EigenpairCheck c =
            check_general_pair(As, I, es.eigenvalues()[i], es.eigenvectors().col(i), true);
        BOOST_TEST(c.accepted);
        BOOST_TEST(c.backward_error < 1e-14);
        VecXc x = es.eigenvectors().col(i);
        x[(i + 1) % 4] += 1e-6;
        BOOST_TEST(!check_general_pair(As, I, es.eigenvalues()[i], x, true).accepted);
    }
    MatX B = MatX::Identity(4, 4);
    B(3, 3) = 0.0;
    VecXc e = VecXc::Zero(4);
    e[3] = 1.0;
    // A e₃ = (0, 0, 1, 7): with λ huge the backward error is small, the participation zero.
    const EigenpairCheck c = check_general_pair(A.sparseView(), B.sparseView(), 1e17, e, true);
    BOOST_TEST_MESSAGE("infinite eigenvalue: " << describe(c));
    BOOST_TEST(!c.accepted);
    BOOST_TEST(c.failure == "mass participation");
}

BOOST_AUTO_TEST_SUITE_END()
