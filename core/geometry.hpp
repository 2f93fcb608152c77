// The reference line of a member, evaluated by arc length s ∈ [0, L].
//
// Given a Model and a member index, ReferenceGeometry gives the reference position x^r(s), the
// unit tangent, the reference frame R^r(s) = [e1 e2 e3] (material → inertial, e1 = tangent) and
// the initial curvature in material axes k(s) = axial(R^rᵀ R^r′) (seed 000: the strain measure
// that is zero in the reference configuration subtracts it; seed 002 Eqs. 20, 22: k).
//
// Frame conventions (comment at the top of core/model.hpp):
// - default: e1 = tangent, e2 = normalize(ẑ × e1) (ŷ projected onto the normal plane when
//   e1 ∥ ẑ), e3 = e1 × e2; a beam along +x has R^r = I;
// - circular arc: e3 = the plane normal, e2 points toward the centre;
// - `e2_hint` (any line kind): e2 = the hint projected onto the plane normal to e1;
// - twist θ(s) (linear from twist_start to twist_end, or the polynomial through the member's
//   twist_values at equally spaced s/L) rotates e2, e3 about e1:
//   R^r = R_base · exp(θ ẽ1), hence k = exp(−θ ẽ1) k_base + θ′ e1.
//
// Line kinds: straight; exact circular arc about a centre (short way round, or right-handed
// about `normal` when given — then the sweep may exceed π); key-point curve = natural cubic
// spline (GSL) through start, keypoints, end in the chord-length parameter, re-parameterized by
// arc length with GSL adaptive quadrature and Brent root finding.
//
// Invalid geometry (coincident ends, arc ends at different radii, degenerate arc plane) throws
// InputError with a message naming the problem; the case loader adds file/line/key.
// The object is immutable after construction and cheap to copy (the spline is shared).
#pragma once

#include <memory>
#include <vector>

#include "core/lagrange.hpp"
#include "core/model.hpp"
#include "core/types.hpp"

namespace rotbeam {

struct KeypointSpline;  // GSL splines and the arc-length table (geometry.cpp)

class ReferenceGeometry {
  public:
    ReferenceGeometry(const Model& model, int member);

    double length() const { return length_; }
    Vec3 position(double s) const;
    Vec3 tangent(double s) const;
    Mat3 frame(double s) const;         // R^r(s) = [e1 e2 e3]
    Vec3 curvature(double s) const;     // k(s) = axial(R^rᵀ R^r′), material axes
    double twist(double s) const;       // θ(s), radians
    double twist_rate(double s) const;  // θ′(s), radians per unit length

    // R^r(s) and its derivative with respect to s (used by curvature and by tests).
    void frame_and_derivative(double s, Mat3& R, Mat3& dR_ds) const;

  private:
    void init_arc(const ReferenceLine& line, const Vec3& x0, const Vec3& x1);
    // Position, tangent e1 and de1/ds of the untwisted line at s.
    void line_point(double s, Vec3& x, Vec3& e1, Vec3& de1) const;

    LineKind kind_ = LineKind::straight;
    Vec3 start_ = Vec3::Zero();
    Vec3 direction_ = Vec3::UnitX();  // straight: unit tangent
    // arc
    Vec3 center_ = Vec3::Zero();
    Vec3 normal_ = Vec3::UnitZ();
    Vec3 radial0_ = Vec3::UnitX();  // unit vector centre → start
    double radius_ = 0.0;
    // frame rule
    bool has_hint_ = false;
    Vec3 hint_ = Vec3::Zero();
    double twist_start_ = 0.0;
    double twist_end_ = 0.0;
    std::shared_ptr<const LagrangeBasis> twist_basis_;  // on s/L ∈ [0, 1]; null: linear twist
    std::vector<double> twist_values_;
    double length_ = 0.0;
    std::shared_ptr<const KeypointSpline> spline_;
};

}  // namespace rotbeam
