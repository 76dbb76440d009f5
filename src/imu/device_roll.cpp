#include "imu/device_roll.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "core/signal/gaussian_filter.hpp"

namespace t2imu {

using Eigen::Vector3d;

void apply_device_roll(const DeviceRoll& roll, const SensorMount& mount, double fps, std::vector<Quat>* world_from_sensor) {
    if (!roll.enabled() || world_from_sensor->empty()) return;
    const Vector3d up = Vector3d::UnitY();
    const Vector3d across_rest = up.cross(mount.skin_normal);
    if (across_rest.norm() < 0.1) return;  // the skin faces up or down: no frontal-plane roll to speak of
    const Vector3d normal_s = mount.rest_from_sensor.transpose() * mount.skin_normal;
    const Vector3d across_s = mount.rest_from_sensor.transpose() * across_rest.normalized();
    const size_t frames = world_from_sensor->size();
    TimeSeries angle(static_cast<Eigen::Index>(frames), 1);
    std::vector<double> tip(frames);
    for (size_t f = 0; f < frames; ++f) {
        const Vector3d n = (*world_from_sensor)[f] * normal_s, t = (*world_from_sensor)[f] * across_s;
        const double elevation = std::clamp(t.dot(up), -1.0, 1.0), level = std::sqrt(1 - elevation * elevation);
        angle(static_cast<Eigen::Index>(f), 0) = std::asin(elevation);
        // d(angle) / d(turn about n) = (n x t).up / cos(angle): 1 upright, 0 lying on the back
        tip[f] = level > 1e-6 ? n.cross(t).dot(up) / level : 0.0;
    }
    const TimeSeries slow = gaussian_filter1d_nearest(angle, roll.sigma_s * fps);
    for (size_t f = 0; f < frames; ++f) {
        const auto i = static_cast<Eigen::Index>(f);
        // Turning t about n by delta raises its angle by tip * delta: to follow gain x the sway, delta = (gain - 1) sway / tip.
        // Below |tip| = 0.5 (the normal within 30 degrees of vertical) the turn fades linearly to 0 instead.
        const double delta = (roll.gain - 1) * (angle(i, 0) - slow(i, 0)) * tip[f] / std::max(tip[f] * tip[f], 0.25);
        const Vector3d n = ((*world_from_sensor)[f] * normal_s).normalized();
        (*world_from_sensor)[f] = (Quat(Eigen::AngleAxisd(delta, n)) * (*world_from_sensor)[f]).normalized();
    }
}

}  // namespace t2imu
