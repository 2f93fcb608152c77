// The list of rotation parameterizations and the one place that turns a name into a type.
//
// Adding a parameterization: write its header (satisfying RotationParameterization) and add it to
// AllParameterizations and ROTBEAM_FOR_EACH_PARAMETERIZATION below (a static_assert checks that
// the two agree). The runner's single switch uses dispatch_parameterization; the formulations'
// explicit instantiations use ROTBEAM_FOR_EACH_PARAMETERIZATION (an explicit instantiation needs
// the type spelled out, which a type list cannot do without a macro).
#pragma once

#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "parameterizations/concept.hpp"
#include "parameterizations/euler_angles.hpp"
#include "parameterizations/quaternion.hpp"
#include "parameterizations/rodrigues.hpp"
#include "parameterizations/rotation_vector.hpp"
#include "parameterizations/wiener_milenkovic.hpp"

namespace rotbeam::param {

template <class... Ts>
struct TypeList {
    static constexpr int kSize = static_cast<int>(sizeof...(Ts));
    template <class T>
    static constexpr bool kContains = (std::is_same_v<T, Ts> || ...);
};

using AllParameterizations =
    TypeList<Quaternion, WienerMilenkovic, Rodrigues, RotationVector, EulerAngles>;

// X(Type) for every parameterization, e.g. `#define INSTANTIATE(P) template class Beam<param::P>;`
#define ROTBEAM_FOR_EACH_PARAMETERIZATION(X) \
    X(Quaternion) X(WienerMilenkovic) X(Rodrigues) X(RotationVector) X(EulerAngles)

namespace detail {
// Both expand to an operator and its operand, to be chained after a first term (`0 +1 +1`);
// parentheses would turn the chain into calls, hence the NOLINT.
// NOLINTBEGIN(bugprone-macro-parentheses)
#define ROTBEAM_DETAIL_COUNT_ONE(T) +1
#define ROTBEAM_DETAIL_CHECK_LISTED(T) &&AllParameterizations::kContains<T>
// NOLINTEND(bugprone-macro-parentheses)
inline constexpr int kMacroCount = 0 ROTBEAM_FOR_EACH_PARAMETERIZATION(ROTBEAM_DETAIL_COUNT_ONE);
static_assert(
    kMacroCount == AllParameterizations::kSize &&
        (true ROTBEAM_FOR_EACH_PARAMETERIZATION(ROTBEAM_DETAIL_CHECK_LISTED)),
    "ROTBEAM_FOR_EACH_PARAMETERIZATION and AllParameterizations must list the same types");
#undef ROTBEAM_DETAIL_COUNT_ONE
#undef ROTBEAM_DETAIL_CHECK_LISTED

template <class... Ts>
constexpr bool all_satisfy_concept(TypeList<Ts...>) {
    return (RotationParameterization<Ts> && ...);
}
static_assert(all_satisfy_concept(AllParameterizations{}));

// Throws InputError naming `name` and the valid names.
[[noreturn]] void throw_unknown_parameterization(std::string_view name);

template <class F, class First, class... Rest>
decltype(auto) dispatch(std::string_view name, F& f, TypeList<First, Rest...>) {
    if constexpr (sizeof...(Rest) == 0) {
        if (name != First::kName) throw_unknown_parameterization(name);
        return f.template operator()<First>();
    } else {
        if (name == First::kName) return f.template operator()<First>();
        return dispatch(name, f, TypeList<Rest...>{});
    }
}

template <class F, class... Ts>
void for_each(F& f, TypeList<Ts...>) {
    (f.template operator()<Ts>(), ...);
}
}  // namespace detail

// The kName of every parameterization, in AllParameterizations order.
std::vector<std::string> parameterization_names();

// f.template operator()<P>() for the parameterization P named `name`; every branch must return
// the same type. Throws InputError listing the valid names for an unknown name.
template <class F>
decltype(auto) dispatch_parameterization(std::string_view name, F&& f) {
    return detail::dispatch(name, f, AllParameterizations{});
}

// f.template operator()<P>() for every P in AllParameterizations, in order.
template <class F>
void for_each_parameterization(F&& f) {
    detail::for_each(f, AllParameterizations{});
}

}  // namespace rotbeam::param
