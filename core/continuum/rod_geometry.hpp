// The reference configuration of one member as the continuum solver sees it, computed here from
// core/model.hpp alone (it deliberately shares no code with core/geometry or the elements).
//
// Straight line: e1 = (end − start)/L; e2 = normalize(ẑ × e1), or ŷ projected normal to e1 when
// e1 ∥ ẑ, or the projected `e2_hint`; e3 = e1 × e2. Reference curvature k⁰ = 0.
// Circular arc (centre c, radius ρ, unit plane normal n, sweep Θ ∈ (0, 2π), L = ρΘ): the radial
// unit vector turns as r̂(s) = exp((s/ρ) ñ) r̂(0); e1 = n × r̂, e2 = −r̂ (toward the centre),
// e3 = n. Then R⁰(s) = exp((s/ρ) ñ) R⁰(0) and R⁰' = R⁰ (k⁰)~ with k⁰ = e3/ρ (material axes).
// Twist τ(s), linear in s, turns e2, e3 about e1: R^r = R⁰ exp(τ ẽ1), so the material reference
// curvature is k^r(s) = exp(−τ ẽ1) k⁰ + τ' e1.
#pragma once

#include <optional>

#include "core/model.hpp"
#include "core/types.hpp"

namespace rotbeam::continuum {

class RodGeometry {
  public:
    // Throws InputError for what the solver does not support (key-point lines, an e2 hint on an
    // arc) or for an inconsistent arc.
    explicit RodGeometry(const Model& model, const Member& member);

    double length() const { return length_; }
    Vec3 position(double s) const;
    Mat3 frame(double s) const;      // R^r(s): material → inertial
    Vec3 curvature(double s) const;  // k^r(s), material components
    // Arc length of a point lying on the reference line (within 1e-9 L), if it does.
    std::optional<double> locate(const Vec3& point) const;

  private:
    double twist(double s) const;
    LineKind kind_;
    Vec3 start_ = Vec3::Zero();
    Vec3 center_ = Vec3::Zero();
    Vec3 normal_ = Vec3::UnitZ();
    double radius_ = 0.0;
    double sweep_ = 0.0;
    double length_ = 0.0;
    Mat3 frame0_ = Mat3::Identity();  // untwisted R⁰(0)
    double twist_start_ = 0.0;
    double twist_end_ = 0.0;
};

}  // namespace rotbeam::continuum
