// The parameterization type lists of the typed tests (BOOST_AUTO_TEST_CASE_TEMPLATE), all derived
// from the registries (parameterizations/registry.hpp, combinations/registry.hpp): a
// parameterization added there is tested without a test edit. A test that needs a property of
// the parameterization (three parameters, a chart that rescaling keeps away from its singular
// set, ...) selects by that property, never by name.
#pragma once

#include <boost/mpl/list.hpp>
#include <type_traits>

#include "combinations/registry.hpp"
#include "parameterizations/parameter_constraint.hpp"
#include "parameterizations/registry.hpp"
#include "parameterizations/wiener_milenkovic_continuous.hpp"

namespace rotbeam::test {

namespace detail {
template <class List>
struct ToMpl;
template <class... Ts>
struct ToMpl<param::TypeList<Ts...>> {
    using type = boost::mpl::list<Ts...>;
};

template <class... Lists>
struct Concat;
template <>
struct Concat<> {
    using type = param::TypeList<>;
};
template <class... As>
struct Concat<param::TypeList<As...>> {
    using type = param::TypeList<As...>;
};
template <class... As, class... Bs, class... Rest>
struct Concat<param::TypeList<As...>, param::TypeList<Bs...>, Rest...> {
    using type = typename Concat<param::TypeList<As..., Bs...>, Rest...>::type;
};

template <template <class> class Keep, class List>
struct Filter;
template <template <class> class Keep, class... Ts>
struct Filter<Keep, param::TypeList<Ts...>> {
    using type = typename Concat<
        std::conditional_t<Keep<Ts>::value, param::TypeList<Ts>, param::TypeList<>>...>::type;
};

// P, followed by Wiener–Milenković with the continuous map where P takes the mixed formulation's
// WM map (the variant combinations/dispatch.hpp solves with).
template <class P>
using WithMixedVariant =
    std::conditional_t<comb::kHasWmMap<P>, param::TypeList<P, param::WienerMilenkovicContinuous>,
                       param::TypeList<P>>;
template <class List>
struct MixedSolved;
template <class... Ts>
struct MixedSolved<param::TypeList<Ts...>> {
    using type = typename Concat<WithMixedVariant<Ts>...>::type;
};
}  // namespace detail

// Selectors (Keep<P>::value).
template <class P>
struct Any : std::true_type {};
// Three independent parameters (no constraint row: parameter_constraint.hpp).
template <class P>
struct ThreeParameters : std::bool_constant<param::ParameterConstraint<P>::kRows == 0> {};

// Every registered parameterization with Keep<P>, in registry order.
template <template <class> class Keep = Any>
using ParameterizationTypes =
    typename detail::ToMpl<typename detail::Filter<Keep, param::AllParameterizations>::type>::type;

// Every parameterization the mixed formulation solves with, with Keep<P>: the registered ones and,
// after Wiener–Milenković, its continuous-map variant (discretization.wm_map: continuous).
template <template <class> class Keep = Any>
using MixedParameterizationTypes = typename detail::ToMpl<typename detail::Filter<
    Keep, typename detail::MixedSolved<param::AllParameterizations>::type>::type>::type;

}  // namespace rotbeam::test
