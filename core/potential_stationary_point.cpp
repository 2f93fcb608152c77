// Newton's method on the potential energy's gradient, from a formulation's equilibrium to the
// energy's own stationary point, and the inertia of the Hessian there (core/potential_hessian.hpp).
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "core/errors.hpp"
#include "core/potential_hessian.hpp"

namespace rotbeam {

namespace {

double largest_entry(const SparseMatrix& A) {
    double m = 0.0;
    for (int k = 0; k < A.outerSize(); ++k) {
        for (SparseMatrix::InnerIterator it(A, k); it; ++it) m = std::max(m, std::abs(it.value()));
    }
    return m;
}

// The Hessian and its factorization at one iterate.
struct EnergyHessian {
    PotentialHessian hessian;
    Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower, Eigen::AMDOrdering<int>> ldlt;
    double norm = 0.0;   // largest entry of S = D H D
    double known = 0.0;  // the scaled error of S's entries: the difference error, or n ε ‖S‖
    std::string failure;
};

void form_energy_hessian(PotentialSystem& potential, const VecX& scale, EnergyHessian& out) {
    out.hessian = potential.potential_hessian();
    out.failure = out.hessian.unavailable;
    if (!out.failure.empty()) return;
    const SparseMatrix S = scale.asDiagonal() * out.hessian.matrix * scale.asDiagonal();
    out.norm = largest_entry(S);
    out.known =
        std::max(out.hessian.scaled_error, static_cast<double>(scale.size()) *
                                               std::numeric_limits<double>::epsilon() * out.norm);
    out.ldlt.compute(S);
    if (out.ldlt.info() != Eigen::Success) out.failure = "the energy's Hessian met a zero pivot";
}

}  // namespace

// Newton's method with an iteration matrix kept while it contracts (a chord iteration): first the
// Newton solve's own tangent J when the driver passes its factorization (it differs from the
// Hessian by the residual's asymmetry, 1e-5 … 1e-3 of its entries, so the chord contracts by
// about that much per step, and costs a gradient and a solve), then the difference Hessian
// (~24 (p + 1) element gradients per element), formed when a step does not halve the previous
// one, and always at the last iterate, where it is assessed. Plain Newton on the Hessian where a
// fresh one does not contract (the start on a coarse mesh).
StaticStability assess_stability_at_stationary_point(StaticSystem& system,
                                                     PotentialSystem& potential,
                                                     const TangentSolve& tangent,
                                                     std::string& unavailable) {
    // Fresh Hessians allowed: from the discretization-sized distances of the benchmarks (scaled
    // 1e-5 … 1e-2) Newton's method needed at most six (two elements of order 2 on the 45° bend).
    constexpr int kMaxHessians = 10;
    constexpr int kMaxSteps = 100;
    // The search stays next to the equilibrium: a stationary point farther than this (scaled:
    // rotations in rad, displacements in the increment scale's length) is another state.
    constexpr double kMaxDistance = 0.1;
    // A step that no longer contracts is round-off (the gradient's floor is ~ε times the scaled
    // Hessian's condition number) if it is this small; the Hessian there differs from the one at
    // the stationary point by ~‖S‖ times it, which is added to its error (1e-8 of the largest
    // entry, below the difference Hessian's accuracy limit, 1e-7, in core/static_stability.cpp).
    constexpr double kRoundOffStep = 1e-8;
    // The tangent's chord stops here and the Hessian is formed: its own test (below) decides.
    constexpr double kTangentChordStep = 1e-12;
    const VecX& scale = system.increment_scale();
    const int n = system.size();
    system.save_state(NonlinearSystem::kLineSearchSlot);
    VecX moved = VecX::Zero(n);
    VecX gradient, y(n), dx(n);
    EnergyHessian H;
    bool have_hessian = false;
    bool fresh = false;  // H was formed at the current iterate
    int hessians = 0;
    std::string failure;
    auto form = [&] {
        if (++hessians > kMaxHessians) {
            failure = "more than " + std::to_string(kMaxHessians) + " Hessians";
            return;
        }
        form_energy_hessian(potential, scale, H);
        have_hessian = fresh = true;
        if (H.hessian.unavailable.empty()) {
            failure = H.failure;
        } else if (moved.lpNorm<Eigen::Infinity>() == 0.0) {
            unavailable = H.hessian.unavailable;  // none at the equilibrium itself
        } else {
            failure = H.hessian.unavailable;
        }
    };
    if (!tangent) form();
    double previous = std::numeric_limits<double>::infinity();
    StaticStability out;
    for (int steps = 0; failure.empty() && unavailable.empty(); ++steps) {
        if (!potential.potential_gradient(gradient)) {
            if (!have_hessian) form();  // the Hessian says why there is no potential
            if (failure.empty() && unavailable.empty()) failure = "the loads have no potential";
            break;
        }
        if (have_hessian) {
            y = H.ldlt.solve(-(scale.asDiagonal() * gradient).eval());
        } else {
            tangent(-gradient, dx);
            y = dx.cwiseQuotient(scale);
        }
        const double step = y.lpNorm<Eigen::Infinity>();
        if (!std::isfinite(step)) {
            failure = "the Newton step on the energy is not finite";
            break;
        }
        const bool contracting = step <= 0.5 * previous;
        // Converged when the remaining distance changes the Hessian by less than its own error;
        // stalled at round-off when a small step no longer contracts.
        const bool converged = have_hessian ? H.norm * step <= H.known : step <= kTangentChordStep;
        const bool stalled = step <= kRoundOffStep && !contracting;
        if (converged || stalled) {
            if (have_hessian && fresh) {
                H.hessian.scaled_error = std::max(H.hessian.scaled_error, H.norm * step);
                out = assess_potential_stability(H.hessian, scale);
                out.stationary_point_distance = moved.lpNorm<Eigen::Infinity>();
                break;
            }
            form();
            continue;
        }
        // A step that does not halve the last one forms the Hessian anew — and so does any
        // step of the tangent's chord that would leave the equilibrium.
        if ((!contracting && !fresh) ||
            (!have_hessian && (moved + y).lpNorm<Eigen::Infinity>() > kMaxDistance)) {
            form();
            continue;
        }
        if (steps == kMaxSteps || (moved + y).lpNorm<Eigen::Infinity>() > kMaxDistance) {
            std::ostringstream why;
            why.precision(2);
            why << "Newton's method on the energy "
                << (steps == kMaxSteps ? "did not converge" : "leaves the equilibrium")
                << " (scaled step " << step << " after " << steps + 1 << " steps, scaled distance "
                << (moved + y).lpNorm<Eigen::Infinity>() << ")";
            failure = why.str();
            break;
        }
        try {
            potential.move_along_potential_chart(scale.asDiagonal() * y);
        } catch (const SingularityError& error) {
            failure = std::string("the rotation chart is singular: ") + error.what();
            break;
        }
        moved += y;
        previous = step;
        fresh = false;
    }
    if (!unavailable.empty()) {
        out = StaticStability{};
        out.reason = unavailable;
    } else if (!failure.empty()) {
        out = StaticStability{};
        out.reason = "no stationary point of the energy found next to the equilibrium: " + failure;
    }
    system.restore_state(NonlinearSystem::kLineSearchSlot);
    return out;
}

}  // namespace rotbeam
