#include "cases/loader/beamdyn_geometry.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/errors.hpp"
#include "core/lagrange.hpp"
#include "core/quadrature.hpp"

namespace rotbeam::cases {

namespace {

// BeamDyn caps the fit at seven points (a polynomial of degree 6).
constexpr int kMaxFitPoints = 7;

}  // namespace

BeamDynMemberLine::BeamDynMemberLine(const std::vector<BeamDynKeyPoint>& key_points, int first,
                                     int count, int order) {
    const int q = std::min({order + 1, count, kMaxFitPoints});
    nodes_ = gauss_lobatto_legendre(q).points;
    const LagrangeBasis basis(nodes_);
    const BeamDynKeyPoint& a = key_points[static_cast<size_t>(first)];
    const BeamDynKeyPoint& b =
        key_points[static_cast<size_t>(first) + static_cast<size_t>(count) - 1];
    // Shp(i, k): fit function i at key point k, in the z-parameter.
    MatX shp(q, count);
    MatX data(count, 4);
    VecX values(q);
    for (int k = 0; k < count; ++k) {
        const BeamDynKeyPoint& p = key_points[static_cast<size_t>(first) + static_cast<size_t>(k)];
        const double xi = 2.0 * (p.z - a.z) / (b.z - a.z) - 1.0;
        basis.values(xi, values);
        shp.col(k) = values;
        data.row(k) << p.x, p.y, p.z, -p.twist_deg;
    }
    MatX normal = shp * shp.transpose();
    MatX rhs = shp * data;
    // The end equations replaced: the curve passes through the member's end key points.
    normal.row(0).setZero();
    normal.row(q - 1).setZero();
    normal(0, 0) = 1.0;
    normal(q - 1, q - 1) = 1.0;
    rhs.row(0) = data.row(0);
    rhs.row(q - 1) = data.row(count - 1);
    const Eigen::PartialPivLU<MatX> lu(normal);
    const MatX c = lu.solve(rhs);
    if (!c.allFinite()) {
        throw InputError(
            "the least-squares fit of the key points is singular (key points at the same z)");
    }
    for (int i = 0; i < q; ++i) {
        position_values_.emplace_back(c(i, 0), c(i, 1), c(i, 2));
        twist_values_.push_back(c(i, 3));
    }
}

Vec3 BeamDynMemberLine::position(double xi) const {
    const LagrangeBasis basis(nodes_);
    VecX n(fit_points());
    basis.values(xi, n);
    Vec3 x = Vec3::Zero();
    for (int i = 0; i < fit_points(); ++i) x += n(i) * position_values_[static_cast<size_t>(i)];
    return x;
}

Vec3 BeamDynMemberLine::derivative(double xi) const {
    const LagrangeBasis basis(nodes_);
    VecX dn(fit_points());
    basis.derivatives(xi, dn);
    Vec3 d = Vec3::Zero();
    for (int i = 0; i < fit_points(); ++i) d += dn(i) * position_values_[static_cast<size_t>(i)];
    return d;
}

double BeamDynMemberLine::twist_rad(double xi) const {
    const LagrangeBasis basis(nodes_);
    VecX n(fit_points());
    basis.values(xi, n);
    double t = 0.0;
    for (int i = 0; i < fit_points(); ++i) t += n(i) * twist_values_[static_cast<size_t>(i)];
    return t * std::numbers::pi / 180.0;
}

double BeamDynMemberLine::length() const {
    // |dX/dξ| is smooth (a polynomial's norm away from a cusp): 40 Gauss points integrate it
    // to round-off for the degrees ≤ 6 of the fit.
    const QuadratureRule rule = gauss_legendre(40);
    double l = 0.0;
    for (size_t i = 0; i < rule.points.size(); ++i) {
        l += rule.weights[i] * derivative(rule.points[i]).norm();
    }
    return l;
}

}  // namespace rotbeam::cases
