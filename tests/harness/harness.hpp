// The generic harness's walk over the combination registry (combinations/registry.hpp): every
// formulation × parameterization × strategy the registry lists, dispatched to its types the way
// the runner dispatches a case, so a combination added to the registry is checked without a line
// here. Each check keeps its own list of states per combination.
#pragma once

#include <string>

#include "combinations/dispatch.hpp"
#include "combinations/registry.hpp"
#include "core/model.hpp"

namespace rotbeam::test {

// The combination's choices written into a model's discretization.
inline void apply(const comb::Combination& c, Model& m) {
    m.discretization.rotation = c.rotation;
    if (c.interpolation) m.discretization.displacement.interpolation = *c.interpolation;
    if (c.wm_map) m.discretization.mixed.wm_map = *c.wm_map;
}

// fn.template operator()<F, P>(c) for every registered combination c, with F its formulation and
// P the parameterization it solves with (Wiener–Milenković with the continuous map where c says).
template <class Fn>
void for_each_combination(Fn&& fn) {
    for (const comb::Combination& c : comb::all_combinations(true, true)) {
        Model m;
        apply(c, m);
        comb::dispatch_formulation(c.formulation, [&]<Formulation F>() {
            comb::dispatch_parameterization_of<F>(
                m.discretization, [&]<class P>() { fn.template operator()<F, P>(c); });
        });
    }
}

}  // namespace rotbeam::test
