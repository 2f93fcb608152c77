// MixedStatics<P> under solver.assemble_all_terms: the inertial terms of seed 002 Eqs. 45–46 and
// 49–50 (mixed_dynamic_element.hpp) assembled in a static analysis, as a formulation that ignores
// the scene would. At rest the momenta P, H and every rate vanish, so f_u, f_ψ of the inertia are
// exact zeros and so are their derivatives with respect to c: the result is the default's, the
// kernel's cost is real. The rows of Eqs. 49–50 and the columns of P, H have no unknowns in the
// statics; only the f_u, f_ψ rows and the c columns are scattered. Included only by
// mixed_statics.cpp.
#pragma once

#include <Eigen/LU>

#include "core/errors.hpp"
#include "formulations/mixed/mixed_dynamic_common.hpp"
#include "formulations/mixed/mixed_dynamic_element.hpp"
#include "formulations/mixed/mixed_statics.hpp"

namespace rotbeam::form {

template <param::RotationParameterization P>
void MixedStatics<P>::prepare_rest_terms() {
    for (const MixedElement& el : layout_.elements) {
        // A static case need not give a section mass: then the identity stands in (with P = H = 0
        // every term is zero whatever the mass; only the kernel's cost is measured).
        Mat6 inverse = Mat6::Identity();
        try {
            const Eigen::FullPivLU<Mat6> lu(mixed_element_mass(model_, el));
            if (lu.isInvertible()) inverse = lu.inverse();
        } catch (const InputError&) {
        }
        rest_mass_inverse_.push_back(inverse);
    }
}

template <param::RotationParameterization P>
void MixedStatics<P>::assemble_rest_terms(int e, int a, int b, VecX& residual,
                                          SparseMatrix* jacobian) {
    const MixedElement& el = layout_.elements[static_cast<std::size_t>(e)];
    const int column = numbering_.element_column(e) + 3;
    const Params c = x_.template segment<K>(column);
    const Vec3 momentum = Vec3::Zero(), angular_momentum = Vec3::Zero();
    MixedInertiaResult<K> q;
    mixed_element_inertia<P>(el, rest_mass_inverse_[static_cast<std::size_t>(e)], c, momentum,
                             angular_momentum, MixedElementRates<K>{}, jacobian != nullptr, q);
    ++counters_.inertial_terms;
    for (const int node : {a, b}) {
        residual.segment<3>(node) += q.fu;
        residual.segment<3>(node + 3) += q.fpsi;
        if (jacobian != nullptr) {
            add_mixed_block(*jacobian, node, column, q.J_x.template block<6, K>(0, 0));
        }
    }
}

}  // namespace rotbeam::form
