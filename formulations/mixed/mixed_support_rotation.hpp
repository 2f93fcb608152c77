// The parameters of a prescribed support rotation exp(ψ) in the mixed formulation.
//
// The elements next to a support difference their nodes' parameters (seed 002 Eq. 48), so the
// support's parameters must lie on the same sheet of the chart as its neighbours': those reached
// continuously from the identity along exp(tψ), t from 0 to 1. The quaternion's exponential and
// the rotation vector, WM and Rodrigues along their axis are continuous in ψ; Euler angles'
// from_rotation_vector returns principal values (a1, a3 in (−π, π]), which jump by 2π when the
// prescribed angle passes π — the elements would take the jump for a turn of the beam, and the
// equations have a solution there: measured on the static manufactured rod (a tip prescribed to
// a twist of 2.5π), every mesh from 4 to 64 elements per member left the exact state at λ = 0.45,
// where the tip's twist passes π, for one a full turn away (π rad at the mid point) and reported
// `converged` (docs/studies.md, effectivity). For Euler angles the path is followed in steps of
// at most kSupportPathStep, each taking the parameters nearest the previous ones (rescale).
#pragma once

#include <algorithm>
#include <cmath>
#include <type_traits>

#include "core/types.hpp"
#include "parameterizations/euler_angles.hpp"

namespace rotbeam {

// Small against the 2π between sheets and the π between Euler angles' branches.
inline constexpr double kSupportPathStep = kPi / 8;

template <class P>
typename P::P continued_support_rotation(const Vec3& psi) {
    if constexpr (!std::is_same_v<P, param::EulerAngles>) {
        return P::from_rotation_vector(psi);
    } else {
        const int n = std::max(1, static_cast<int>(std::ceil(psi.norm() / kSupportPathStep)));
        typename P::P p = P::identity();
        for (int i = 1; i <= n; ++i) {
            p = P::rescale(P::from_rotation_vector(psi * (static_cast<double>(i) / n)), p);
        }
        return p;
    }
}

}  // namespace rotbeam
