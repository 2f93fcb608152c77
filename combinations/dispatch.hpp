// From a combination's ids to its types: the static problem class of each formulation ×
// parameterization, and the dispatch the runner's single switch uses. Every combination the
// registries list is checked here at compile time (static_assert below): a formulation without
// its StaticsOf, or a parameterization a formulation's class cannot take, fails the build of
// every file that includes this header, not a run.
#pragma once

#include <concepts>
#include <memory>
#include <utility>

#include "combinations/registry.hpp"
#include "core/model.hpp"
#include "core/static_state.hpp"
#include "formulations/displacement/displacement_statics.hpp"
#include "formulations/mixed/mixed_statics_of.hpp"
#include "parameterizations/wiener_milenkovic_continuous.hpp"

namespace rotbeam::comb {

// The static problem class of formulation F with parameterization P.
template <Formulation F, class P>
struct StaticsOf;
template <class P>
struct StaticsOf<Formulation::displacement, P> {
    using type = form::DisplacementStatics<P>;
};
template <class P>
struct StaticsOf<Formulation::mixed, P> {
    using type = form::MixedStaticsOf<P>;
};

// A combination's static piece: a StaticProblem built from the model.
template <Formulation F, class P>
concept HasStatics = requires {
    typename StaticsOf<F, P>::type;
}
&&std::derived_from<typename StaticsOf<F, P>::type, StaticProblem>&&
    std::constructible_from<typename StaticsOf<F, P>::type, const Model&>;

namespace detail {
template <Formulation F, class... Ps>
constexpr bool has_statics_for(param::TypeList<Ps...>) {
    return (HasStatics<F, Ps> && ...);
}
template <std::size_t... I>
constexpr bool every_formulation_has_statics(std::index_sequence<I...>) {
    return (has_statics_for<static_cast<Formulation>(I)>(param::AllParameterizations{}) && ...);
}
}  // namespace detail
static_assert(
    detail::every_formulation_has_statics(std::make_index_sequence<kFormulations.size()>{}),
    "a formulation × parameterization of the registries has no static problem class "
    "(StaticsOf in combinations/dispatch.hpp)");
static_assert(HasStatics<Formulation::mixed, param::WienerMilenkovicContinuous>);

// f.template operator()<F>() for the formulation F (a compile-time constant in f).
template <class Fn>
decltype(auto) dispatch_formulation(Formulation formulation, Fn&& f) {
    static_assert(kFormulations.size() == 2, "add the new formulation's case to this switch");
    switch (formulation) {
        case Formulation::displacement:
            return f.template operator()<Formulation::displacement>();
        case Formulation::mixed:
            return f.template operator()<Formulation::mixed>();
    }
    return f.template operator()<Formulation::displacement>();  // unreachable: every enumerator
}

// f.template operator()<P>() for the parameterization the formulation F solves with: the
// registry's, or Wiener–Milenković with GXBeam's continuous map when F takes wm_map and the case
// asks for it.
template <Formulation F, class Fn>
decltype(auto) dispatch_parameterization_of(const Discretization& d, Fn&& f) {
    return param::dispatch_parameterization(d.rotation, [&]<class P>() -> decltype(auto) {
        if constexpr (traits(F).wm_maps && kHasWmMap<P>) {
            if (d.mixed.wm_map == WmMap::continuous) {
                return f.template operator()<param::WienerMilenkovicContinuous>();
            }
        }
        return f.template operator()<P>();
    });
}

}  // namespace rotbeam::comb
