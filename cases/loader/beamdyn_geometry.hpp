// BeamDyn's reference line of one member, reproduced from its source (BeamDyn.f90,
// InitializeNodalLocations; docs/beamdyn-import.md states the construction):
//
// - the member's key points k = 1..n are given the parameter ξ_k = 2 (z_k − z_1)/(z_n − z_1) − 1
//   (their z coordinate, scaled to [−1, 1]);
// - a Lagrange polynomial on q = min(order + 1, n, 7) Gauss–Lobatto–Legendre points of ξ is
//   fitted to x, y, z and the twist of the key points by least squares (normal equations), with
//   the first and last equations replaced so that the curve passes through the end key points;
// - the finite-element nodes lie on that curve at the GLL points of ξ; the tangent there is
//   dX/dξ normalized, the twist the fitted twist (BeamDyn negates the deck's initial_twist).
//
// The curve is a polynomial of degree q − 1 in ξ, so the element of order ≥ q − 1 that
// interpolates it through its nodes reproduces it exactly.
#pragma once

#include <vector>

#include "cases/loader/beamdyn_deck.hpp"
#include "core/types.hpp"

namespace rotbeam::cases {

class BeamDynMemberLine {
  public:
    // Key points [first, first + count) of the deck; the order is order_elem.
    BeamDynMemberLine(const std::vector<BeamDynKeyPoint>& key_points, int first, int count,
                      int order);

    Vec3 position(double xi) const;     // blade-root frame
    Vec3 derivative(double xi) const;   // dX/dξ
    double twist_rad(double xi) const;  // the frame's rotation about the tangent, radians
    double length() const;              // ∫ |dX/dξ| dξ (Gauss, exact to round-off)
    int fit_points() const { return static_cast<int>(nodes_.size()); }

  private:
    std::vector<double> nodes_;          // GLL points of the fit
    std::vector<Vec3> position_values_;  // the fitted curve at those points
    std::vector<double> twist_values_;   // degrees, as BeamDyn stores them (negated)
};

}  // namespace rotbeam::cases
