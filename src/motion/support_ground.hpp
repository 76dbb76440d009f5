// The ground a motion stands on, inferred from where its feet are planted (SMPL-22 joints, metres, Y up, the
// floor at y = 0 where HumanML3D's processing and place_on_floor put a clip's lowest joint).
//
// A quality filter that measures heights above y = 0 reads a flight of stairs as hovering: at the top of a
// 2 m climb every joint is 2 m above the starting floor. The treads are not in the motion, but the footholds
// are: each planted phase of a foot (foot_contacts.hpp, planted_frames: still horizontally and vertically, at
// any height) stands on something at the lowest height its ankle or toe joint reaches in the phase (a foot
// lands, rolls and lifts on its tread). Not every planted foot stands on raised ground, though: a body that
// floats 0.5 m up plants its feet in mid-air, a dancer holds a lifted foot still while the other carries the
// weight, and one that sinks 0.4 m in one frame plants them in a pit. So:
//   - footholds within kFloorBand of the floor are on the floor. Captured clips disagree about where the floor
//     is by that much (some put it under the toe joints, others under one early frame's lowest joint), and no
//     stair riser or kerb is that low;
//   - a foothold above the band is raised ground only when it carries the body: it lasts at least
//     kMinRaisedStanceSeconds and, at some frame of it, the foot is the body's lowest part (within the band).
//     A foot held up while the other stands on the floor is a pose, and feet held up while lying are no steps;
//   - raised ground must connect to the floor: a chain of footholds in time order, each hop from the last
//     grounded foothold a step a person can take (a rise or drop of at most kMaxFootholdRise, landing at least
//     kMinStepDistance away horizontally: stepping onto a tread or a kerb carries the foot over its edge; rising
//     or sinking in place does not). The chain runs forward (a climb starts on the floor) and backward (a
//     descent ends there). A clip may start or end with a foot on its way to the floor (a flight cut before the
//     last step lands): when no foothold is on the floor but some joint comes within kFloorBand of it, the
//     lowest foothold links to the floor if it is at most kMaxFootholdRise above it. No ground is below the floor.
// So a staircase, a kerb or a ramp qualify; a level walk raised into the air, a body that drifts up without
// planting its feet, or a sudden sink do not.
//
// Where a raised foothold is ground: within kFootprintReach (horizontal distance) of its footprint, the segment
// from the foot's ankle to its toe averaged over the phase, from the frame the foot lands until the same foot
// lands again (the foot that leaves a tread and the other foot swinging past it must clear it; before the foot
// arrives, and after it has moved on, nothing says the tread is there). Footprints and not whole treads: a
// tread's edges are not in the motion, and a swinging foot passes beside the other foot's tread, or beyond the
// last tread of a clip cut before the floor, at 0.15-0.2 m. Everywhere else the ground is the floor.
#pragma once
#include <Eigen/Core>
#include <vector>

#include "motion/foot_contacts.hpp"
#include "motion/joint_sequence.hpp"

namespace t2imu {

constexpr double kFloorBand = 0.10;              // m: footholds this near the floor stand on it
constexpr double kMinRaisedStanceSeconds = 0.3;  // a stair stance lasts 0.5-0.9 s; a held pose can be shorter
// m between consecutive grounded footholds: two stair risers at once (building codes allow at most 0.196 m a
// riser in homes) and a kerb, not a body that lifts off.
constexpr double kMaxFootholdRise = 0.40;
constexpr double kMinStepDistance = 0.15;  // m, horizontal: a stair's going is at least 0.22 m
constexpr double kFootprintReach = 0.10;   // m, horizontal, around a footprint's ankle-toe segment

struct Foothold {
    StancePhase phase;
    double height = 0;           // m: the lowest its ankle or toe joint reaches in the phase
    Eigen::Vector2d ankle, toe;  // horizontal (x, z), means over the phase: the footprint
    int until_frame = 0;         // exclusive: the same foot's next foothold's first frame, or the clip's end
    bool raised = false;         // above the band and carrying the body
    bool grounded = false;       // on the floor, or raised and linked to it by steps
};

// The footholds of a motion in time order (detect_planted_phases) with the rules above applied.
std::vector<Foothold> infer_footholds(const JointSequence& motion);

class SupportGround {
public:
    explicit SupportGround(const JointSequence& motion);
    // m: the ground under p (its y ignored) at `frame`: the nearest raised grounded footprint in effect then
    // within kFootprintReach, else 0 (the floor).
    double height_at(const Eigen::Vector3d& p, int frame) const;
    const std::vector<Foothold>& raised_footholds() const { return footholds_; }  // raised and grounded

private:
    std::vector<Foothold> footholds_;
};

}  // namespace t2imu
