#include "motion/two_bone_ik.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace t2imu {

using Eigen::Vector3d;

namespace {

// Unit vector perpendicular to unit `axis`, toward `toward` where it has a perpendicular part.
Vector3d bend_direction(const Vector3d& axis, const Vector3d& toward) {
    Vector3d side = toward - toward.dot(axis) * axis;
    if (side.norm() > 1e-12 * std::max(1.0, toward.norm())) return side.normalized();
    // No side given: any perpendicular, from the world axis least aligned with the chain.
    Eigen::Index least = 0;
    axis.cwiseAbs().minCoeff(&least);
    return axis.cross(Vector3d::Unit(least)).normalized();
}

}  // namespace

TwoBoneIkResult solve_two_bone_ik(const Vector3d& root, const Vector3d& target, double upper, double lower,
                                  const Vector3d& bend_hint) {
    if (!(upper > 0) || !(lower > 0)) throw Error("solve_two_bone_ik", "bone lengths", "both > 0");
    const Vector3d to_target = target - root;
    const double d = to_target.norm();
    const Vector3d axis = d > 1e-12 ? Vector3d(to_target / d) : bend_direction(Vector3d::UnitY(), bend_hint - root);
    TwoBoneIkResult r;
    if (d >= upper + lower) {  // too far: straight toward the target
        r.middle = root + upper * axis;
        r.end = root + (upper + lower) * axis;
        r.reached = (r.end - target).norm() < 1e-12;
        return r;
    }
    if (d <= std::abs(upper - lower)) {  // too near: folded flat, the end as near the target as it gets
        r.middle = root + (upper >= lower ? upper : -upper) * axis;
        r.end = root + std::abs(upper - lower) * axis;
        r.reached = (r.end - target).norm() < 1e-12;
        return r;
    }
    // Law of cosines for the angle at the root between the axis and the upper segment.
    const double cos_root = std::clamp((upper * upper + d * d - lower * lower) / (2 * upper * d), -1.0, 1.0);
    const double sin_root = std::sqrt(1 - cos_root * cos_root);
    r.middle = root + upper * (cos_root * axis + sin_root * bend_direction(axis, bend_hint - root));
    r.end = target;
    r.reached = true;
    return r;
}

}  // namespace t2imu
