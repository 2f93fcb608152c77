// A manufactured solution in space and time for both formulations:
// a prescribed motion u(s, t), R(s, t) of a straight rod whose rotation passes 2π about
// an axis that varies along the rod and in time, and the distributed force and moment that make it
// an exact motion of the continuum equations, inertia included. Derivation and measured orders in
// docs/reference-solutions.md §Manufactured motion.
//
// Rod along +x, length L, free at both ends (a body in flight: no support, the loads drive it).
// With s̄ = s/L, A = exp(α ẽ₁) and B = exp(β ẽ₃) (a bend about the spun e₃, so the rotation
// axis varies along the rod and in time):
//   R(s, t) = A B,   α = φ(t) + λ(t) a cos(πs̄),   β = μ(t) b sin²(πs̄),
//   u(s, t) = λ(t) w(s) + μ(t) v(s),
//   w = L (0.05 c₁, 0.2 c₁, 0.1 c₂),   v = L (0, 0.1 c₂, −0.15 c₁),   c₁ = cos(πs̄), c₂ = cos(2πs̄),
//   φ(t) = φ₀ + Ω t + ½ Ω̇ t²,   λ(t) = sin(ω₁t + θ₁),   μ(t) = cos(ω₂t).
// φ spins the rod about its axis past 2π (defaults: 1.5π at t = 0, 2.45π at t = 1, through 2π at
// t ≈ 0.56); λ twists it, μ bends it. Every s-derivative vanishes at both ends with β = 0 there,
// so x′ = e₁ = R e₁ and the strains and resultants vanish at the free ends: no end load.
// Why free, not clamped: holding a rotation past 2π with the ends fixed takes a twist strain of
// order 2π/L, carried by dead distributed torques — Ziegler's/Greenhill's rod under dead axial
// torque, dynamically unstable. First versions (free tip, then both ends clamped, twist 2.25–2.5π)
// were: held static (ω₁ = ω₂ = 0) at λ = 0.3 the clamped one left the exact state by 6e-2 rad
// within 1 s from a 1e-5 space error, although the static solver converged to it; the observed
// time orders were noise. Here the large rotation is a spin (strain-free), the twist and bend
// strains are small, and the exact motion is followed to the space error.
//
// Velocities are spatial (Ṙ = ω̃R): ω = α̇e₁ + β̇Ae₃, ω̇ = α̈e₁ + β̈Ae₃ + β̇α̇ e₁ × Ae₃ (the same
// algebra as the curvature k = α′e₁ + β′Ae₃ along s). Momenta from the 6×6 section mass M*
// (material axes): [P; H] = M* [Rᵀu̇; Rᵀω], p = RP, h = RH. The loads are those of the equations
// of motion shared by seed 000 Eq. 9 (with the inertial forces F^I) and seed 002 Eq. 17 (with the
// momenta P, H; written in inertial components):
//   f = ṗ − n′,   μ = ḣ + u̇ × p − m′ − x′ × n,
// with ṗ = ω × p + R Ṗ, Ṗ = M*_top [V̇; Ω̇], V̇ = Rᵀü − Ω × V, Ω̇ = Rᵀω̇ (likewise ḣ), every
// derivative analytic. For the physical mass [m I, m η̃ᵀ; m η̃, ρ*] these are the displacement
// formulation's F^I = [m ü + (ω̇~ + ω̃ω̃) m η; m η̃ ü + ρ ω̇ + ω̃ ρ ω].
#pragma once

#include "core/model.hpp"
#include "core/oracles/manufactured.hpp"
#include "core/types.hpp"

namespace rotbeam::oracle {

// A fully populated SPD section mass of the physical form [m I, m η̃ᵀ; m η̃, ρ*]: m = 1, centre of
// mass offset η* with three components, ρ* with every product of inertia non-zero.
Mat6 manufactured_mass();

struct ManufacturedMotion {
    double length = 1.0;
    double spin0 = 1.5 * kPi;        // φ₀
    double spin_rate = 2.0;          // Ω
    double spin_acceleration = 1.0;  // Ω̇
    double twist = 0.5;              // a: twist amplitude about the spin
    double b = 0.5;                  // bend amplitude (the axis varies)
    double omega1 = 2.0;             // λ(t) = sin(ω₁t + θ₁)
    double phase1 = 0.5;
    double omega2 = 3.0;                      // μ(t) = cos(ω₂t)
    Mat6 stiffness = manufactured_section();  // material axes
    Mat6 mass = manufactured_mass();          // material axes, [m I, m η̃ᵀ; m η̃, ρ*]

    struct State {
        Vec3 u = Vec3::Zero(), u_dot = Vec3::Zero(), u_ddot = Vec3::Zero();
        Mat3 R = Mat3::Identity();
        Vec3 omega = Vec3::Zero(), omega_dot = Vec3::Zero();  // spatial
    };
    State state(double s, double t) const;
    // The rotation vector of R(s, t), continuous in s and t (not the principal value: the branch
    // nearest αe₁ + βe₃, so a chart past π sees no jump between neighbouring points).
    Vec3 rotation_vector(double s, double t) const;
    // Material strains [Γ; K] and section resultants [F; M] = C*[Γ; K] (material axes).
    Vec6 strains(double s, double t) const;
    // Distributed force and moment per unit length at (s, t), inertial components.
    void loads(double s, double t, Vec3& force, Vec3& moment) const;
    // Largest rotation angle over the rod at time t (sampled at 201 points).
    double max_angle(double t) const;
};

// The model of the manufactured motion: points root (s = 0), q1, mid, q3 (s = L/4, L/2, 3L/4)
// and tip, four members of `elements_per_member` elements joined at the interior points, no
// support, the manufactured load (in time) on every member, the motion's stiffness
// and mass. A dynamic analysis 0 … end_time with step dt.
Model manufactured_motion_model(const ManufacturedMotion& motion, int elements_per_member,
                                double dt, double end_time);

}  // namespace rotbeam::oracle
