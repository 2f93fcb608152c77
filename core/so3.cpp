#include "core/so3.hpp"

#include <cmath>

namespace rotbeam::so3 {

Mat3 skew(const Vec3& a) {
    Mat3 m;
    m << 0.0, -a.z(), a.y(), a.z(), 0.0, -a.x(), -a.y(), a.x(), 0.0;
    return m;
}

Vec3 axial(const Mat3& M) {
    return Vec3(0.5 * (M(2, 1) - M(1, 2)), 0.5 * (M(0, 2) - M(2, 0)), 0.5 * (M(1, 0) - M(0, 1)));
}

Mat3 exp_map(const Vec3& psi) {
    const double phi2 = psi.squaredNorm();
    const double phi = std::sqrt(phi2);
    double a;  // sin φ / φ
    double b;  // (1 − cos φ) / φ²
    if (phi < kSeriesAngle) {
        a = 1.0 - phi2 / 6.0 + phi2 * phi2 / 120.0;
        b = 0.5 - phi2 / 24.0 + phi2 * phi2 / 720.0;
    } else {
        a = std::sin(phi) / phi;
        const double s = std::sin(0.5 * phi) / phi;
        b = 2.0 * s * s;  // (1 − cos φ)/φ² without cancellation
    }
    const Mat3 k = skew(psi);
    return Mat3::Identity() + a * k + b * k * k;
}

Vec4 quat_identity() { return Vec4(1.0, 0.0, 0.0, 0.0); }

Vec4 quat_multiply(const Vec4& a, const Vec4& b) {
    const double w = a[0] * b[0] - a.tail<3>().dot(b.tail<3>());
    const Vec3 v = a[0] * b.tail<3>() + b[0] * a.tail<3>() + a.tail<3>().cross(b.tail<3>());
    return Vec4(w, v.x(), v.y(), v.z());
}

Vec4 quat_conjugate(const Vec4& q) { return Vec4(q[0], -q[1], -q[2], -q[3]); }

Mat3 quat_to_matrix(const Vec4& q) {
    const double w = q[0], x = q[1], y = q[2], z = q[3];
    Mat3 R;
    R << 1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y),  //
        2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x),  //
        2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y);
    return R;
}

Vec4 quat_from_matrix(const Mat3& R) {
    // Shepperd: pick the largest of 4w², 4x², 4y², 4z² to divide by.
    const double t = R.trace();
    Vec4 q;
    if (t >= R(0, 0) && t >= R(1, 1) && t >= R(2, 2)) {
        const double r = std::sqrt(1.0 + t);
        const double s = 0.5 / r;
        q << 0.5 * r, (R(2, 1) - R(1, 2)) * s, (R(0, 2) - R(2, 0)) * s, (R(1, 0) - R(0, 1)) * s;
    } else if (R(0, 0) >= R(1, 1) && R(0, 0) >= R(2, 2)) {
        const double r = std::sqrt(1.0 + R(0, 0) - R(1, 1) - R(2, 2));
        const double s = 0.5 / r;
        q << (R(2, 1) - R(1, 2)) * s, 0.5 * r, (R(0, 1) + R(1, 0)) * s, (R(0, 2) + R(2, 0)) * s;
    } else if (R(1, 1) >= R(2, 2)) {
        const double r = std::sqrt(1.0 - R(0, 0) + R(1, 1) - R(2, 2));
        const double s = 0.5 / r;
        q << (R(0, 2) - R(2, 0)) * s, (R(0, 1) + R(1, 0)) * s, 0.5 * r, (R(1, 2) + R(2, 1)) * s;
    } else {
        const double r = std::sqrt(1.0 - R(0, 0) - R(1, 1) + R(2, 2));
        const double s = 0.5 / r;
        q << (R(1, 0) - R(0, 1)) * s, (R(0, 2) + R(2, 0)) * s, (R(1, 2) + R(2, 1)) * s, 0.5 * r;
    }
    if (q[0] < 0.0) q = -q;
    return q.normalized();
}

Vec4 quat_from_rotvec(const Vec3& psi) {
    const double phi2 = psi.squaredNorm();
    const double phi = std::sqrt(phi2);
    double s;  // sin(φ/2)/φ
    if (phi < kSeriesAngle) {
        s = 0.5 - phi2 / 48.0 + phi2 * phi2 / 3840.0;
    } else {
        s = std::sin(0.5 * phi) / phi;
    }
    return Vec4(std::cos(0.5 * phi), s * psi.x(), s * psi.y(), s * psi.z());
}

Vec3 rotvec_from_quat(const Vec4& q_in) {
    const Vec4 q = q_in[0] < 0.0 ? Vec4(-q_in) : q_in;
    const Vec3 v = q.tail<3>();
    const double sn = v.norm();
    const double phi = 2.0 * std::atan2(sn, q[0]);  // in [0, π]
    double f;  // φ / sin(φ/2)
    if (sn < 0.5 * kSeriesAngle && q[0] > 0.0) {
        // φ/sin(φ/2) = 2 (1 + φ²/24 + 7φ⁴/5760); with φ ≈ 2 sn/w.
        const double p2 = phi * phi;
        f = 2.0 * (1.0 + p2 / 24.0 + 7.0 * p2 * p2 / 5760.0) / q.norm();
    } else {
        f = phi / sn;
    }
    return f * v;
}

Vec3 quat_rotate(const Vec4& q, const Vec3& v) {
    const Vec3 u = q.tail<3>();
    const Vec3 t = 2.0 * u.cross(v);
    return v + q[0] * t + u.cross(t);
}

Vec3 log_map(const Mat3& R) { return rotvec_from_quat(quat_from_matrix(R)); }

double rotation_angle(const Mat3& R) {
    const Vec3 s = 2.0 * axial(R);          // 2 sin φ n
    const double c = R.trace() - 1.0;       // 2 cos φ
    return std::atan2(s.norm(), c);
}

Vec3 unwrap_rotation_vector(const Vec3& principal, const Vec3& previous_psi) {
    // Candidates: ψ + 2πk n for the principal axis n (and the opposite axis), pick the one nearest
    // the previous unwrapped rotation vector.
    const double phi = principal.norm();
    if (phi < 1e-300) {
        // Identity: either 0 or a multiple of 2π about the previous axis.
        const double prev = previous_psi.norm();
        if (prev < 1e-300) return principal;
        const Vec3 n = previous_psi / prev;
        const double k = std::round(prev / (2.0 * kPi));
        return 2.0 * kPi * k * n;
    }
    const Vec3 n = principal / phi;
    Vec3 best = principal;
    double best_distance = (principal - previous_psi).norm();
    const double prev_norm = previous_psi.norm();
    const int kmax = static_cast<int>(prev_norm / (2.0 * kPi)) + 2;
    for (int k = -kmax; k <= kmax; ++k) {
        const Vec3 candidate = (phi + 2.0 * kPi * k) * n;
        const double d = (candidate - previous_psi).norm();
        if (d < best_distance) {
            best_distance = d;
            best = candidate;
        }
    }
    return best;
}

}  // namespace rotbeam::so3
