#include "core/geometry.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_poly.h>
#include <gsl/gsl_roots.h>
#include <gsl/gsl_spline.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <sstream>

#include "core/errors.hpp"
#include "core/so3.hpp"

namespace rotbeam {

namespace {

// Relative tolerance for "same radius"/"in plane" checks of arcs: the case file gives
// coordinates with ~7–10 significant digits, so 1e-6 accepts printed data and refuses wrong data.
constexpr double kArcTolerance = 1e-6;
// Arc-length quadrature and inversion: far below anything a finite-element error can resolve.
constexpr double kArcLengthTolerance = 1e-13;

// GSL's default handler aborts; inside geometry every status is checked instead.
class GslHandlerOff {
  public:
    GslHandlerOff() : previous_(gsl_set_error_handler_off()) {}
    ~GslHandlerOff() { gsl_set_error_handler(previous_); }
    GslHandlerOff(const GslHandlerOff&) = delete;
    GslHandlerOff& operator=(const GslHandlerOff&) = delete;

  private:
    gsl_error_handler_t* previous_;
};

std::string format_vec(const Vec3& v) {
    std::ostringstream s;
    s << "(" << v.x() << ", " << v.y() << ", " << v.z() << ")";
    return s.str();
}

}  // namespace

// Natural cubic splines x(t), y(t), z(t) in the chord-length parameter t, plus the arc length
// S_i at each knot. Evaluated with a null accelerator, so concurrent reads are safe.
struct KeypointSpline {
    std::vector<double> t;
    std::vector<double> arc;  // S(t_i)
    struct SplineFree {
        void operator()(gsl_spline* s) const { gsl_spline_free(s); }
    };
    // Owned, so that a constructor which refuses the curve frees what it allocated.
    std::array<std::unique_ptr<gsl_spline, SplineFree>, 3> xyz;

    explicit KeypointSpline(const std::vector<Vec3>& points);

    Vec3 x(double u) const { return eval(u, gsl_spline_eval); }
    Vec3 x_t(double u) const { return eval(u, gsl_spline_eval_deriv); }
    Vec3 x_tt(double u) const { return eval(u, gsl_spline_eval_deriv2); }
    // ∫_a^b |x_t| dt, to 1e-13 of itself or of `scale` (the knot interval's length), whichever
    // is larger: pieces of an interval need only the interval's absolute accuracy.
    double length_between(double a, double b, double scale) const;
    // The points of (a, b) where |x_t| is stationary, ascending: where the curve turns fastest.
    std::vector<double> turning_points(double a, double b) const;
    double parameter_at(double s) const;  // t(s), the inverse of S(t)

  private:
    template <class F>
    Vec3 eval(double u, F f) const {
        return Vec3(f(xyz[0].get(), u, nullptr), f(xyz[1].get(), u, nullptr),
                    f(xyz[2].get(), u, nullptr));
    }
};

KeypointSpline::KeypointSpline(const std::vector<Vec3>& points) {
    const size_t n = points.size();
    t.assign(n, 0.0);
    for (size_t i = 1; i < n; ++i) {
        const double chord = (points[i] - points[i - 1]).norm();
        if (!(chord > 0.0)) {
            throw InputError("key points " + std::to_string(i - 1) + " and " + std::to_string(i) +
                             " of the curve (start, keypoints..., end) coincide at " +
                             format_vec(points[i]));
        }
        t[i] = t[i - 1] + chord;
    }
    for (int c = 0; c < 3; ++c) {
        std::vector<double> v(n);
        for (size_t i = 0; i < n; ++i) v[i] = points[i][c];
        xyz[c].reset(gsl_spline_alloc(gsl_interp_cspline, n));
        ROTBEAM_VERIFY(xyz[c] != nullptr, "gsl_spline_alloc failed");
        ROTBEAM_VERIFY(gsl_spline_init(xyz[c].get(), t.data(), v.data(), n) == GSL_SUCCESS,
                       "gsl_spline_init failed");
    }
    arc.assign(n, 0.0);
    for (size_t i = 1; i < n; ++i) {
        try {
            arc[i] = arc[i - 1] + length_between(t[i - 1], t[i], t[i] - t[i - 1]);
        } catch (const InputError& e) {
            throw InputError("between key points " + std::to_string(i - 1) + " and " +
                             std::to_string(i) +
                             " of the curve (start, keypoints..., end): " + e.what());
        }
    }
}

std::vector<double> KeypointSpline::turning_points(double a, double b) const {
    // In the knot interval [t_i, t_i+1] holding (a, b), x_t(t_i + w) = A + B w + C w² exactly
    // (cubic splines), so d|x_t|²/dw / 2 = x_t · x_tt is the cubic
    // 2 C·C w³ + 3 B·C w² + (2 A·C + B·B) w + A·B.
    const size_t i = std::min(
        static_cast<size_t>(std::upper_bound(t.begin(), t.end(), 0.5 * (a + b)) - t.begin()) - 1,
        t.size() - 2);
    const double h = t[i + 1] - t[i];
    const Vec3 A = x_t(t[i]);
    const Vec3 B = x_tt(t[i]);
    const Vec3 C = (x_tt(t[i + 1]) - B) / (2.0 * h);
    std::array<double, 3> w{};
    int count = 0;
    if (C.dot(C) > 0.0) {
        const double lead = 2.0 * C.dot(C);
        count = gsl_poly_solve_cubic(3.0 * B.dot(C) / lead, (2.0 * A.dot(C) + B.dot(B)) / lead,
                                     A.dot(B) / lead, &w[0], &w[1], &w[2]);
    } else {
        count = gsl_poly_solve_quadratic(3.0 * B.dot(C), 2.0 * A.dot(C) + B.dot(B), A.dot(B), &w[0],
                                         &w[1]);
    }
    std::vector<double> points;
    for (int k = 0; k < count; ++k) {
        const double u = t[i] + w[static_cast<size_t>(k)];
        if (u > a && u < b && (points.empty() || u > points.back())) points.push_back(u);
    }
    return points;
}

double KeypointSpline::length_between(double a, double b, double scale) const {
    if (b <= a) return 0.0;
    gsl_function f;
    f.function = [](double u, void* p) -> double {
        return static_cast<const KeypointSpline*>(p)->x_t(u).norm();
    };
    f.params = const_cast<KeypointSpline*>(this);
    // Within one knot interval |x_t| is the root of a quartic: smooth, except that where the
    // curve nearly folds back (x_t almost vanishes) it has a near-kink. Splitting there puts the
    // kink at the end of a piece, which adaptive bisection resolves.
    std::vector<double> pieces{a};
    for (const double u : turning_points(a, b)) pieces.push_back(u);
    pieces.push_back(b);
    gsl_integration_workspace* w = gsl_integration_workspace_alloc(200);
    double result = 0.0, error = 0.0;
    const int status =
        gsl_integration_qagp(&f, pieces.data(), pieces.size(), kArcLengthTolerance * scale,
                             kArcLengthTolerance, 200, w, &result, &error);
    gsl_integration_workspace_free(w);
    // A geometry whose length is uncertain beyond 1e-10 would put that uncertainty into every
    // node position: a property of the key points given, so it is refused as input.
    if (status != GSL_SUCCESS && !(error <= 1e-10 * std::max(result, scale))) {
        std::ostringstream m;
        m << "the spline's arc length cannot be computed to 1e-10 (" << gsl_strerror(status)
          << ", length " << result << " +- " << error << "); check the key points";
        throw InputError(m.str());
    }
    return result;
}

double KeypointSpline::parameter_at(double s) const {
    const size_t n = t.size();
    if (s <= 0.0) return t.front();
    if (s >= arc.back()) return t.back();
    const size_t i =
        static_cast<size_t>(std::upper_bound(arc.begin(), arc.end(), s) - arc.begin()) - 1;
    if (i + 1 >= n) return t.back();
    struct Params {
        const KeypointSpline* spline;
        double t0, target, scale;
    } params{this, t[i], s - arc[i], t[i + 1] - t[i]};
    gsl_function f;
    f.function = [](double u, void* p) -> double {
        const Params& q = *static_cast<const Params*>(p);
        return q.spline->length_between(q.t0, u, q.scale) - q.target;
    };
    f.params = &params;
    gsl_root_fsolver* solver = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
    gsl_root_fsolver_set(solver, &f, t[i], t[i + 1]);
    double root = t[i];
    int status = GSL_CONTINUE;
    for (int iter = 0; iter < 200 && status == GSL_CONTINUE; ++iter) {
        gsl_root_fsolver_iterate(solver);
        root = gsl_root_fsolver_root(solver);
        status = gsl_root_test_interval(gsl_root_fsolver_x_lower(solver),
                                        gsl_root_fsolver_x_upper(solver), 0.0, kArcLengthTolerance);
    }
    gsl_root_fsolver_free(solver);
    return root;
}

ReferenceGeometry::ReferenceGeometry(const Model& model, int member) {
    ROTBEAM_VERIFY(member >= 0 && member < static_cast<int>(model.members.size()),
                   "member index out of range");
    const Member& m = model.members[static_cast<size_t>(member)];
    ROTBEAM_VERIFY(m.start_point >= 0 && m.end_point >= 0 &&
                       m.start_point < static_cast<int>(model.points.size()) &&
                       m.end_point < static_cast<int>(model.points.size()),
                   "member end point index out of range");
    const Vec3 x0 = model.points[static_cast<size_t>(m.start_point)].position;
    const Vec3 x1 = model.points[static_cast<size_t>(m.end_point)].position;
    if (!((x1 - x0).norm() > 0.0)) {
        throw InputError("the member's start and end points coincide at " + format_vec(x0));
    }
    kind_ = m.line.kind;
    start_ = x0;
    twist_start_ = m.twist_start;
    twist_end_ = m.twist_end;
    if (m.twist_values.size() > 2) {
        const size_t n = m.twist_values.size();
        std::vector<double> nodes(n);
        for (size_t i = 0; i < n; ++i)
            nodes[i] = static_cast<double>(i) / static_cast<double>(n - 1);
        twist_basis_ = std::make_shared<const LagrangeBasis>(std::move(nodes));
        twist_values_ = m.twist_values;
    }
    if (m.line.e2_hint) {
        has_hint_ = true;
        hint_ = *m.line.e2_hint;
        if (!(hint_.norm() > 0.0)) throw InputError("e2 hint is the zero vector");
    }
    const GslHandlerOff guard;
    if (kind_ == LineKind::straight || (kind_ == LineKind::keypoints && m.line.keypoints.empty())) {
        kind_ = LineKind::straight;
        length_ = (x1 - x0).norm();
        direction_ = (x1 - x0) / length_;
    } else if (kind_ == LineKind::arc) {
        init_arc(m.line, x0, x1);
    } else {
        std::vector<Vec3> points{x0};
        points.insert(points.end(), m.line.keypoints.begin(), m.line.keypoints.end());
        points.push_back(x1);
        spline_ = std::make_shared<const KeypointSpline>(points);
        length_ = spline_->arc.back();
    }
}

void ReferenceGeometry::init_arc(const ReferenceLine& line, const Vec3& x0, const Vec3& x1) {
    center_ = line.center;
    const Vec3 a = x0 - center_;
    const Vec3 b = x1 - center_;
    radius_ = a.norm();
    if (!(radius_ > 0.0)) throw InputError("arc centre coincides with the start point");
    if (std::abs(b.norm() - radius_) > kArcTolerance * radius_) {
        throw InputError("arc ends are at different distances from the centre (" +
                         std::to_string(radius_) + " and " + std::to_string(b.norm()) + ")");
    }
    radial0_ = a / radius_;
    const Vec3 bhat = b.normalized();
    double sweep = 0.0;
    if (line.normal) {
        if (!(line.normal->norm() > 0.0)) throw InputError("arc normal is the zero vector");
        normal_ = line.normal->normalized();
        if (std::abs(normal_.dot(radial0_)) > kArcTolerance ||
            std::abs(normal_.dot(bhat)) > kArcTolerance) {
            throw InputError("arc ends do not lie in the plane through the centre normal to " +
                             format_vec(normal_));
        }
        // Right-handed about the normal, in (0, 2π].
        sweep = std::atan2(normal_.dot(radial0_.cross(bhat)), radial0_.dot(bhat));
        if (sweep <= 0.0) sweep += 2.0 * kPi;
    } else {
        const Vec3 c = radial0_.cross(bhat);
        if (c.norm() < kArcTolerance) {
            throw InputError(
                "arc ends are collinear with the centre (sweep 0 or 180°): "
                "give `normal` to fix the plane and sense");
        }
        normal_ = c.normalized();
        sweep = std::atan2(c.norm(), radial0_.dot(bhat));
    }
    length_ = radius_ * sweep;
}

void ReferenceGeometry::line_point(double s, Vec3& x, Vec3& e1, Vec3& de1) const {
    s = std::clamp(s, 0.0, length_);
    switch (kind_) {
        case LineKind::straight:
            x = start_ + s * direction_;
            e1 = direction_;
            de1.setZero();
            return;
        case LineKind::arc: {
            const double phi = s / radius_;
            const Vec3 r = std::cos(phi) * radial0_ + std::sin(phi) * normal_.cross(radial0_);
            x = center_ + radius_ * r;
            e1 = normal_.cross(r);
            de1 = -r / radius_;
            return;
        }
        case LineKind::keypoints: {
            const GslHandlerOff guard;
            const double u = spline_->parameter_at(s);
            x = spline_->x(u);
            const Vec3 xt = spline_->x_t(u);
            const Vec3 xtt = spline_->x_tt(u);
            const double speed = xt.norm();
            e1 = xt / speed;
            de1 = (xtt - e1 * e1.dot(xtt)) / (speed * speed);
            return;
        }
    }
}

Vec3 ReferenceGeometry::position(double s) const {
    Vec3 x, e1, de1;
    line_point(s, x, e1, de1);
    return x;
}

Vec3 ReferenceGeometry::tangent(double s) const {
    Vec3 x, e1, de1;
    line_point(s, x, e1, de1);
    return e1;
}

double ReferenceGeometry::twist(double s) const {
    const double a = std::clamp(s, 0.0, length_) / length_;
    if (!twist_basis_) return (1.0 - a) * twist_start_ + a * twist_end_;
    VecX n(twist_basis_->size());
    twist_basis_->values(a, n);
    return n.dot(Eigen::Map<const VecX>(twist_values_.data(), n.size()));
}

double ReferenceGeometry::twist_rate(double s) const {
    if (!twist_basis_) return (twist_end_ - twist_start_) / length_;
    VecX dn(twist_basis_->size());
    twist_basis_->derivatives(std::clamp(s, 0.0, length_) / length_, dn);
    return dn.dot(Eigen::Map<const VecX>(twist_values_.data(), dn.size())) / length_;
}

void ReferenceGeometry::frame_and_derivative(double s, Mat3& R, Mat3& dR_ds) const {
    Vec3 x, e1, de1;
    line_point(s, x, e1, de1);
    // Unnormalized e2 direction a(s) and its derivative, by the frame rule of the header.
    Vec3 a, da;
    if (kind_ == LineKind::arc && !has_hint_) {
        a = -(x - center_) / radius_;  // toward the centre
        da = -e1 / radius_;
    } else {
        Vec3 h = hint_;
        if (!has_hint_) {
            a = Vec3::UnitZ().cross(e1);
            da = Vec3::UnitZ().cross(de1);
            // e1 ∥ ẑ: fall back to ŷ projected (model.hpp's rule).
            h = Vec3::UnitY();
        }
        if (has_hint_ || a.norm() < 1e-8) {
            a = h - e1 * e1.dot(h);
            da = -de1 * e1.dot(h) - e1 * de1.dot(h);
            if (a.norm() < 1e-8)
                throw InputError("e2 hint " + format_vec(h) +
                                 " is parallel to "
                                 "the tangent " +
                                 format_vec(e1));
        }
    }
    const double an = a.norm();
    const Vec3 e2 = a / an;
    const Vec3 de2 = (da - e2 * e2.dot(da)) / an;
    const Vec3 e3 = e1.cross(e2);
    const Vec3 de3 = de1.cross(e2) + e1.cross(de2);
    Mat3 Rb, dRb;
    Rb << e1, e2, e3;
    dRb << de1, de2, de3;
    // Twist: R = R_base exp(θ ẽ1), dR/ds = dR_base exp(θ ẽ1) + R_base exp(θ ẽ1) ẽ1 θ′.
    const double theta = twist(s);
    const double dtheta = twist_rate(s);
    const Mat3 Rt = so3::exp_map(theta * Vec3::UnitX());
    R = Rb * Rt;
    dR_ds = dRb * Rt + R * so3::skew(Vec3::UnitX()) * dtheta;
}

Mat3 ReferenceGeometry::frame(double s) const {
    Mat3 R, dR;
    frame_and_derivative(s, R, dR);
    return R;
}

Vec3 ReferenceGeometry::curvature(double s) const {
    Mat3 R, dR;
    frame_and_derivative(s, R, dR);
    const Mat3 K = R.transpose() * dR;
    // RᵀR′ is skew for an exact frame; take the skew part so round-off cannot leak in.
    const Mat3 K_skew = 0.5 * (K - K.transpose());
    return so3::axial(K_skew);
}

}  // namespace rotbeam
