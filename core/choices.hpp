// The named choices of a case (formulation, schemes and strategies) as enums, with their names.
//
// A name is parsed into its enum once, where it enters the program (the case loader, which also
// reads the command line's overrides); everything past that point compares enums. The names are
// those of the case format (docs/case-format.md) and of the result files, in enum order:
// choice_name(e) is what a result file prints, parse_choice<E>(name) its inverse.
//
// The parameterization is chosen by a ParameterizationId: an index into the parameterization
// registry (parameterizations/registry.hpp), which core does not know, so it has no enumerators
// here; the registry turns names into ids and ids into types. Which formulation takes which
// scheme or strategy is listed in combinations/registry.hpp.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rotbeam {

// Index of a parameterization in param::AllParameterizations; 0 is the first listed (the
// quaternion), the default of a case that names none.
enum class ParameterizationId : int {};

enum class Formulation { displacement, mixed };

// How the displacement formulation interpolates rotations between nodes (docs/architecture.md).
enum class Interpolation { relative, direct };

// How a Newton increment updates the nodal rotations of the displacement formulation.
enum class Update { multiplicative, additive };

// The mixed formulation's Wiener–Milenković rescaling map: `plain` (seed 002 as published) or
// `continuous` (GXBeam's, parameterizations/wiener_milenkovic_continuous.hpp).
enum class WmMap { plain, continuous };

// The time integrator; `automatic` (no name in the case) is the formulation's first listed.
// gauss_legendre_2/3: Gauss–Legendre collocation with 2/3 stages (core/gauss_collocation.hpp);
// radau_iia_3: the 3-stage Radau IIA method on the implicit DAE (core/dae_radau.hpp).
enum class Integrator {
    automatic,
    generalized_alpha,
    trapezoidal,
    ida,
    gauss_legendre_2,
    gauss_legendre_3,
    radau_iia_3
};

// Where a dynamic analysis starts: at rest in the reference configuration, or at rest from the
// static equilibrium of the loads at t = 0.
enum class InitialState { rest, static_equilibrium };

// How the inertia is integrated: the displacement formulation's mass quadrature (consistent,
// one mid-point, or nodal GLL points), the mixed formulation's element mass (consistent: the
// element average of the section mass, midpoint: its mid-length value; no lumped rule).
enum class MassRule { consistent, midpoint, lumped };

enum class LinearSolver { sparse, dense };

// The static nonlinear solver: the in-house Newton or KINSOL (additive systems only).
enum class Driver { newton, kinsol };

// Which side of the run the error estimate's companions lie on (docs/error-estimates.md): finer
// meshes and time steps (h/2 and h/4, Δt/2), or coarser ones (2h and 4h, 2Δt), which cost a
// fraction of the run instead of several runs.
enum class CompanionSide { finer, coarser };

// The names of each choice, in enum order (ChoiceNames<E>::kNames[static_cast<size_t>(e)]).
template <class E>
struct ChoiceNames;

template <>
struct ChoiceNames<Formulation> {
    static constexpr std::array<std::string_view, 2> kNames = {"displacement", "mixed"};
};
template <>
struct ChoiceNames<Interpolation> {
    static constexpr std::array<std::string_view, 2> kNames = {"relative", "direct"};
};
template <>
struct ChoiceNames<Update> {
    static constexpr std::array<std::string_view, 2> kNames = {"multiplicative", "additive"};
};
template <>
struct ChoiceNames<WmMap> {
    static constexpr std::array<std::string_view, 2> kNames = {"plain", "continuous"};
};
template <>
struct ChoiceNames<Integrator> {
    // `automatic` has no name in a case file: parse_choice never returns it.
    static constexpr std::array<std::string_view, 7> kNames = {
        "",           "generalized-alpha", "trapezoidal",
        "ida",        "gauss-legendre-2",  "gauss-legendre-3",
        "radau-iia-3"};
};
template <>
struct ChoiceNames<InitialState> {
    static constexpr std::array<std::string_view, 2> kNames = {"rest", "static"};
};
template <>
struct ChoiceNames<MassRule> {
    static constexpr std::array<std::string_view, 3> kNames = {"consistent", "midpoint", "lumped"};
};
template <>
struct ChoiceNames<LinearSolver> {
    static constexpr std::array<std::string_view, 2> kNames = {"sparse", "dense"};
};
template <>
struct ChoiceNames<Driver> {
    static constexpr std::array<std::string_view, 2> kNames = {"newton", "kinsol"};
};
template <>
struct ChoiceNames<CompanionSide> {
    static constexpr std::array<std::string_view, 2> kNames = {"finer", "coarser"};
};

template <class E>
constexpr std::string_view choice_name(E e) {
    return ChoiceNames<E>::kNames[static_cast<std::size_t>(e)];
}

// The enum named `name`, or nothing for an unknown (or empty) name.
template <class E>
constexpr std::optional<E> parse_choice(std::string_view name) {
    for (std::size_t i = 0; i < ChoiceNames<E>::kNames.size(); ++i) {
        if (!name.empty() && ChoiceNames<E>::kNames[i] == name) return static_cast<E>(i);
    }
    return std::nullopt;
}

// Every non-empty name of E, in enum order (the valid values a message lists).
template <class E>
std::vector<std::string> choice_names() {
    std::vector<std::string> names;
    for (std::string_view n : ChoiceNames<E>::kNames) {
        if (!n.empty()) names.emplace_back(n);
    }
    return names;
}

}  // namespace rotbeam
