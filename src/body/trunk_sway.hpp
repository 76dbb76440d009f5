// How much of its trunk segment's sway a device on the trunk turns with, about the segment's left-right axis
// (pitch) and its long axis (yaw): a belt board at the waist, a chest strap.
//
// Why a lever: a belt at the waistline lies on the abdomen between the pelvis and the ribs, where the lumbar
// spine counter-rotates against the pelvis in the transverse plane and damps its tilt in the sagittal one
// (Crosbie, Vachalathiti & Smith 1997, Gait & Posture 5:6-12), while the pelvis segment of a capture carries
// the full rotation of the hip line: SisFall's board turns less than a sensor on the captured pelvis (`t2imu
// analysis signal-stats`, gyr_sway_sd; the gains calibrated and measured, and why the share is no constant of a
// belt: docs/realism.md on the trunk's sway). Turning about a vertical axis 0.1-0.15 m behind the board,
// the yaw is also a lateral acceleration at the stride frequency.
//
// The edit: the segment's rotation (world from rest) R is split into its slow part S (a Gaussian low-pass of
// the sign-continuous quaternion, sd `sigma_s`: heading, posture, lying down) and its sway W = S^T R, a
// rotation in the segment's rest axes (X left, Y up along the trunk, Z front); W's rotation vector is scaled
// by pitch_gain about X and yaw_gain about Y (Z, the frontal-plane roll, is left as it is: a lever scaling it lowered
// HAR and raised the two-sample accuracy, docs/realism.md on device roll and drawn bodies, and was retired).
// The sensor then rides on S W': its orientation and its position about the segment's proximal joint both follow, so
// the lever arm's tangential acceleration shrinks with the turn. Gains 1 leave the segment as it is.
#pragma once
#include <vector>

#include "body/body_model.hpp"

namespace t2imu {

struct TrunkSway {
    double pitch_gain = 1;  // share of the sway about the segment's left-right axis the device follows
    double yaw_gain = 1;    // ... about its long axis
    // The slow part's Gaussian sd (s): 0.5 s passes 0.007 of a 1 Hz stride's amplitude and 0.62 of a 0.2 Hz turn's.
    double sigma_s = 0.5;
    bool enabled() const { return pitch_gain != 1 || yaw_gain != 1; }
};

bool is_trunk_segment(int segment);  // pelvis, spine1, spine2, spine3

// The frames (fps) with segment's rotation edited as above; other segments, and every joint position, as they
// were. A segment that is not a trunk segment, or gains of 1, leave the frames unchanged.
void apply_trunk_sway(const TrunkSway& sway, int segment, double fps, std::vector<PosedFrame>* frames);

}  // namespace t2imu
