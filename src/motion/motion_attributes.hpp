// What a caption could say about how a motion moves, measured from its joints (SMPL-22, metres, Y up, at any
// frame rate): how fast and how far it travels, which way it turns, in which direction it steps relative to its
// facing, how it holds its trunk and swings its arms, how many steps it climbs, how often and how high it
// jumps, how long it sits or lies and on which side, and the order of its transitions. `t2imu motion describe`
// prints these, `data build --measured-captions` writes captions from them, and the attribute benchmark checks
// prompts against them (docs/attributes.md: definitions, thresholds and their sources).
//
// Conventions: heading is the body's facing in the horizontal plane, atan2(x, z) of body_facing(): positive
// angles turn left (counter-clockwise seen from above; a canonical body faces +Z with its left at +X).
// Horizontal paths are smoothed over one second, about a stride, so that a walk's side-to-side sway does not
// count as travel.
#pragma once
#include <string>
#include <utility>
#include <vector>

#include "motion/joint_sequence.hpp"

namespace t2imu {

enum class Posture { standing, seated, lying };
enum class TravelDirection { none, forward, backward, left, right };  // relative to the body's facing
enum class LyingSide { none, back, front, left, right };              // the side the body lies on
enum class Transition { sit_down, stand_up, lie_down, get_up, climb_up, climb_down };

const char* posture_name(Posture p);                   // "standing", "seated", "lying"
const char* travel_direction_name(TravelDirection d);  // "none", "forward", "backward", "left", "right"
const char* lying_side_name(LyingSide s);              // "none", "back", "front", "left", "right"
const char* transition_name(Transition t);  // "sit_down", "stand_up", "lie_down", "get_up", "climb_up", "climb_down"

struct MotionAttributes {
    double duration_s = 0;
    double ground_speed_m_s = 0;    // median horizontal speed of the pelvis path smoothed over 1 s
    double distance_m = 0;          // length of that smoothed path
    double cadence_steps_min = 0;   // foot landings (foot_landings.hpp) per minute, both feet
    double stride_length_m = 0;     // two steps: 2 x ground speed / step rate (0 without steps)
    double heading_change_deg = 0;  // net change of the facing from the first half second to the last, + left
    double turning_deg = 0;         // total absolute change of the facing (a turn there and back counts twice)
    double path_turn_deg = 0;       // net change of the travel direction over the frames that travel, + left
    TravelDirection travel = TravelDirection::none;  // most frames' step direction while travelling
    double arm_swing_m = 0;            // wrist range along the facing relative to the pelvis (5th-95th pct.), both arms
    double trunk_lean_deg = 0;         // mean lean of pelvis -> neck towards the facing, upright frames; + forward
    double rise_m = 0;                 // height of the last foothold over the first (+ up)
    int steps_up = 0, steps_down = 0;  // footholds a tread higher / lower than the one before
    double step_height_m = 0;          // mean height difference of those steps
    int jumps = 0;                     // flights that lift the pelvis kJumpRise over its standing height
    double jump_height_m = 0;          // mean pelvis rise of those flights over its standing height
    double seated_s = 0, lying_s = 0;
    LyingSide lying_side = LyingSide::none;  // over the lying frames (none if it never lies)
    std::vector<Transition> transitions;     // in time order
};

constexpr double kSmoothingSeconds = 1.0;   // horizontal path smoothing: about one stride
constexpr double kTravelSpeed = 0.3;        // m/s: below this a frame does not travel
constexpr double kTreadRise = 0.08;         // m: a foothold this much above/below the one before is a step
constexpr double kJumpRise = 0.12;          // m of pelvis rise over its standing height
constexpr double kMinPostureSeconds = 0.5;  // posture runs shorter than this join their neighbours

// At least 3 frames of SMPL-22 joints; throws Error naming `source` otherwise.
MotionAttributes measure_attributes(const JointSequence& motion, const std::string& source = "motion");

// The posture at each frame: lying when the head is within 0.3 m of the pelvis height, seated when the thighs
// are more than 55 degrees from vertical with the pelvis under 0.7 m above the lowest joint, standing otherwise;
// runs shorter than kMinPostureSeconds joined to the run before (the first to the one after).
std::vector<Posture> posture_per_frame(const JointSequence& motion);

// The smoothed horizontal pelvis path's speed at each frame (m/s), as ground_speed_m_s takes its median.
std::vector<double> ground_speed_per_frame(const JointSequence& motion);

// The attributes as named text fields in a fixed order ("ground_speed_m_s" -> "1.234"; transitions joined by
// '+', "climb_up+climb_down"): the columns `motion describe` prints and the report shows.
std::vector<std::pair<std::string, std::string>> attribute_fields(const MotionAttributes& a);

}  // namespace t2imu
