#include "motion/lying_turn.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "motion/lying_still.hpp"
#include "motion/motion_edit.hpp"
#include "motion/skeleton.hpp"

namespace t2imu {

using Eigen::Vector3d;
using namespace smpl22;

namespace {

// The turn (rad) at frame f: up over turn_s, held, back over back_s.
double turn_at(int f, const LyingTurnOptions& o, double fps) {
    const double t = f / fps;
    const double up = min_jerk((t - o.before_s) / o.turn_s);
    const double down = min_jerk((t - o.before_s - o.turn_s - o.on_side_s) / o.back_s);
    return o.angle_rad * (up - down);
}

}  // namespace

void validate(const LyingTurnOptions& o) {
    check_option_range(o.before_s, 0.0, 10.0, "lying turn options", "before_s");
    check_option_range(o.turn_s, 0.8, 4.0, "lying turn options", "turn_s");
    check_option_range(o.on_side_s, 0.0, 20.0, "lying turn options", "on_side_s");
    check_option_range(o.back_s, 0.8, 4.0, "lying turn options", "back_s");
    check_option_range(o.after_s, 0.0, 10.0, "lying turn options", "after_s");
    check_option_range(std::abs(o.angle_rad), 0.5, 1.7, "lying turn options", "angle_rad");
}

int lying_turn_frames(const LyingTurnOptions& o, double fps) {
    return frames_of(o.before_s + o.turn_s + o.on_side_s + o.back_s + o.after_s, fps) + 1;
}

JointSequence lying_turn(const JointSequence& lying, const LyingTurnOptions& o) {
    validate(o);
    if (lying.num_joints != kNumJoints) throw Error("lying_turn", "lying", "22 SMPL joints");
    const int n = lying_turn_frames(o, lying.fps);
    if (lying.num_frames < n)
        throw Error("lying_turn", "lying", "at least " + std::to_string(n) + " frames",
                    std::to_string(lying.num_frames));
    if (!is_lying(lying, 0))
        throw Error("lying_turn", "lying",
                    "a clip lying at frame 0 (pelvis below 0.4 m, trunk more than 45 deg from vertical)");
    const Vector3d axis = horizontal_direction(lying.at(0, neck) - lying.at(0, pelvis));
    const Vector3d pivot = 0.5 * (lying.at(0, neck) + lying.at(0, pelvis));
    double floor = lying.at(0, 0).y();
    for (int j = 1; j < kNumJoints; ++j) floor = std::min(floor, lying.at(0, j).y());

    JointSequence m(n, kNumJoints, lying.fps);
    std::vector<double> sunk(static_cast<size_t>(n), 0.0);  // how far the lowest joint is below the floor contact (m)
    for (int f = 0; f < n; ++f) {
        const Eigen::Matrix3d turn = Eigen::AngleAxisd(turn_at(f, o, lying.fps), axis).toRotationMatrix();
        for (int j = 0; j < kNumJoints; ++j) {
            m.at(f, j) = pivot + turn * (lying.at(f, j) - pivot);
            sunk[static_cast<size_t>(f)] = std::max(sunk[static_cast<size_t>(f)], floor - m.at(f, j).y());
        }
    }
    const std::vector<double> lift = upper_envelope(sunk, std::max(1, frames_of(0.25, lying.fps)));
    for (int f = 0; f < n; ++f)
        for (int j = 0; j < kNumJoints; ++j) m.at(f, j).y() += lift[static_cast<size_t>(f)];
    return m;
}

}  // namespace t2imu
