// Whether a discrete solution still describes the beam: the kinematic check of the mixed elements.
//
// A mixed element relates its end nodes' rotations through its curvature κ (seed 002 Eq. 48): in
// SO(3), R_b = R_a exp(ΔL C^ab κ) up to the element's discretization error, which is O(t³) for an
// element turning by t = |ΔL κ| (the quaternion's Cayley step turns by 4 atan(t/4), short of t by
// t³/48, docs/mixed-formulation.md). The three-parameter charts (Rodrigues, WM, rotation vector,
// Euler angles) impose Eq. 48 on their parameters with the tangent inverse H⁻¹ evaluated at the
// element's parameter mid-point. Past π the charts are
// strongly distorted (the rotation vector's H⁻¹ scales the part of κ across ψ by (φ/2)cot(φ/2),
// which changes sign at π and diverges at 2π), so with the axis varying along the beam the
// constant of that O(t³) grows tenfold (measured on the precessing helix: defect ≈ 0.22 t³ for the
// rotation vector, 0.25 t³ for continuous WM, 0.14 t³ for plain WM, 0.02 t³ for the quaternion,
// at every mesh from 16 to 64 elements: a consistent local error, with a large constant). On a mesh
// whose elements turn by ~1 rad the nodes then no longer follow from the curvature: the equations
// are solved to tolerance (`converged`), but they no longer model the beam, and the answer is off
// by O(L) (0.49 L for the rotation vector on the 16-element precessing helix at κL = 4π, where the
// quaternion on the same mesh is off by 0.13 L). The solution is the continuation of the discrete
// path (the same to 1e-13 for 10 … 160 load sub-steps); no parameter reaches its singular angle.
//
// The check is chart-independent: from the rotations the formulation reports (the nodes' and the
// element's turn ΔL C^ab κ, StaticProblem::rotation_stations) it measures each element's defect
// d = angle(exp(t)ᵀ R_aᵀ R_b). It accepts d ≤ kMaxRelativeDefect · |t| + kDefectRoundOff with
// kMaxRelativeDefect = (π/2)²/48 ≈ 5.1 %: an element's kinematics may be as unfaithful to its
// curvature as those of a quaternion element turning by π/2 about a fixed axis (the most a linear
// element can be asked to resolve), no more. The bound is a property of the element, not of a
// case: a quaternion element turning by less than π/2 passes (measured defect ≤ t³/48 on every
// path tried), a three-parameter element fails where its chart error, not its turn, dominates.
// Conservative case: WM with the continuous map is only C¹ at its switch angles (π, 3π, …), so
// an element straddling one loses an order and may be stopped on a coarse mesh although the
// answer is as accurate as the quaternion's (roll-up, 16 elements, λ = 3.5:
// docs/mixed-formulation.md). The measured consequence on the precessing helix (continuum
// reference, tip error / L at κL = 2π, 3π, 4π): 16 elements, rotation vector 0.071 (3.7 %, passes),
// 0.35 and 0.49 (stopped at 3π, 9.1 %); quaternion 0.037, 0.070, 0.13 (at most 1.7 %, passes); 32
// elements, rotation vector 0.018, 0.022, 0.046 (3.7 %, passes).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/model.hpp"
#include "core/static_state.hpp"

namespace rotbeam {

inline constexpr double kMaxRelativeDefect = (kPi / 2) * (kPi / 2) / 48.0;
// The status of a run stopped by the check (the solver statuses are in core/static_driver.hpp).
inline constexpr const char* kKinematicsUnresolved = "kinematics-unresolved";
// Composing three rotation matrices and taking an angle: ~1e-15 rad; with margin.
inline constexpr double kDefectRoundOff = 1e-12;

struct KinematicDefect {
    int member = -1;
    int element = -1;     // within the member, from 1 at its start
    double turn = 0.0;    // |ΔL C^ab κ| [rad]
    double defect = 0.0;  // angle(exp(t)ᵀ R_aᵀ R_b) [rad]
};

// The element with the largest defect / (kMaxRelativeDefect·turn + kDefectRoundOff) — the worst
// against the bound — or nothing when `stations` hold no element station.
std::optional<KinematicDefect> worst_kinematic_defect(
    const std::vector<StaticProblem::RotationStation>& stations);

bool within_kinematic_bound(const KinematicDefect& d);

// "element 12 of member 'beam' turns by 0.63 rad with its curvature, its nodes by a rotation
// 0.067 rad (11 %) away from that (bound 10 %)".
std::string describe_kinematic_defect(const Model& model, const KinematicDefect& d);

}  // namespace rotbeam
