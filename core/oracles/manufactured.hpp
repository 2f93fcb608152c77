// A manufactured static solution for both formulations: a prescribed
// displacement u(s, λ) and rotation R(s, λ) of a straight rod whose rotation passes 2π about an
// axis that varies along the rod, and the distributed force and moment that make it an exact
// equilibrium of the continuum equations. Derivation in docs/reference-solutions.md
// §Manufactured solution.
//
// Rod along +x, length L, section stiffness C* (6×6, material axes, any SPD matrix), clamped at
// s = 0, motion prescribed at s = L. With A = exp(α ẽ₁) (twist) and B = exp(β ẽ₃) (a bend that
// vanishes at both ends, so the rotation axis varies along the rod):
//   R(s) = A(s) B(s),  α = λ a (s/L + 0.1 sin(πs/L)),  β = λ b sin(πs/L),
//   u(s) = λ w(s),     w = L (−0.2 (s/L)², 0.3 sin(πs/2L), 0.25 (s/L)³),
// so at the tip R = exp(λ a ẽ₁), u = λ w(L): linear in λ, as a prescribed constraint is.
// The large rotation is twist about the rod's axis, so the strains stay moderate (|Γ| ≲ 0.3):
// a first version turned the sections 2.5π about e₃ while the centreline stayed straight
// (strains of order one), and the continuation left that equilibrium for a neighbouring one
// near λ ≈ 0.9 unless it took ≥ 100 steps on fine meshes. The twist's torque GJ·2.5π/L is 0.58
// of the clamped rod's Greenhill buckling torque (≈ 2.86π EI/L), so the state is stable.
// Strains Γ = Rᵀx′ − e₁, K = Rᵀk (k = axial(R′Rᵀ)), resultants n = R C*_top[Γ; K],
// m = R C*_bottom[Γ; K]; the loads are those of the equilibrium equations shared by seed 000
// Eq. 9 (static part) and seed 002 Eq. 17:
//   f = −n′,   μ = −m′ − x′ × n,
// with every derivative analytic (no finite differences), so the loads are exact to round-off.
#pragma once

#include "core/model.hpp"
#include "core/types.hpp"

namespace rotbeam::oracle {

struct ManufacturedRod {
    double length = 1.0;
    double a = 2.5 * kPi;  // tip twist about e₁ at λ = 1 (passes 2π)
    double b = 0.8;        // amplitude of the bend about the twisted e₃ (the axis varies)
    Mat6 stiffness = Mat6::Identity();

    struct State {
        Vec3 displacement = Vec3::Zero();
        Mat3 rotation = Mat3::Identity();
    };
    State state(double s, double lambda) const;
    // Distributed force and moment per unit length at s (inertial components).
    void loads(double s, double lambda, Vec3& force, Vec3& moment) const;
};

// A fully populated, symmetric positive definite section with stiffnesses of order one (its
// strains at λ = 1 are of order one: the solution is a test of the discretization, not a
// physical state).
Mat6 manufactured_section();

// The model of the manufactured rod: points root (s = 0), q1, mid, q3 (s = L/4, L/2, 3L/4) and
// tip, four members of `elements_per_member` elements joined rigidly at the interior points
// (one rod), root clamped, tip prescribed, the manufactured load on every member, static load
// factors λ = 1/steps … 1. `formulation`, `rotation` and `order` go to the discretization.
Model manufactured_model(const ManufacturedRod& rod, int elements_per_member, int steps);

}  // namespace rotbeam::oracle
