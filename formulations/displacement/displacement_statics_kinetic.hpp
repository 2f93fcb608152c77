// DisplacementStatics::kinetic_spectrum (core/static_stability_kinetic.hpp): the linearized free
// motion about the current static state, M q̈ + K q = 0, with the tangent K = ∂r/∂x through the
// retraction (follower-load stiffness included: not symmetric) and the modal mass M at the
// state's rotations in the same unknowns [δu; δψ] — the pair the modal analysis about a static
// state uses (displacement_modal.hpp). At an equilibrium (r = 0) the linearization does not
// depend on the chart of the increments. Solved by the solver of the modes about a spinning state
// with G = 0 (gyroscopic_modal.hpp: the first-order pencil's shift-invert Arnoldi about s = 0,
// each pair refined on the quadratic problem with its first-order error estimate), which keeps
// one of each conjugate pair (Im s > 0) and the growing member of a real pair.
#pragma once

#include <algorithm>

#include "core/errors.hpp"
#include "core/static_stability_kinetic.hpp"
#include "formulations/displacement/displacement_modal.hpp"
#include "formulations/displacement/displacement_statics.hpp"
#include "formulations/displacement/gyroscopic_modal.hpp"

namespace rotbeam::form {

template <param::RotationParameterization P>
KineticSpectrum DisplacementStatics<P>::kinetic_spectrum(int count) {
    KineticSpectrum out;
    if (model_.rotating_frame.active()) {
        // Its small oscillations carry the Coriolis coupling G as well (a modal analysis about
        // the rotating state has it: docs/rotating-frame.md); not built here.
        out.unavailable = "no kinetic criterion in a rotating frame (the gyroscopic terms)";
        return out;
    }
    if (additive_) {
        out.unavailable =
            "no kinetic criterion with the additive update (its tangent's columns "
            "are in the parameters, the mass matrix's in the spatial increments)";
        return out;
    }
    for (const Member& member : model_.members) {
        for (const SectionStation& st : member.sections) {
            if (st.section.mass) continue;
            out.unavailable = "no kinetic criterion without a mass: member '" + member.name +
                              "' states no density or mass (the stability of a non-conservative "
                              "equilibrium depends on the mass distribution)";
            return out;
        }
    }
    VecX r;
    SparseMatrix K;
    const AssemblyCounters kept = counters_;  // an assessment, not a solve
    evaluate(r, &K);
    counters_ = kept;
    const SparseMatrix M = assemble_mass_matrix(model_, build_mass_mesh(model_),
                                                [&](int node) { return P::matrix(p_[node]); });
    const SparseMatrix G(K.rows(), K.cols());
    try {
        const GyroscopicModes modes =
            solve_gyroscopic_modes(K, G, M, std::min(count, std::max(1, size() / 2)));
        for (const GyroscopicMode& m : modes.modes) {
            out.eigenvalues.push_back({m.s, m.error, m.check.accepted, m.check.failure});
        }
    } catch (const SolverError& e) {
        out.unavailable = std::string("the eigenvalues of the linearized motion: ") + e.what();
    }
    return out;
}

}  // namespace rotbeam::form
