// A motion at a glance: a strip of skeleton poses drawn as inline SVG lines along the SMPL-22 kinematic tree
// (smpl22::kParents), for the HTML report (no external files).
//
// View: from the body's right side (-X) in the world frame (Y up, metres): world Z, the facing of a canonical
// start pose, runs to the right and Y up. Each pose sits in its own panel, centred horizontally on its pelvis
// (so walking does not run out of the strip) and standing on the ground under its lowest foot joint at that
// frame (support_ground.hpp: the floor, or the tread or step its footholds show), drawn as the grey line: a
// climb stays in view, and where that ground is raised the panel's label gives its height above the starting
// floor ("ground +0.85 m"). Heights above the ground are true, so a jump lifts the pose. SVG user units are
// centimetres: a panel is kPanelWidthCm wide, the floor lies kHeadroomCm below the panel's top and the panel ends
// kBelowFloorCm under the floor. Bones take the colour of their child joint's side: left blue, right orange, centre
// grey.
#pragma once
#include <string>
#include <vector>

#include "motion/joint_sequence.hpp"

namespace t2imu {

constexpr double kPanelWidthCm = 200, kHeadroomCm = 220, kBelowFloorCm = 30;
constexpr double kPoseStripPixelsPerCm = 0.75;  // rendered size: a 150 x 187.5 px panel

// `poses` frame indices evenly over [0, num_frames - 1], first and last included (fewer when the motion has
// fewer frames; {0} for poses == 1).
std::vector<int> strip_frames(int num_frames, int poses);

// <svg class="pose-strip" ...> with one panel per strip frame of `joints` (SMPL-22), each labelled with its
// time in seconds (frame / joints.fps).
std::string pose_strip_svg(const JointSequence& joints, int poses = 6);

}  // namespace t2imu
