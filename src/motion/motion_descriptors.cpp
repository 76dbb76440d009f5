#include "motion/motion_descriptors.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/error.hpp"
#include "motion/skeleton.hpp"

namespace t2imu {

const std::array<const char*, kNumMotionDescriptors> kMotionDescriptorNames = {
    "pelvis_height_m", "pelvis_height_sd_m", "head_above_pelvis_m", "trunk_tilt_rad",
    "thigh_tilt_rad",  "knee_flexion_rad",   "root_speed_m_s",      "root_vertical_speed_sd_m_s",
    "climb_rate_m_s",  "foot_speed_m_s",     "wrist_speed_m_s",     "airborne_fraction"};

namespace {

using smpl22::Joint;

double angle_from_vertical(const Eigen::Vector3d& v) {
    const double n = v.norm();
    return n > 0 ? std::acos(std::clamp(v.y() / n, -1.0, 1.0)) : 0.0;
}

double angle_between(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    const double n = a.norm() * b.norm();
    return n > 0 ? std::acos(std::clamp(a.dot(b) / n, -1.0, 1.0)) : 0.0;
}

double mean(const std::vector<double>& v) {
    double s = 0;
    for (double x : v) s += x;
    return v.empty() ? 0.0 : s / static_cast<double>(v.size());
}

double standard_deviation(const std::vector<double>& v) {
    const double m = mean(v);
    double s = 0;
    for (double x : v) s += (x - m) * (x - m);
    return v.empty() ? 0.0 : std::sqrt(s / static_cast<double>(v.size()));
}

// Least-squares slope of y over time (units of y per second).
double slope(const std::vector<double>& y, double fps) {
    const double n = static_cast<double>(y.size()), t_mean = (n - 1) / 2 / fps, y_mean = mean(y);
    double num = 0, den = 0;
    for (size_t i = 0; i < y.size(); ++i) {
        const double t = static_cast<double>(i) / fps - t_mean;
        num += t * (y[i] - y_mean);
        den += t * t;
    }
    return den > 0 ? num / den : 0.0;
}

// Mean speed (m/s) of joint j, relative to joint `relative_to` when it is >= 0.
double mean_speed(const JointSequence& m, int j, int relative_to = -1) {
    double s = 0;
    for (int f = 0; f + 1 < m.num_frames; ++f) {
        Eigen::Vector3d d = m.at(f + 1, j) - m.at(f, j);
        if (relative_to >= 0) d -= m.at(f + 1, relative_to) - m.at(f, relative_to);
        s += d.norm() * m.fps;
    }
    return s / (m.num_frames - 1);
}

// A frame is airborne when the lowest foot joint is more than kAirborneHeight above the floor it stands on both
// before and after: the lowest it gets within the past second and within the next second. On stairs the
// floor ahead (going up) or behind (going down) is the step the foot stands on, so climbing is not flight.
double airborne_fraction(const std::vector<double>& lowest_foot, double fps) {
    const int n = static_cast<int>(lowest_foot.size()), window = static_cast<int>(std::lround(fps));
    int airborne = 0;
    for (int f = 0; f < n; ++f) {
        double before = lowest_foot[static_cast<size_t>(f)], after = before;
        for (int g = std::max(0, f - window); g < f; ++g)
            before = std::min(before, lowest_foot[static_cast<size_t>(g)]);
        for (int g = f + 1; g <= std::min(n - 1, f + window); ++g)
            after = std::min(after, lowest_foot[static_cast<size_t>(g)]);
        airborne += lowest_foot[static_cast<size_t>(f)] - std::max(before, after) > kAirborneHeight;
    }
    return static_cast<double>(airborne) / n;
}

}  // namespace

MotionDescriptors describe_motion(const JointSequence& m) {
    if (m.num_joints != smpl22::kNumJoints || m.num_frames < 3)
        throw Error("motion descriptors", "joints", "22 joints and at least 3 frames");
    std::vector<double> pelvis, head_above, trunk, thigh, knee, horizontal_speed, vertical_velocity, lowest_foot;
    for (int f = 0; f < m.num_frames; ++f) {
        const Eigen::Vector3d& p = m.at(f, smpl22::pelvis);
        pelvis.push_back(p.y());
        head_above.push_back(m.at(f, smpl22::head).y() - p.y());
        trunk.push_back(angle_from_vertical(m.at(f, smpl22::neck) - p));
        for (const auto& [hip, knee_joint, ankle] :
             {std::array<Joint, 3>{smpl22::left_hip, smpl22::left_knee, smpl22::left_ankle},
              std::array<Joint, 3>{smpl22::right_hip, smpl22::right_knee, smpl22::right_ankle}}) {
            const Eigen::Vector3d up = m.at(f, hip) - m.at(f, knee_joint), down = m.at(f, ankle) - m.at(f, knee_joint);
            thigh.push_back(angle_from_vertical(up));
            knee.push_back(M_PI - angle_between(up, down));
        }
        double low = m.at(f, smpl22::left_ankle).y();
        for (int j : {smpl22::left_foot, smpl22::right_ankle, smpl22::right_foot}) low = std::min(low, m.at(f, j).y());
        lowest_foot.push_back(low);
        if (f + 1 < m.num_frames) {
            const Eigen::Vector3d d = (m.at(f + 1, smpl22::pelvis) - p) * m.fps;
            horizontal_speed.push_back(std::hypot(d.x(), d.z()));
            vertical_velocity.push_back(d.y());
        }
    }
    const double feet = (mean_speed(m, smpl22::left_ankle) + mean_speed(m, smpl22::right_ankle)) / 2;
    const double wrists =
        (mean_speed(m, smpl22::left_wrist, smpl22::pelvis) + mean_speed(m, smpl22::right_wrist, smpl22::pelvis)) / 2;
    return {mean(pelvis),
            standard_deviation(pelvis),
            mean(head_above),
            mean(trunk),
            mean(thigh),
            mean(knee),
            mean(horizontal_speed),
            standard_deviation(vertical_velocity),
            slope(lowest_foot, m.fps),
            feet,
            wrists,
            airborne_fraction(lowest_foot, m.fps)};
}

}  // namespace t2imu

namespace t2imu {

DescriptorMoments descriptor_moments(const std::vector<MotionDescriptors>& set) {
    DescriptorMoments m;
    if (set.empty()) return m;
    const double n = static_cast<double>(set.size());
    for (const MotionDescriptors& x : set)
        for (size_t i = 0; i < kNumMotionDescriptors; ++i) m.mean[i] += x[i] / n;
    for (const MotionDescriptors& x : set)
        for (size_t i = 0; i < kNumMotionDescriptors; ++i) m.sd[i] += (x[i] - m.mean[i]) * (x[i] - m.mean[i]) / n;
    for (double& v : m.sd) v = std::sqrt(v);
    return m;
}

}  // namespace t2imu
