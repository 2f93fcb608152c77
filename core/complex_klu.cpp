#include "core/complex_klu.hpp"

#include <klu.h>

#include "core/klu_settings.hpp"

namespace rotbeam {

struct ComplexKlu::Impl {
    klu_common common{};
    klu_symbolic* symbolic = nullptr;
    klu_numeric* numeric = nullptr;
    double pivoted_rcond = 0.0;
    Eigen::Index rows = -1, nonzeros = -1;
    int pivoted = 0;

    Impl() { set_klu_settings(common); }
    ~Impl() { release(); }
    Impl(const Impl&) = delete;
    Impl& operator=(const Impl&) = delete;
    void release() {
        if (numeric != nullptr) klu_z_free_numeric(&numeric, &common);
        if (symbolic != nullptr) klu_free_symbolic(&symbolic, &common);
    }
    bool factor_pivoted(int* Ap, int* Ai, double* Ax) {
        if (numeric != nullptr) klu_z_free_numeric(&numeric, &common);
        numeric = klu_z_factor(Ap, Ai, Ax, symbolic, &common);
        ++pivoted;
        if (numeric == nullptr || common.status != KLU_OK) return false;
        if (klu_z_rcond(symbolic, numeric, &common) != 1) return false;
        pivoted_rcond = common.rcond;
        return pivoted_rcond > 0.0;
    }
};

ComplexKlu::ComplexKlu() : impl_(std::make_unique<Impl>()) {}
ComplexKlu::~ComplexKlu() = default;

bool ComplexKlu::factorize(const ComplexSparse& E) {
    Impl& s = *impl_;
    // KLU's interface takes non-const arrays; it does not write to them. A complex<double> is two
    // doubles, real then imaginary ([complex.numbers.general]), KLU's packed complex format.
    int* Ap = const_cast<int*>(E.outerIndexPtr());
    int* Ai = const_cast<int*>(E.innerIndexPtr());
    auto* Ax = reinterpret_cast<double*>(const_cast<std::complex<double>*>(E.valuePtr()));
    if (s.symbolic == nullptr || E.rows() != s.rows || E.nonZeros() != s.nonzeros) {
        s.release();
        s.symbolic = klu_analyze(static_cast<int>(E.rows()), Ap, Ai, &s.common);
        if (s.symbolic == nullptr) return false;
        s.rows = E.rows();
        s.nonzeros = E.nonZeros();
        return s.factor_pivoted(Ap, Ai, Ax);
    }
    if (s.numeric == nullptr || klu_z_refactor(Ap, Ai, Ax, s.symbolic, s.numeric, &s.common) != 1 ||
        klu_z_rcond(s.symbolic, s.numeric, &s.common) != 1 ||
        !(s.common.rcond >= 1e-3 * s.pivoted_rcond)) {
        return s.factor_pivoted(Ap, Ai, Ax);
    }
    return true;
}

void ComplexKlu::solve_in_place(Eigen::VectorXcd& x) {
    Impl& s = *impl_;
    klu_z_solve(s.symbolic, s.numeric, static_cast<int>(x.size()), 1,
                reinterpret_cast<double*>(x.data()), &s.common);
}

int ComplexKlu::pivoted_factorizations() const { return impl_->pivoted; }

}  // namespace rotbeam
