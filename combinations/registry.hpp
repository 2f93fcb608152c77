// The combination registry: which formulations there are, and what each one offers with each
// parameterization (analyses, time integrators, interpolation strategies, the WM map, the MIP
// Newton). The parameterizations themselves are listed in parameterizations/registry.hpp; the
// classes each combination solves with are in combinations/dispatch.hpp.
//
// The runner, the gate, the suite, the studies, the benches and the tests iterate over
// all_combinations() or kFormulations; none of them names a formulation or parameterization
// outside an enum. Adding a formulation: an enumerator of Formulation (core/choices.hpp) with its
// name, one FormulationTraits entry below, and its StaticsOf specialization in dispatch.hpp (the
// static_asserts there and here refuse a formulation without either); docs/architecture.md.
#pragma once

#include <array>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "core/choices.hpp"
#include "parameterizations/registry.hpp"

namespace rotbeam::comb {

// What one formulation offers.
struct FormulationTraits {
    Formulation id;
    bool dynamics;  // a dynamic analysis exists
    bool modal;     // a modal analysis exists
    // The time integrators it takes; the first is the default (Integrator::automatic).
    std::span<const Integrator> integrators;
    // Its rotation interpolation strategies (discretization.interpolation); empty: none.
    std::span<const Interpolation> interpolations;
    // It takes discretization.wm_map (with Wiener–Milenković: has_wm_map).
    bool wm_maps;
    // It takes the mixed-integration-point Newton (solver.mip); else why not.
    bool mip;
    std::string_view no_mip_reason;
    // It takes a lumped mass (discretization.mass_rule: lumped); else why not.
    bool lumped_mass;
    std::string_view no_lumped_mass_reason;
    // Why the stability of its static equilibria is not assessed (core/static_stability.hpp);
    // empty: assessed, at dead loads.
    std::string_view no_stability_reason;
};

inline constexpr std::array kDisplacementIntegrators = {
    Integrator::generalized_alpha, Integrator::gauss_legendre_2, Integrator::gauss_legendre_3};
inline constexpr std::array kDisplacementInterpolations = {Interpolation::relative,
                                                           Interpolation::direct};
inline constexpr std::array kMixedIntegrators = {Integrator::trapezoidal, Integrator::ida,
                                                 Integrator::radau_iia_3};

// One entry per Formulation, in enum order.
inline constexpr std::array kFormulations = {
    // Displacement-based (seed 000; docs/displacement-formulation.md).
    FormulationTraits{Formulation::displacement, true, true, kDisplacementIntegrators,
                      kDisplacementInterpolations, false, true, "", true, "", ""},
    // Mixed (seed 002; docs/mixed-formulation.md, docs/mixed-dynamics.md).
    FormulationTraits{Formulation::mixed,
                      true,
                      true,
                      kMixedIntegrators,
                      {},
                      true,
                      false,
                      "the mixed formulation's section resultants are unknowns already; mip is "
                      "for the displacement formulation",
                      false,
                      "'lumped' is not available in the mixed formulation (element momenta, no "
                      "nodal masses); consistent | midpoint",
                      ""},
};

namespace detail {
constexpr bool formulations_in_enum_order() {
    if (kFormulations.size() != ChoiceNames<Formulation>::kNames.size()) return false;
    for (std::size_t i = 0; i < kFormulations.size(); ++i) {
        if (kFormulations[i].id != static_cast<Formulation>(i)) return false;
        if (kFormulations[i].integrators.empty()) return false;
    }
    return true;
}
}  // namespace detail
static_assert(detail::formulations_in_enum_order(),
              "kFormulations must list every Formulation once, in enum order, each with at least "
              "one integrator");

constexpr const FormulationTraits& traits(Formulation f) {
    return kFormulations[static_cast<std::size_t>(f)];
}

// The parameterizations with a WM map choice (the mixed formulation's continuous map,
// parameterizations/wiener_milenkovic_continuous.hpp, exists for Wiener–Milenković only).
template <class P>
inline constexpr bool kHasWmMap = std::is_same_v<P, param::WienerMilenkovic>;

// Whether the combination takes discretization.wm_map.
bool has_wm_map(Formulation f, ParameterizationId rotation);

// The integrator a dynamic analysis uses (Integrator::automatic: the formulation's first).
Integrator integrator_for(Formulation f, Integrator asked);
// Whether the formulation integrates with `asked` (automatic always).
bool takes_integrator(Formulation f, Integrator asked);
// The names of the formulation's integrators, "trapezoidal | ida".
std::string integrator_names(Formulation f);

// One formulation × parameterization, with a strategy where the combination has one.
struct Combination {
    Combination() = default;
    Combination(Formulation f, ParameterizationId r = {}, std::optional<Interpolation> i = {},
                std::optional<WmMap> m = {})
        : formulation(f), rotation(r), interpolation(i), wm_map(m) {}
    Formulation formulation = Formulation::displacement;
    ParameterizationId rotation{};
    std::optional<Interpolation> interpolation;  // nothing: the case's
    std::optional<WmMap> wm_map;                 // nothing: the case's
    // e.g. "displacement/quaternion/relative", "mixed/wiener-milenkovic/continuous"
    std::string label() const;
    std::string formulation_name() const { return std::string(choice_name(formulation)); }
    std::string rotation_name() const { return std::string(param::name_of(rotation)); }
    bool operator==(const Combination&) const = default;
    bool operator<(const Combination& o) const { return label() < o.label(); }
};

// Every formulation × parameterization, formulation-major, in registry order. with_interpolation:
// one per interpolation strategy where the formulation has them; with_wm_map: one per WM map where
// the combination has one.
std::vector<Combination> all_combinations(bool with_interpolation, bool with_wm_map = false);

// The formulations, in enum order.
std::vector<Formulation> formulations();

}  // namespace rotbeam::comb
