// The constraint a parameterization's parameters carry beyond the rotation: ParameterConstraint<P>.
//
// Three parameters describe a rotation without redundancy: kRows = 0, no constraint. Four (the
// quaternion) carry one more, the norm: R(q) = C(q)/|q|² (quaternion.hpp Q1) does not see it, and
// the radial direction q is the null space of the tangents (H q = 0). A formulation that keeps the
// four parameters as unknowns uses these traits where the redundancy shows (the mixed formulation:
// docs/mixed-formulation.md, "The quaternion"):
//   residual(q) = ½(|q|² − 1), jacobian(q) = ∂residual/∂q = qᵀ   the unit-norm row of a structure
//                                                                 that no support fixes
//   radial_part(q, v) = q (qᵀv)/|q|²                              the part of a rate no tangent
//   sees algebraic_component(q)                                        the component of largest
//       magnitude: with q_k ≠ 0 the other components' tangent columns span R³, so holding q_k and
//       solving for the others is a regular chart of the rotation.
// Any parameterization registered later gets kRows = kSize − 3 from the primary template; a
// four-parameter one with another constraint specializes this template beside its header.
#pragma once

#include <Eigen/Core>

#include "parameterizations/concept.hpp"

namespace rotbeam::param {

template <RotationParameterization P>
struct ParameterConstraint {
    static_assert(P::kSize == 3, "a redundant parameterization specializes ParameterConstraint");
    static constexpr int kRows = 0;
};

// The unit norm of four parameters.
template <RotationParameterization P>
requires(P::kSize == 4) struct ParameterConstraint<P> {
    static constexpr int kRows = 1;
    static double residual(const Params<4>& q) { return 0.5 * (q.squaredNorm() - 1.0); }
    static Eigen::Matrix<double, 1, 4> jacobian(const Params<4>& q) { return q.transpose(); }
    static Params<4> radial_part(const Params<4>& q, const Params<4>& v) {
        return q * (q.dot(v) / q.squaredNorm());
    }
    static int algebraic_component(const Params<4>& q) {
        Eigen::Index k = 0;
        q.cwiseAbs().maxCoeff(&k);
        return static_cast<int>(k);
    }
};

}  // namespace rotbeam::param
