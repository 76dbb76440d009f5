// How much of its segment's sway a device on the skin rolls with: the rotation about the skin's outward normal
// that tips the device's horizontal tangent up and down (for a belt board at the front of the waist: the
// frontal-plane roll of walking, whose gravity component is the largest part of the lateral axis at the
// stride frequency).
//
// Why a lever: a belt board sits on the abdomen above the pelvis, where the lumbar spine counter-rotates
// against the pelvic list in the frontal plane (Crosbie, Vachalathiti & Smith 1997, "Patterns of spinal motion
// during walking", Gait & Posture 5:6-12), so the board need not roll as the pelvis segment of a capture does.
// Measured on the shared SisFall walking trials (`t2imu analysis signal-stats`, grav_x at the stride
// frequency; README, "Sensor realism"): the gravity part of the real board's lateral axis, what its roll does to
// gravity's projection, is in quadrature with the rest of that axis (ratio 0.01 - 0.33i, median of 56
// recordings), where ours, rolling with the captured pelvis, is against it (-0.38 - 0.11i over the 160 of the
// ablation's ideal sensor) and cancels it.
//
// The edit: the roll angle, the elevation of the skin's horizontal tangent, is split into its slow part (a
// Gaussian low-pass of sd `sigma_s`: posture, lying down, the mounting tilt) and its sway; the device is
// turned about the skin normal so that it follows gain x the sway. gain 1 leaves the track as it is, 0 keeps
// the device at its slow roll, negative values roll it against its segment. The turn fades where a rotation
// about the normal hardly tips the tangent (the normal within 30 degrees of vertical; none at all lying on the
// back), so postures without a frontal-plane roll are left alone. Position is unchanged (the device turns in
// place).
#pragma once
#include <Eigen/Core>
#include <vector>

#include "imu/placement.hpp"
#include "motion/quaternion.hpp"

namespace t2imu {

struct DeviceRoll {
    double gain = 1;         // share of the sway the device follows (1 = bolted to the segment)
    // The slow part's Gaussian sd (s). 0.5 s passes 13 % of a 0.65 Hz stride and 0.7 % at 1 Hz (gain
    // exp(-(2 pi f sigma)^2 / 2)), and 62 % of a posture change at 0.2 Hz.
    double sigma_s = 0.5;
    bool enabled() const { return gain != 1; }
};

// The mount's track (world_from_sensor per frame at fps; world Y up) turned to follow gain x its sway. A mount
// whose skin normal is within 6 degrees of vertical at rest has no horizontal tangent: left unchanged.
void apply_device_roll(const DeviceRoll& roll, const SensorMount& mount, double fps, std::vector<Quat>* world_from_sensor);

}  // namespace t2imu
