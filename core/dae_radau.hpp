// The 3-stage Radau IIA method (Hairer & Wanner, "Solving ODEs II", §IV.5 Table 5.6, §IV.8;
// for DAEs §VI.1 and §VII.4) on the implicit DAE F(t, X, Ẋ) = 0 of core/dae_system.hpp.
//
// Nodes c = ((4 − √6)/10, (4 + √6)/10, 1), Butcher matrix A, b = the last row of A (stiffly
// accurate: X_{n+1} is the last stage). With the stage increments Z_i = Y_i − X_n and W = A⁻¹ the
// stage rates are Ẏ_i = (1/h) Σ_j w_ij Z_j (the derivative of the collocation polynomial through
// (t_n, X_n) and the stages), and the stage equations are
//   F(t_n + c_i h, X_n + Z_i, (1/h) Σ_j w_ij Z_j) = 0,    i = 1, 2, 3;
// X_{n+1} = X_n + Z_3, Ẋ_{n+1} = Ẏ_3, which satisfy F(t_{n+1}, X_{n+1}, Ẋ_{n+1}) = 0 (the last
// stage equation): each step ends on a consistent state. The algebraic unknowns' rates are not in F
// and are kept at zero (as in the trapezoidal scheme).
//
// Orders of the global error at the step points (constant steps; s = 3): 2s − 1 = 5 for an ODE
// and for every component of an index-1 DAE, differential and algebraic (HW II §VI.1: the method
// is stiffly accurate); index 2 (HW II §VII.4): differential 5, algebraic s = 3; index 3 in
// Hessenberg form (Hairer, Lubich & Roche, "The Numerical Solution of Differential-Algebraic
// Systems by Runge–Kutta Methods", Lecture Notes in Math. 1409, 1989): positions 2s − 1 = 5,
// velocities s = 3, multipliers s − 1 = 2. The mixed DAE of a closed loop (the joined beam,
// docs/mixed-dynamics.md "Index") has that structure: the loop closure constrains the positions
// u, c, the momenta P, H are the velocities, the redundant internal forces the multipliers. Radau
// IIA is L-stable: it damps the modes with ωh ≫ 1 (|R(iy)| → 0) and leaves the resolved ones almost
// untouched (the damping of a mode is O((ωh)^6) per step).
//
// Stage equations: simplified Newton (HW II §IV.8) with ∂F/∂X and ∂F/∂Ẋ evaluated once per step at
// the step start, J = I ⊗ ∂F/∂X + (W/h) ⊗ ∂F/∂Ẋ. With W = S Λ S⁻¹ (one real eigenvalue γ and one
// conjugate pair α ± iβ) the correction decouples into
//   E_γ = ∂F/∂X + (γ/h) ∂F/∂Ẋ            (real, factored by KLU with the pivot order kept),
//   E_α+iβ = ∂F/∂X + ((α + iβ)/h) ∂F/∂Ẋ  (complex, KLU in complex arithmetic with the pivot
//                                         order kept: core/complex_klu.hpp),
// both in the system's pattern; the conjugate eigenvalue's solution is the conjugate. No stage
// matrix of size 3n is formed. The convergence test is the project's (core/convergence.hpp) on the
// stacked stage residuals and corrections, scaled max norms, with the round-off floor of
// |∂F/∂X| + (‖W‖∞/h) |∂F/∂Ẋ|. Starting values: the previous step's collocation polynomial
// extrapolated to the new stage times (HW II §IV.8, "starting values"); at the first step and
// after a cut Z_i = c_i h Ẋ_n. A step whose stage iteration fails (no contraction in two iterations
// in a row, the iteration limit, a singular stage matrix, a parameterization refusing a stage
// state) is retried with h/2 (core/dae_fixed_steps.hpp).
//
// Adaptive steps (analysis.time_tolerance > 0; the loop of core/dae_fixed_steps.hpp, the control
// of core/step_size_control.hpp, error per unit step): the embedded estimate of HW II §IV.8,
// Eq. (8.19)–(8.20), written for F(t, X, Ẋ) = 0. For M ẏ = f(y), F = M Ẋ − f(X), so
// ∂F/∂Ẋ = M, ∂F/∂X = −J and E_γ = γ/h M − J is HW's (I − hγ0 J)/(hγ0) with γ0 = 1/γ; HW's
// err = (I − hγ0 J)⁻¹ [γ0 h f(y0) + Σ e_i Z_i] becomes
//   err = E_γ⁻¹ ∂F/∂Ẋ (Ẋ_n + Σ_i d_i Z_i / h),   d = γ e,
// since f(y0) = M Ẋ_n on the consistent state at the step start. Where it exceeds the allowance
// it is filtered once more, err ← E_γ⁻¹ (that right side − F(t_n, X_n + err, Ẋ_n)) (HW's
// f(y0 + err) in implicit form), which takes the estimate of the stiff components to zero as
// hλ → ∞. The estimate is of order 3: local error ∝ h^4 (q = 4), pessimistic for the method's
// h^6. Measured on the configuration only (the system's configuration(): the mixed formulation's
// u and c, over their state scales, max norm): the momenta are velocity-level unknowns (index 2
// in a closed loop) and the internal forces multipliers (index 3), whose estimates HW scale by h
// and h² (§VII.4); excluding them measures what the tolerance is about (the configuration),
// and the velocity error enters the configuration's through the kinematic equations. With the
// momenta included the stiff modes' momenta at the release of the free vibration kept the
// steps at 3e-8 s (measured).
#pragma once

#include "core/dae_driver.hpp"
