// The refinement sequences of the effectivity study (study_effectivity.cpp): every case with an
// independent reference × every combination × the formulation's estimate strategy, and the
// quantities of one level's result against the reference (effectivity_rows.hpp).
//
// References: the roll-up's exact tip (core/oracles/rollup.hpp, cantilever-moment), the exact
// state of the static manufactured rod at its interior points (core/oracles/manufactured.hpp,
// kManufacturedRodCase; its root and tip are clamped and prescribed, exact by construction), the
// continuum reference (core/continuum) for the 45° bend and the precessing helix, and for the
// joined beam's
// frequencies the displacement formulation at convergence (order 8 on 10 elements per member,
// consistent mass; its distance to order 7 sets the floor of the true error, as in
// tests/estimates/test_effectivity_modal.cpp).
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "effectivity_rows.hpp"
#include "study_common.hpp"

namespace rotbeam::cli {

enum class ReferenceKind { rollup_exact, manufactured_exact, continuum, converged_modes };

struct EffectivitySequence {
    std::string case_name;  // catalog name
    Combination combination;
    RefinementKind kind;  // p: displacement formulation (p+1), h: mixed (h/2, h/4 or 2h, 4h)
    ReferenceKind reference;
    std::vector<int> levels;             // orders (p) or elements per member (h)
    int p_elements = 0;                  // p: elements per member at every order
    std::vector<std::string> overrides;  // common to every level

    RunSpec spec(size_t level) const;
    std::string strategy() const {
        return kind == RefinementKind::p ? "p+1" : kind == RefinementKind::h ? "h/2,h/4" : "2h,4h";
    }
    std::string x_label() const {
        return kind == RefinementKind::p ? "order p" : "elements per member";
    }
};

// The study's sequences: the quick form (the roll-up, the bend and the manufactured rod, the
// quaternion with both formulations, three to four levels) or the full one (every combination,
// every case).
std::vector<EffectivitySequence> effectivity_sequences(bool quick);

// The runs a sequence's reference needs (a continuum solve, or the converged modal runs):
// their RunSpecs, the first the reference itself. Empty for the exact roll-up and manufactured rod.
std::vector<RunSpec> reference_specs(const EffectivitySequence& s);

// The quantities of `result` with a reference value: points' displacements and rotations at every
// load step (estimated or not), or the estimated frequencies paired with the reference modes by
// shape. `references` are
// the results of reference_specs(s), in that order.
LevelQuantities level_quantities(const EffectivitySequence& s, const nlohmann::json& result,
                                 const std::vector<nlohmann::json>& references);

}  // namespace rotbeam::cli
