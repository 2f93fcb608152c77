#include "core/refined_ritz_modes.hpp"

#include <algorithm>
#include <optional>
#include <sstream>
#include <utility>

#include "core/errors.hpp"

namespace rotbeam {

std::vector<RefinedRitzMode> refined_ritz_modes(const ShiftInvertRitz& ritz, double shift,
                                                const QuadraticPencil& pencil, int count,
                                                const std::string& what) {
    struct Candidate {
        std::complex<double> s;
        Eigen::Index index;
    };
    std::vector<Candidate> kept;
    for (Eigen::Index i = 0; i < ritz.theta.size(); ++i) {
        const std::optional<std::complex<double>> s = ritz_eigenvalue(ritz, i, shift);
        if (!s) continue;
        const bool real = std::abs(s->imag()) <= kRealEigenvalueTolerance * std::abs(*s);
        if (real ? s->real() > 0.0 : s->imag() > 0.0) kept.push_back({*s, i});
    }
    if (static_cast<int>(kept.size()) < count) {
        std::ostringstream m;
        m << "modal analysis " << what << " (Arnoldi): only " << kept.size() << " modes found, "
          << count << " requested";
        throw SolverError(m.str());
    }
    std::sort(kept.begin(), kept.end(),
              [](const Candidate& a, const Candidate& b) { return a.s.imag() < b.s.imag(); });
    kept.resize(static_cast<size_t>(count));

    const Eigen::Index n = pencil.K.rows();
    std::vector<RefinedRitzMode> out;
    for (const Candidate& c : kept) {
        RefinedQuadraticPair r =
            refine_quadratic_pair(pencil, c.s, ritz.vectors.col(c.index).head(n));
        out.push_back({r.s, c.s, std::move(r.x), std::move(r.check), r.error, r.steps});
    }
    std::stable_sort(
        out.begin(), out.end(),
        [](const RefinedRitzMode& a, const RefinedRitzMode& b) { return a.s.imag() < b.s.imag(); });
    return out;
}

}  // namespace rotbeam
