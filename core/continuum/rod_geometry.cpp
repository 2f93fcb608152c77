#include "core/continuum/rod_geometry.hpp"

#include <algorithm>
#include <cmath>

#include "core/errors.hpp"
#include "core/so3.hpp"

namespace rotbeam::continuum {
namespace {

constexpr double kOnLine = 1e-9;  // relative distance under which a point lies on the line

Mat3 frame_from(const Vec3& e1, const Vec3& e2) {
    Mat3 R;
    R.col(0) = e1;
    R.col(1) = e2;
    R.col(2) = e1.cross(e2);
    return R;
}

Vec3 default_e2(const Vec3& e1, const std::optional<Vec3>& hint) {
    if (hint) {
        const Vec3 a = *hint - hint->dot(e1) * e1;
        if (!(a.norm() > 1e-8 * hint->norm()))
            throw InputError("e2 hint is parallel to the member");
        return a.normalized();
    }
    const Vec3 a = Vec3::UnitZ().cross(e1);
    if (a.norm() > 1e-8) return a.normalized();
    return (Vec3::UnitY() - e1.y() * e1).normalized();
}

}  // namespace

RodGeometry::RodGeometry(const Model& model, const Member& member)
    : kind_(member.line.kind), twist_start_(member.twist_start), twist_end_(member.twist_end) {
    start_ = model.points.at(member.start_point).position;
    const Vec3 end = model.points.at(member.end_point).position;
    if (kind_ == LineKind::keypoints)
        throw InputError("continuum solver: key-point reference lines are not supported");
    if (member.twist_values.size() > 2)
        throw InputError(
            "continuum solver: a twist that is not linear along a member is not "
            "supported");
    if (kind_ == LineKind::straight) {
        length_ = (end - start_).norm();
        if (!(length_ > 0.0)) throw InputError("continuum solver: member ends coincide");
        const Vec3 e1 = (end - start_) / length_;
        frame0_ = frame_from(e1, default_e2(e1, member.line.e2_hint));
        return;
    }
    if (member.line.e2_hint)
        throw InputError("continuum solver: an e2 hint on an arc is not supported");
    center_ = member.line.center;
    const Vec3 r0 = start_ - center_, r1 = end - center_;
    radius_ = r0.norm();
    if (!(radius_ > 0.0) || std::abs(r1.norm() - radius_) > kOnLine * radius_)
        throw InputError("continuum solver: arc ends are not equidistant from the centre");
    normal_ = member.line.normal ? member.line.normal->normalized() : r0.cross(r1).normalized();
    if (!(normal_.allFinite()) || std::abs(normal_.dot(r0)) > kOnLine * radius_)
        throw InputError("continuum solver: arc plane is undefined or does not hold the start");
    sweep_ = std::atan2(normal_.dot(r0.cross(r1)), r0.dot(r1));
    if (sweep_ <= 0.0) sweep_ += 2.0 * kPi;
    length_ = radius_ * sweep_;
    const Vec3 rhat = r0 / radius_;
    frame0_ = frame_from(normal_.cross(rhat), -rhat);
}

double RodGeometry::twist(double s) const {
    return twist_start_ + (twist_end_ - twist_start_) * s / length_;
}

Vec3 RodGeometry::position(double s) const {
    if (kind_ == LineKind::straight) return start_ + s * frame0_.col(0);
    return center_ + so3::exp_map((s / radius_) * normal_) * (start_ - center_);
}

Mat3 RodGeometry::frame(double s) const {
    const Mat3 twist_rotation = so3::exp_map(Vec3(twist(s), 0.0, 0.0));
    if (kind_ == LineKind::straight) return frame0_ * twist_rotation;
    return so3::exp_map((s / radius_) * normal_) * frame0_ * twist_rotation;
}

Vec3 RodGeometry::curvature(double s) const {
    Vec3 k0 = Vec3::Zero();
    if (kind_ == LineKind::arc) k0 = Vec3(0.0, 0.0, 1.0 / radius_);
    const Mat3 untwist = so3::exp_map(Vec3(-twist(s), 0.0, 0.0));
    return untwist * k0 + Vec3((twist_end_ - twist_start_) / length_, 0.0, 0.0);
}

std::optional<double> RodGeometry::locate(const Vec3& point) const {
    double s = 0.0;
    if (kind_ == LineKind::straight) {
        s = (point - start_).dot(frame0_.col(0));
    } else {
        const Vec3 r0 = start_ - center_, r = point - center_;
        double phi = std::atan2(normal_.dot(r0.cross(r)), r0.dot(r));
        if (phi < -kOnLine) phi += 2.0 * kPi;
        s = radius_ * phi;
    }
    if (s < -kOnLine * length_ || s > (1.0 + kOnLine) * length_) return std::nullopt;
    s = std::clamp(s, 0.0, length_);
    if ((position(s) - point).norm() > kOnLine * length_) return std::nullopt;
    return s;
}

}  // namespace rotbeam::continuum
