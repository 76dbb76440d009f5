// Analytic two-bone inverse kinematics on joint positions (any consistent length unit, any frame): where the
// middle joint of a two-segment chain (hip -> knee -> ankle) goes so that the chain's end lands on a target.
// Used to re-solve legs after derived motions move hips and feet (stair_gait, sit_to_stand).
#pragma once
#include <Eigen/Core>

namespace t2imu {

struct TwoBoneIkResult {
    Eigen::Vector3d middle;  // the middle joint (knee)
    Eigen::Vector3d end;     // the chain's end (ankle): the target when reached
    bool reached = false;    // false when the target is out of reach (see solve_two_bone_ik)
};

// The middle joint of a chain root -> middle -> end with segment lengths `upper` (root-middle) and `lower`
// (middle-end), both > 0, whose end is placed at `target`. The chain bends in the plane through root, target
// and `bend_hint`, with the middle joint on the hint's side of the root-target line (pass the original knee
// position, or a point in front of the knee). Both lengths are kept exactly in every case.
// Out of reach, farther than upper + lower: the chain is stretched straight from the root toward the target
// and `end` stops short of it. Nearer than |upper - lower|: the chain folds flat along the root-target line.
// Both return reached = false. A hint on the root-target line (no side to bend to) bends toward any direction
// perpendicular to it; a target at the root itself points the chain at the hint.
TwoBoneIkResult solve_two_bone_ik(const Eigen::Vector3d& root, const Eigen::Vector3d& target, double upper,
                                  double lower, const Eigen::Vector3d& bend_hint);

}  // namespace t2imu
