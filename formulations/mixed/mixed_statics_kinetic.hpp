// MixedStatics::kinetic_spectrum (core/static_stability_kinetic.hpp): the stability of a mixed
// static state from the linearized free motion about it, the modes the mixed modal analysis about
// a loaded state computes (mixed_modal.hpp). The dynamic residual F(X, Ẋ) with the loads frozen at
// the state's load factor (frozen_loads) is linearized at the static state at rest,
//   A x + B ẋ = 0,   (A + s B) φ = 0,   A = ∂F/∂X, B = ∂F/∂Ẋ,
// B holding the element momenta's mass (Eqs. 45–46, 49–50) and singular (F, M and the node
// unknowns have no rate: infinite eigenvalues, dropped by the shift-invert). The static tangent is
// the block of A on the statics' unknowns; the momentum rows add V = I⁻¹[P; H] = 0 at rest. Its
// eigenvalues nearest s = 0 (one of each conjugate pair, and the growing member of each real
// pair) are refined on A + sB with their first-order error estimates (solve_dae_modal_refined):
// a real s > 0 is a divergence, a complex s with Re s > 0 a flutter. Why this and not an inertia
// count: docs/solver-convergence.md, "The mixed formulation".
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/errors.hpp"
#include "core/static_stability_kinetic.hpp"
#include "formulations/mixed/mixed_dynamics.hpp"
#include "formulations/mixed/mixed_modal.hpp"
#include "formulations/mixed/mixed_statics.hpp"

namespace rotbeam::form {

template <param::RotationParameterization P>
KineticSpectrum MixedStatics<P>::kinetic_spectrum(int count) {
    // The mixed modes about a spinning state carry the Coriolis coupling (mixed_modal.hpp), but the
    // verdict's pairing of s with −s is argued for the motion at rest only
    // (core/static_stability_kinetic.hpp), as in the displacement formulation.
    if (model_.rotating_frame.active())
        return {{}, "no kinetic criterion in a rotating frame (the gyroscopic terms)"};
    KineticSpectrum out;
    try {
        // The undamped motion, as the displacement formulation's M q̈ + K q = 0: the verdict
        // pairs s with −s (a decaying s has a growing partner), which damping would break.
        Model frozen = frozen_loads(model_, lambda_);
        for (Member& member : frozen.members) {
            for (SectionStation& st : member.sections) st.section.damping.setZero();
        }
        MixedDynamics<P> dyn(frozen, 1.0);
        const VecX x0 = dyn.from_static_state(x_);
        VecX r;
        SparseMatrix A;
        SparseMatrix B;
        dyn.evaluate(0.0, x0, VecX::Zero(dyn.size()), r, &A, &B);
        const DaeModalSolution modes =
            solve_dae_modal_refined(A, B, std::min(count, std::max(1, size() / 4)));
        for (std::size_t i = 0; i < modes.frequencies_hz.size(); ++i) {
            const std::complex<double> s(modes.growth_rates[i],
                                         2.0 * kPi * modes.frequencies_hz[i]);
            const EigenpairCheck& c = modes.checks[i];
            // error_estimate is relative to |s| (core/quadratic_eigenpair.hpp); none: infinite.
            const double relative = c.error_estimate >= 0.0
                                        ? c.error_estimate
                                        : std::numeric_limits<double>::infinity();
            const double error = std::abs(s) > 0.0 ? relative * std::abs(s) : relative;
            out.eigenvalues.push_back({s, error, c.accepted, c.failure});
        }
    } catch (const SolverError& e) {
        out.unavailable = std::string("the eigenvalues of the linearized motion: ") + e.what();
    } catch (const InputError& e) {
        // A section without a mass (the dynamics invert it) or a structure the dynamics refuse:
        // the mixed formulation has no energy to fall back on.
        out.unavailable =
            std::string("no kinetic criterion, the mixed formulation's only one: ") + e.what();
    }
    return out;
}

}  // namespace rotbeam::form
