#include "body/trunk_sway.hpp"

#include <Eigen/Geometry>

#include "core/signal/gaussian_filter.hpp"
#include "motion/quaternion.hpp"
#include "motion/skeleton.hpp"

namespace t2imu {

using Eigen::Vector3d;

bool is_trunk_segment(int segment) {
    return segment == smpl22::pelvis || segment == smpl22::spine1 || segment == smpl22::spine2 ||
           segment == smpl22::spine3;
}

namespace {

// Gaussian low-pass of a rotation track: the sign-continuous quaternions filtered component-wise, renormalised.
std::vector<Quat> slow_rotations(std::vector<Quat> q, double sigma_frames) {
    qfix(q);
    TimeSeries series(static_cast<Eigen::Index>(q.size()), 4);
    for (size_t f = 0; f < q.size(); ++f) series.row(static_cast<Eigen::Index>(f)) = q[f].coeffs().transpose();
    series = gaussian_filter1d_nearest(series, sigma_frames);
    std::vector<Quat> out(q.size());
    for (size_t f = 0; f < q.size(); ++f) {
        out[f].coeffs() = series.row(static_cast<Eigen::Index>(f)).transpose();
        out[f].normalize();
    }
    return out;
}

}  // namespace

void apply_trunk_sway(const TrunkSway& sway, int segment, double fps, std::vector<PosedFrame>* frames) {
    if (!sway.enabled() || !is_trunk_segment(segment) || frames->empty()) return;
    const size_t s = static_cast<size_t>(segment);
    std::vector<Quat> rotation(frames->size());
    for (size_t f = 0; f < frames->size(); ++f) rotation[f] = Quat((*frames)[f].rotation[s]);
    const std::vector<Quat> slow = slow_rotations(rotation, sway.sigma_s * fps);
    const Vector3d gain(sway.pitch_gain, sway.yaw_gain, 1);
    for (size_t f = 0; f < frames->size(); ++f) {
        const Eigen::AngleAxisd w(slow[f].conjugate() * rotation[f]);  // the sway, in the segment's rest axes
        const Vector3d v = (w.angle() * w.axis()).cwiseProduct(gain);
        const double angle = v.norm();
        const Quat edited = angle > 0 ? Quat(Eigen::AngleAxisd(angle, v / angle)) : Quat::Identity();
        (*frames)[f].rotation[s] = (slow[f] * edited).normalized().toRotationMatrix();
    }
}

}  // namespace t2imu
