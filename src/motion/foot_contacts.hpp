// Stance phases of each foot in a walk (SMPL-22 joints, metres, Y up): the frames when a foot carries weight,
// which motion editing pins to the ground (stair_gait places each one on a tread).
//
// A foot is in stance at a frame when its ankle or its toe joint is both low and slow: within kStanceHeight of
// that joint's lowest height in the clip, and moving horizontally slower than kStanceSpeed (central difference).
// Either joint will do because a planted foot rolls: the heel is down and the toe still falling after heel
// strike, the toe down and the heel rising before toe-off. In level walking a swinging foot moves at 2-5 m/s
// and clears the floor by 1-2 cm at the toe and several cm at the ankle (Winter 1991, The Biomechanics and
// Motor Control of Human Gait), so the two thresholds leave a wide margin on both sides. Runs of stance shorter
// than kMinStanceSeconds are dropped (a swinging foot passing slowly over its lowest point) and gaps of up to
// kMaxStanceGapSeconds inside a stance are closed (capture jitter); both count frames at the motion's rate (3 and 1
// at 20 fps, 5 and 2 at 30, 9 and 3 at 60). HumanML3D's own foot-contact channels (humanml3d.hpp)
// use displacement alone with a looser threshold (0.9 m/s at 20 fps); they label contacts, not placements.
#pragma once
#include <vector>

#include "motion/joint_sequence.hpp"

namespace t2imu {

constexpr double kStanceHeight = 0.05;         // m above the joint's lowest height in the clip
constexpr double kStanceSpeed = 0.5;           // m/s, horizontal
constexpr double kMinStanceSeconds = 0.15;     // shortest stance kept
constexpr double kMaxStanceGapSeconds = 0.05;  // longest gap closed inside a stance (one frame at 20 fps)

enum class Foot : int { left = 0, right = 1 };

struct StancePhase {
    Foot foot;
    int first_frame, last_frame;  // inclusive
};

// Per foot, a flag per frame: in stance or not.
std::vector<bool> stance_frames(const JointSequence& walk, Foot foot);

// Per foot, a flag per frame: planted, at whatever height. A foot is planted when its ankle or its toe moves
// slower than kStanceSpeed horizontally and kPlantVerticalSpeed vertically (central differences): the stance
// test without "low", so that a foot on a stair tread, a kerb or a step counts as well as one on the floor. A
// foot that floats up or sinks while it stands still horizontally is not planted. Gaps are closed as in
// stance_frames.
constexpr double kPlantVerticalSpeed = 0.25;  // m/s; a stance foot on a tread moves < 0.1 m/s vertically at 20 fps
std::vector<bool> planted_frames(const JointSequence& motion, Foot foot);

// Every stance phase of both feet, ordered by first frame (then left before right). SMPL-22 joints, at least
// 3 frames; throws Error otherwise.
std::vector<StancePhase> detect_stance_phases(const JointSequence& walk);

// Every planted phase of both feet (planted_frames, runs of at least kMinStanceSeconds), ordered as above.
std::vector<StancePhase> detect_planted_phases(const JointSequence& motion);

}  // namespace t2imu
