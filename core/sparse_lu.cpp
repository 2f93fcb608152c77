#include "core/sparse_lu.hpp"

#include <klu.h>

#include <Eigen/LU>
#include <Eigen/SparseLU>
#include <optional>

#include "core/klu_settings.hpp"

namespace rotbeam {

struct SparseLUSolver::Impl {
    bool klu = false;
    bool dense = false;
    // Dense: the matrix and its LU in the same memory (no allocation after the first pattern).
    MatX dense_matrix;
    std::optional<Eigen::PartialPivLU<Eigen::Ref<MatX>>> dense_lu;
    // Eigen
    Eigen::SparseLU<SparseMatrix, Eigen::COLAMDOrdering<int>> lu;
    // KLU
    klu_common common{};
    klu_symbolic* symbolic = nullptr;
    klu_numeric* numeric = nullptr;
    double pivoted_rcond = 0.0;
    // The pattern the analysis belongs to.
    Eigen::Index rows = -1, nonzeros = -1;
    bool analyzed = false;
    int analyses = 0;

    ~Impl() { free_klu(); }
    void free_klu() {
        if (numeric != nullptr) klu_free_numeric(&numeric, &common);
        if (symbolic != nullptr) klu_free_symbolic(&symbolic, &common);
    }
    bool klu_factor_pivoted(int* Ap, int* Ai, double* Ax) {
        if (numeric != nullptr) klu_free_numeric(&numeric, &common);
        numeric = klu_factor(Ap, Ai, Ax, symbolic, &common);
        if (numeric == nullptr || common.status != KLU_OK) return false;
        klu_rcond(symbolic, numeric, &common);
        pivoted_rcond = common.rcond;
        return true;
    }
};

SparseLUSolver::SparseLUSolver(bool refactor_in_place) : impl_(std::make_unique<Impl>()) {
    impl_->klu = refactor_in_place;
    if (impl_->klu) set_klu_settings(impl_->common);
}
SparseLUSolver::SparseLUSolver(Kind kind) : SparseLUSolver(kind == Kind::klu_refactor) {
    impl_->dense = kind == Kind::dense;
}
SparseLUSolver::~SparseLUSolver() = default;
SparseLUSolver::SparseLUSolver(SparseLUSolver&&) noexcept = default;
SparseLUSolver& SparseLUSolver::operator=(SparseLUSolver&&) noexcept = default;

bool SparseLUSolver::factorize(const SparseMatrix& J) {
    Impl& s = *impl_;
    const bool new_pattern = !s.analyzed || J.rows() != s.rows || J.nonZeros() != s.nonzeros;
    if (s.dense) {
        if (new_pattern) {
            s.dense_matrix.setZero(J.rows(), J.cols());
            s.dense_lu.emplace(s.dense_matrix);  // binds the LU to dense_matrix's memory
            s.analyzed = true;
            ++s.analyses;
            s.rows = J.rows();
            s.nonzeros = J.nonZeros();
        }
        s.dense_matrix.setZero();
        for (Eigen::Index c = 0; c < J.outerSize(); ++c) {
            for (SparseMatrix::InnerIterator it(J, c); it; ++it) {
                s.dense_matrix(it.row(), c) = it.value();
            }
        }
        s.dense_lu->compute(s.dense_matrix);
        // PartialPivLU does not flag singularity: a zero pivot leaves a zero on U's diagonal.
        return s.dense_matrix.allFinite() && (s.dense_matrix.diagonal().array() != 0.0).all();
    }
    if (!s.klu) {
        if (new_pattern) {
            s.lu.analyzePattern(J);
            ++s.analyses;
        }
        s.lu.factorize(J);
        s.analyzed = true;
        s.rows = J.rows();
        s.nonzeros = J.nonZeros();
        return s.lu.info() == Eigen::Success;
    }
    // KLU's interface takes non-const arrays; it does not write to them.
    int* Ap = const_cast<int*>(J.outerIndexPtr());
    int* Ai = const_cast<int*>(J.innerIndexPtr());
    double* Ax = const_cast<double*>(J.valuePtr());
    if (new_pattern) {
        s.free_klu();
        s.symbolic = klu_analyze(static_cast<int>(J.rows()), Ap, Ai, &s.common);
        if (s.symbolic == nullptr) return false;
        s.analyzed = true;
        ++s.analyses;
        s.rows = J.rows();
        s.nonzeros = J.nonZeros();
        return s.klu_factor_pivoted(Ap, Ai, Ax);
    }
    if (klu_refactor(Ap, Ai, Ax, s.symbolic, s.numeric, &s.common) != 1 ||
        klu_rcond(s.symbolic, s.numeric, &s.common) != 1 ||
        !(s.common.rcond >= 1e-3 * s.pivoted_rcond)) {
        return s.klu_factor_pivoted(Ap, Ai, Ax);
    }
    return true;
}

int SparseLUSolver::symbolic_analyses() const { return impl_->analyses; }

double SparseLUSolver::factor_nonzeros() const {
    const Impl& s = *impl_;
    if (s.dense) return static_cast<double>(s.rows) * static_cast<double>(s.rows);
    if (!s.klu) return static_cast<double>(s.lu.nnzL() + s.lu.nnzU());
    return s.numeric == nullptr ? 0.0 : static_cast<double>(s.numeric->lnz + s.numeric->unz);
}

void SparseLUSolver::solve(const VecX& b, VecX& x) {
    Impl& s = *impl_;
    if (s.dense) {
        x = s.dense_lu->solve(b);
        return;
    }
    if (!s.klu) {
        x = s.lu.solve(b);
        return;
    }
    x = b;
    klu_solve(s.symbolic, s.numeric, static_cast<int>(x.size()), 1, x.data(), &s.common);
}

}  // namespace rotbeam
