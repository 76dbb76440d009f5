// Joint heights from both of HumanML3D's copies of a motion: the positions (channel 3, the root's height, and the
// rotation-invariant positions 4-66, whose Y is the joint's height) and the local velocities (193-258: each joint's
// displacement to the next frame, turned about Y, so its Y is the height's difference). Features made from a
// captured motion hold them consistent (humanml3d.hpp, process_file). A diffusion model's need not be: the default's
// walking has its positions flicker from frame to frame while its velocities move like a person's (docs/results.md,
// walking jitter), and recover_from_ric reads the positions alone.
//
// Each joint's height series x (metres, 20 fps) solves
//   min_x  w sum_t (x_t - p_t)^2 + sum_t (x_{t+1} - x_t - v_t)^2,   w = 4 sin^2(pi f_c / fps)
// (a tridiagonal system): the positions p set the height below the crossover f_c, the velocities v above it, where the
// difference operator's gain 2 sin(pi f / fps) passes sqrt(w). A complementary filter, as an attitude filter fuses an
// accelerometer's tilt (no drift) with a gyroscope's rate (no noise). Heights only: the horizontal positions come
// from the root's integrated velocities and match real sensors' high frequencies already.
#pragma once
#include "motion/joint_sequence.hpp"

namespace t2imu {

// `joints`: recover_from_ric(features) (or any joints of the features' frames); returns them with every joint's height
// fused as above. crossover_hz in (0, fps / 2); Error naming --height-crossover otherwise or for features of another
// length or width.
JointSequence fuse_joint_heights(const JointSequence& joints, const FeatureMatrix& features, double crossover_hz);
// A model's features as joints: recover_from_ric, its heights fused when crossover_hz > 0.
JointSequence joints_from_features(const FeatureMatrix& features, double crossover_hz);

}  // namespace t2imu
