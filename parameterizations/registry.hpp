// The list of rotation parameterizations, and the one place that turns a name into a type.
//
// Adding a parameterization: write its header (satisfying RotationParameterization), include it
// below and add X(Type) to ROTBEAM_FOR_EACH_PARAMETERIZATION. Everything else derives from that
// list: the type list AllParameterizations, the ids and names (the case loader's valid values),
// the runner's dispatch, every formulation's explicit instantiations and the combination registry
// (combinations/registry.hpp). The CTest check `parameterizations_registered` fails when a header
// of parameterizations/ satisfies the concept without being listed here.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "core/choices.hpp"
#include "parameterizations/concept.hpp"
#include "parameterizations/euler_angles.hpp"
#include "parameterizations/quaternion.hpp"
#include "parameterizations/rodrigues.hpp"
#include "parameterizations/rotation_vector.hpp"
#include "parameterizations/wiener_milenkovic.hpp"

// Variants: WienerMilenkovicContinuous (parameterizations/wiener_milenkovic_continuous.hpp) is
// Wiener–Milenković with GXBeam's continuous map, chosen by `discretization.wm_map`, not a
// parameterization of its own; it is not in the list (the CTest check `parameterizations_registered`
// reads this line's first word after "Variants:").
//
// X(Type) for every parameterization, in registry order (the first is a case's default), e.g.
// `#define INSTANTIATE(P) template class Beam<param::P>;`. The one list of parameterizations.
#define ROTBEAM_FOR_EACH_PARAMETERIZATION(X) \
    X(Quaternion)                            \
    X(WienerMilenkovic)                      \
    X(Rodrigues)                             \
    X(RotationVector)                        \
    X(EulerAngles)

namespace rotbeam::param {

template <class... Ts>
struct TypeList {
    static constexpr int kSize = static_cast<int>(sizeof...(Ts));
    template <class T>
    static constexpr bool kContains = (std::is_same_v<T, Ts> || ...);
    // The position of T in the list (kSize when absent).
    template <class T>
    static constexpr int kIndexOf = [] {
        int i = 0;
        (void)((std::is_same_v<T, Ts> ? true : (++i, false)) || ...);
        return i;
    }();
};

namespace detail {
struct ListStart;
template <class List>
struct DropFirst;
template <class First, class... Rest>
struct DropFirst<TypeList<First, Rest...>> {
    using type = TypeList<Rest...>;
};
// Expands to `, Type` to follow ListStart (a comma-separated list without a trailing comma).
// NOLINTNEXTLINE(bugprone-macro-parentheses): a type in a template argument list.
#define ROTBEAM_DETAIL_COMMA_TYPE(T) , T
}  // namespace detail

using AllParameterizations = typename detail::DropFirst<
    TypeList<detail::ListStart ROTBEAM_FOR_EACH_PARAMETERIZATION(ROTBEAM_DETAIL_COMMA_TYPE)>>::type;
#undef ROTBEAM_DETAIL_COMMA_TYPE

namespace detail {
template <class... Ts>
constexpr bool all_satisfy_concept(TypeList<Ts...>) {
    return (RotationParameterization<Ts> && ...);
}
template <class... Ts>
constexpr bool names_distinct(TypeList<Ts...>) {
    const std::string_view names[] = {Ts::kName...};
    for (std::size_t i = 0; i < sizeof...(Ts); ++i) {
        for (std::size_t j = 0; j < i; ++j) {
            if (names[i] == names[j]) return false;
        }
    }
    return true;
}
}  // namespace detail

static_assert(detail::all_satisfy_concept(AllParameterizations{}));
static_assert(detail::names_distinct(AllParameterizations{}),
              "two parameterizations share a kName: a case could not choose between them");

// The id of P (its position in the list), the value a Model's discretization.rotation holds.
template <class P>
constexpr ParameterizationId id_of() {
    static_assert(AllParameterizations::kContains<P>,
                  "not in ROTBEAM_FOR_EACH_PARAMETERIZATION (parameterizations/registry.hpp)");
    return static_cast<ParameterizationId>(AllParameterizations::kIndexOf<P>);
}

// The default of a case that names no rotation (Discretization::rotation's value-initialized id).
static_assert(id_of<Quaternion>() == ParameterizationId{},
              "the quaternion is the default parameterization and must be listed first");

// Every id, in registry order.
std::vector<ParameterizationId> parameterization_ids();
// The kName of every parameterization, in registry order (the valid values of a case's rotation).
std::vector<std::string> parameterization_names();
// The kName of the parameterization with this id.
std::string_view name_of(ParameterizationId id);
// The id of the parameterization named `name`; nothing for an unknown name (the caller, the case
// loader, says which file and key).
std::optional<ParameterizationId> parse_parameterization(std::string_view name);

namespace detail {
template <class F, class First, class... Rest>
decltype(auto) dispatch(int index, F& f, TypeList<First, Rest...>) {
    if constexpr (sizeof...(Rest) == 0) {
        return f.template operator()<First>();
    } else {
        if (index == 0) return f.template operator()<First>();
        return dispatch(index - 1, f, TypeList<Rest...>{});
    }
}

template <class F, class... Ts>
void for_each(F& f, TypeList<Ts...>) {
    (f.template operator()<Ts>(), ...);
}

// Throws std::logic_error: an id that no parse produced.
[[noreturn]] void throw_invalid_id(ParameterizationId id);
}  // namespace detail

// f.template operator()<P>() for the parameterization P with this id; every branch must return
// the same type.
template <class F>
decltype(auto) dispatch_parameterization(ParameterizationId id, F&& f) {
    const int index = static_cast<int>(id);
    if (index < 0 || index >= AllParameterizations::kSize) detail::throw_invalid_id(id);
    return detail::dispatch(index, f, AllParameterizations{});
}

// f.template operator()<P>() for every P in AllParameterizations, in order.
template <class F>
void for_each_parameterization(F&& f) {
    detail::for_each(f, AllParameterizations{});
}

}  // namespace rotbeam::param
