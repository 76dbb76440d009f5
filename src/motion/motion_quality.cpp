#include "motion/motion_quality.hpp"

#include <algorithm>
#include <stdexcept>

#include "core/error.hpp"
#include "motion/skeleton.hpp"
#include "motion/support_ground.hpp"

namespace t2imu {

const std::array<const char*, kNumQualityScores> kQualityScoreNames = {
    "foot_skate_m_s", "penetration_m", "hover_m", "max_speed_m_s", "max_acc_m_s2", "pelvis_acc_m_s2"};

std::array<double, kNumQualityScores> quality_scores(const MotionQuality& q) {
    return {q.foot_skate_m_s, q.penetration_m, q.hover_m, q.max_speed_m_s, q.max_acc_m_s2, q.pelvis_acc_m_s2};
}

std::array<double, kNumQualityScores> quality_limits(const MotionQualityThresholds& t) {
    return {t.foot_skate_m_s, t.penetration_m, t.hover_m, t.max_speed_m_s, t.max_acc_m_s2, t.pelvis_acc_m_s2};
}

MotionQualityThresholds default_quality_thresholds() { return {1.3, 0.05, 0.30, 14.0, 350.0, 60.0}; }

namespace {

double foot_skate(const JointSequence& m, const GroundHeight& ground) {
    double sum = 0;
    int n = 0;
    for (int j : {smpl22::left_ankle, smpl22::left_foot, smpl22::right_ankle, smpl22::right_foot})
        for (int f = 0; f + 1 < m.num_frames; ++f) {
            const Eigen::Vector3d& a = m.at(f, j);
            const Eigen::Vector3d& b = m.at(f + 1, j);
            if (std::max(a.y() - ground(a, f), b.y() - ground(b, f + 1)) > kContactHeight) continue;
            sum += std::hypot(b.x() - a.x(), b.z() - a.z()) * m.fps;
            ++n;
        }
    return n > 0 ? sum / n : 0.0;
}

}  // namespace

MotionQuality score_motion(const JointSequence& m) {
    if (m.num_joints != smpl22::kNumJoints || m.num_frames < 3)
        throw Error("motion quality", "joints", "22 joints and at least 3 frames");
    const SupportGround ground(m);
    return score_motion_on_ground(m, [&](const Eigen::Vector3d& p, int frame) { return ground.height_at(p, frame); });
}

MotionQuality score_motion_on_ground(const JointSequence& m, const GroundHeight& ground) {
    if (m.num_joints != smpl22::kNumJoints || m.num_frames < 3)
        throw Error("motion quality", "joints", "22 joints and at least 3 frames");
    MotionQuality q;
    q.foot_skate_m_s = foot_skate(m, ground);
    std::vector<double> lowest(static_cast<size_t>(m.num_frames));
    for (int f = 0; f < m.num_frames; ++f) {
        double low = m.at(f, 0).y() - ground(m.at(f, 0), f);
        for (int j = 0; j < m.num_joints; ++j) {
            low = std::min(low, m.at(f, j).y() - ground(m.at(f, j), f));
            if (f + 1 < m.num_frames)
                q.max_speed_m_s = std::max(q.max_speed_m_s, (m.at(f + 1, j) - m.at(f, j)).norm() * m.fps);
            if (f < 1 || f + 1 >= m.num_frames) continue;
            const double acc = (m.at(f + 1, j) - 2 * m.at(f, j) + m.at(f - 1, j)).norm() * m.fps * m.fps;
            q.max_acc_m_s2 = std::max(q.max_acc_m_s2, acc);
            if (j == smpl22::pelvis) q.pelvis_acc_m_s2 = std::max(q.pelvis_acc_m_s2, acc);
        }
        lowest[static_cast<size_t>(f)] = low;
        q.penetration_m = std::max(q.penetration_m, -low);
    }
    std::nth_element(lowest.begin(), lowest.begin() + static_cast<std::ptrdiff_t>(lowest.size() / 2), lowest.end());
    q.hover_m = std::max(0.0, lowest[lowest.size() / 2]);
    return q;
}

double place_on_floor(JointSequence& m) {
    if (m.num_frames == 0 || m.num_joints == 0) return 0;
    const double low = lowest_joint_height(m);
    for (int f = 0; f < m.num_frames; ++f)
        for (int j = 0; j < m.num_joints; ++j) m.at(f, j).y() -= low;
    return -low;
}

std::vector<std::string> quality_failures(const MotionQuality& q, const MotionQualityThresholds& t) {
    static const std::array<const char*, kNumQualityScores> failure = {"foot_skate", "penetration", "hover",
                                                                       "max_speed",  "max_acc",     "pelvis_acc"};
    const auto score = quality_scores(q), limit = quality_limits(t);
    std::vector<std::string> out;
    for (size_t i = 0; i < kNumQualityScores; ++i)
        if (score[i] > limit[i]) out.push_back(failure[i]);
    return out;
}

double quality_badness(const MotionQuality& q, const MotionQualityThresholds& t) {
    const auto score = quality_scores(q), limit = quality_limits(t);
    double worst = 0;
    for (size_t i = 0; i < kNumQualityScores; ++i) worst = std::max(worst, score[i] / limit[i]);
    return worst;
}

}  // namespace t2imu
