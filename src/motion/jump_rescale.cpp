#include "motion/jump_rescale.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "core/error.hpp"
#include "motion/foot_contacts.hpp"
#include "motion/motion_edit.hpp"
#include "motion/skeleton.hpp"

namespace t2imu {

using Eigen::Vector3d;
using namespace smpl22;

namespace {

constexpr double kMinJumpSeconds = 0.5;

// Median pelvis height over the frames where both feet are in stance (m): the height the excursions are
// measured from.
double standing_pelvis_height(const JointSequence& m, const std::array<std::vector<bool>, 2>& stance) {
    std::vector<double> heights;
    for (int f = 0; f < m.num_frames; ++f)
        if (stance[0][static_cast<size_t>(f)] && stance[1][static_cast<size_t>(f)])
            heights.push_back(m.at(f, pelvis).y());
    if (heights.empty()) throw Error("rescale_jump", "jump", "a clip with both feet on the floor at some frame");
    std::nth_element(heights.begin(), heights.begin() + static_cast<long>(heights.size() / 2), heights.end());
    return heights[heights.size() / 2];
}

// Per frame, how much a foot moves with the body (0 in stance, 1 in the air), smoothed by a triangle 0.1 s
// wide either side ([1/4, 1/2, 1/4] at 20 fps) so that a foot leaving or meeting the floor takes the body's
// extra lift over 0.1 s, not one frame.
std::vector<double> airborne_weight(const std::vector<bool>& stance, double fps) {
    const int n = static_cast<int>(stance.size());
    const double half_width = 0.1 * fps;  // frames
    const int reach = static_cast<int>(std::ceil(half_width)) - 1;
    std::vector<double> w(stance.size());
    auto air = [&](int f) { return stance[static_cast<size_t>(std::clamp(f, 0, n - 1))] ? 0.0 : 1.0; };
    for (int f = 0; f < n; ++f) {
        double sum = 0, weights = 0;
        for (int k = -reach; k <= reach; ++k) {
            const double weight = half_width - std::abs(k);
            sum += weight * air(f + k), weights += weight;
        }
        w[static_cast<size_t>(f)] = sum / weights;
    }
    return w;
}

}  // namespace

void validate(const JumpRescaleOptions& o) {
    check_option_range(o.time_scale, 0.8, 1.25, "jump options", "time_scale");
}

JointSequence rescale_jump(const JointSequence& jump, const JumpRescaleOptions& o) {
    validate(o);
    if (jump.num_joints != kNumJoints) throw Error("rescale_jump", "jump", "SMPL-22 joints");
    if (jump.num_frames < kMinJumpSeconds * jump.fps) throw Error("rescale_jump", "jump", "a clip of at least 0.5 s");
    const double k = o.time_scale;
    const JointSequence source = retime(jump, 1.0 / k);  // k times slower; bones at the source's lengths
    const std::array<std::vector<bool>, 2> stance = {stance_frames(source, Foot::left),
                                                     stance_frames(source, Foot::right)};
    const std::array<std::vector<double>, 2> airborne = {airborne_weight(stance[0], source.fps),
                                                         airborne_weight(stance[1], source.fps)};
    const double standing = standing_pelvis_height(source, stance);

    JointSequence m = source;
    std::vector<Vector3d> forward(static_cast<size_t>(m.num_frames));
    for (int f = 0; f < m.num_frames; ++f) {
        const double lift = (k * k - 1) * (source.at(f, pelvis).y() - standing);
        for (int j = 0; j < m.num_joints; ++j)
            if (!is_leg_joint(j)) m.at(f, j).y() += lift;
        for (size_t leg = 0; leg < 2; ++leg) {
            const double w = airborne[leg][static_cast<size_t>(f)];
            m.at(f, kLegs[leg].ankle).y() += w * lift;
            m.at(f, kLegs[leg].toe).y() += w * lift;
        }
        forward[static_cast<size_t>(f)] = body_facing(source, f);
    }
    place_knees(m, source, forward, bone_lengths(jump, 0));
    return m;
}

}  // namespace t2imu
