#include "motion/quaternion.hpp"

#include <cmath>

namespace t2imu {

Eigen::Vector3d qrot(const Quat& q, const Eigen::Vector3d& v) {
    const Eigen::Vector3d u = q.vec();
    const Eigen::Vector3d uv = u.cross(v);
    const Eigen::Vector3d uuv = u.cross(uv);
    return v + 2.0 * (q.w() * uv + uuv);
}

Quat qbetween(const Eigen::Vector3d& v0, const Eigen::Vector3d& v1) {
    const Eigen::Vector3d axis = v0.cross(v1);
    const double w = std::sqrt(v0.squaredNorm() * v1.squaredNorm()) + v0.dot(v1);
    Quat q(w, axis.x(), axis.y(), axis.z());
    q.coeffs() /= q.coeffs().norm();
    return q;
}

Eigen::Matrix3d quaternion_to_matrix(const Quat& q) {
    const double r = q.w(), i = q.x(), j = q.y(), k = q.z();
    const double s = 2.0 / q.coeffs().squaredNorm();
    Eigen::Matrix3d m;
    m << 1 - s * (j * j + k * k), s * (i * j - k * r), s * (i * k + j * r), s * (i * j + k * r),
        1 - s * (i * i + k * k), s * (j * k - i * r), s * (i * k - j * r), s * (j * k + i * r), 1 - s * (i * i + j * j);
    return m;
}

Cont6d quaternion_to_cont6d(const Quat& q) {
    const Eigen::Matrix3d m = quaternion_to_matrix(q);
    Cont6d c;
    c << m.col(0), m.col(1);
    return c;
}

Eigen::Matrix3d cont6d_to_matrix(const Cont6d& c) {
    const Eigen::Vector3d x = c.head<3>().normalized();
    const Eigen::Vector3d z = x.cross(Eigen::Vector3d(c.tail<3>())).normalized();
    const Eigen::Vector3d y = z.cross(x);
    Eigen::Matrix3d m;
    m << x, y, z;
    return m;
}

Quat slerp(const Quat& q0, const Quat& q1, double t) {
    Quat b = q1;
    double d = q0.coeffs().dot(q1.coeffs());
    if (d < 0) {
        b.coeffs() = -b.coeffs();
        d = -d;
    }
    if (d > 1.0 - 1e-12) {  // nearly equal: the linear blend is exact to rounding and avoids 0/0
        Quat q;
        q.coeffs() = ((1 - t) * q0.coeffs() + t * b.coeffs()).normalized();
        return q;
    }
    const double theta = std::acos(d);
    const double s0 = std::sin((1 - t) * theta) / std::sin(theta), s1 = std::sin(t * theta) / std::sin(theta);
    Quat q;
    q.coeffs() = s0 * q0.coeffs() + s1 * b.coeffs();
    return q;
}

}  // namespace t2imu
