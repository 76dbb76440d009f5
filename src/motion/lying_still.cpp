#include "motion/lying_still.hpp"

#include <Eigen/Geometry>
#include <array>
#include <cmath>

#include "core/error.hpp"
#include "motion/motion_edit.hpp"
#include "motion/skeleton.hpp"
#include "motion/two_bone_ik.hpp"

namespace t2imu {

using Eigen::Vector3d;
using namespace smpl22;

namespace {

constexpr double kPi = 3.14159265358979323846;

// spine3 and its descendants: the rib cage and what hangs off it.
bool on_rib_cage(int j) {
    while (j > 0 && j != spine3) j = kParents[static_cast<size_t>(j)];
    return j == spine3;
}

}  // namespace

bool is_lying(const JointSequence& s, int f) {
    const Vector3d trunk = s.at(f, neck) - s.at(f, pelvis);
    return s.at(f, pelvis).y() <= 0.4 && std::abs(trunk.normalized().y()) <= std::cos(kPi / 4);
}

void validate(const LyingOptions& o) {
    check_option_range(o.seconds, 1.0, 120.0, "lying options", "seconds");
    check_option_range(o.breaths_per_min, 8.0, 25.0, "lying options", "breaths_per_min");
    check_option_range(o.chest_rad, 0.0, 0.05, "lying options", "chest_rad");
}

JointSequence lying_still(const JointSequence& lie_down, const LyingOptions& o) {
    validate(o);
    if (lie_down.num_joints != kNumJoints || lie_down.num_frames < 1)
        throw Error("lying_still", "lie_down", "22 SMPL joints, at least one frame");
    const int last = lie_down.num_frames - 1;
    if (!is_lying(lie_down, last))
        throw Error("lying_still", "lie_down",
                    "a clip that ends lying (pelvis below 0.4 m, trunk more than 45 deg from vertical)");
    const int n = frames_of(o.seconds, lie_down.fps) + 1;
    JointSequence m(n, kNumJoints, lie_down.fps);
    const Vector3d pivot = lie_down.at(last, spine2);
    Vector3d axis = (lie_down.at(last, left_hip) - lie_down.at(last, right_hip)).normalized();
    // Prone, the chest cannot sink into the floor: the back rises instead. Turn whichever way lifts the head.
    const Vector3d head_arm = lie_down.at(last, head) - pivot;
    if ((Eigen::AngleAxisd(0.01, axis) * head_arm).y() < head_arm.y()) axis = -axis;
    for (int f = 0; f < n; ++f) {
        const double angle = o.chest_rad * 0.5 * (1 - std::cos(2 * kPi * o.breaths_per_min / 60.0 * f / lie_down.fps));
        const Eigen::Matrix3d turn = Eigen::AngleAxisd(angle, axis).toRotationMatrix();
        for (int j = 0; j < kNumJoints; ++j) {
            const Vector3d& p = lie_down.at(last, j);
            m.at(f, j) = on_rib_cage(j) ? Vector3d(pivot + turn * (p - pivot)) : p;
        }
        // The hands rest where they lie (on the floor, the belly): each elbow re-solved from the moved shoulder.
        for (const auto& [shoulder, elbow, wrist] : {std::array<int, 3>{left_shoulder, left_elbow, left_wrist},
                                                     std::array<int, 3>{right_shoulder, right_elbow, right_wrist}}) {
            const Vector3d& hand = lie_down.at(last, wrist);
            const TwoBoneIkResult ik = solve_two_bone_ik(
                m.at(f, shoulder), hand, (lie_down.at(last, elbow) - lie_down.at(last, shoulder)).norm(),
                (hand - lie_down.at(last, elbow)).norm(), m.at(f, elbow));
            m.at(f, elbow) = ik.middle;
            m.at(f, wrist) = ik.end;
        }
    }
    return m;
}

}  // namespace t2imu
