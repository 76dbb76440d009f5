// Stair gait derived from a captured level walk (SMPL-22 joints, metres, Y up, floor at y = 0): the walk is
// replayed on a straight staircase that runs along its walking direction, step over step (one tread per step).
//
// How the walk is edited (positions only; every bone keeps its length):
//   1. Cadence: the walk is replayed slower (retime), since stair gait is slower than level walking.
//   2. Footholds: each stance phase (foot_contacts.hpp) gets the next tread in walking order, feet side by side
//      sharing one; the foot is moved rigidly so that its ankle-toe midpoint sits over the tread's middle and
//      raised by the tread's height. Steps thereby shorten from the walk's step length to the going.
//   3. Swing: between two footholds a foot keeps the source's swing timing (its progress along the walk, mapped
//      from the old step onto the new one) and moves up or down by a minimum-jerk blend, leading for ascent (up
//      before over the nosing) and lagging for descent (over the nosing before down), plus a lift sin(pi t)
//      sized so that ankle and toe clear every tread under them by swing_clearance_m at mid-swing.
//   4. Body: pelvis, hips and trunk move together: progress along the walk scaled by the least-squares ratio of
//      new to old foothold positions, height raised by the mean height of the two feet's footholds (smoothed),
//      and lowered further wherever a leg would be stretched past the walk's own reach (motion_edit.hpp). The
//      trunk leans forward by trunk_lean_rad about the pelvis.
//   5. Knees: two-bone IK from hip to ankle, bending to the walk's knee side.
// The clip is trimmed to the frames where both feet lie between two footholds, so no foot hangs before the
// first tread it has; expect about one gait cycle less than the retimed walk.
//
// Biomechanics behind the defaults (healthy adults, stairs of about 17-18 cm rise):
//   - Knee flexion peaks at about 90-100 deg in ascent swing and 85-95 deg in descent, against about 60-70 deg in
//     level walking; hip flexion peaks at about 60-65 deg in ascent (McFadyen & Winter 1988, J Biomech 21:733;
//     Protopapadaki et al. 2007, Clin Biomech 22:203). Those follow here from the geometry, not from targets:
//     on 25 captured Bandai Namco walks (defaults, 0.17 m rise) knee flexion peaks at 98-115 deg ascending and
//     105-122 deg descending, against 70-82 deg in the same walks on the level.
//   - Cadence is lower than on the level, more so ascending than descending (Riener, Rabuffetti & Frigo 2002,
//     Gait Posture 15:32; Protopapadaki et al. 2007): cadence_factor 0.72 ascent, 0.76 descent by default.
//     Set on the shared SisFall subjects' stair trials, whose waist step frequency (median per recording 1.38 Hz)
//     is 0.76 of their level walking's (1.82 Hz); at 0.80 / 0.85 the derived stairs stepped at 1.56 Hz. That
//     median hides two paces, D05 "slowly" at 1.25 Hz and D06 "quickly" at 2.80 Hz; stairs from walks played
//     1.3-1.5 times as fast for the quick one took real walking into the stairs class
//     (docs/realism.md on quick stairs).
//   - The trunk leans further forward than on the level when ascending, less so descending (McFadyen & Winter
//     1988; Riener et al. 2002): trunk_lean_rad 0.12 (7 deg) ascent, 0.05 descent by default.
//   - The swinging foot clears the nosing by a few centimetres (Hamel, Okita, Higginson & Cavanagh 2005, on
//     stair descent): swing_clearance_m 0.04 by default.
//   - Building codes bound the geometry: riser 102-178 mm and tread at least 279 mm in public buildings,
//     riser at most 196 mm and tread at least 254 mm in homes (International Building Code and International
//     Residential Code, 2018); UK Approved Document K allows rise 150-220 mm, going 220-300 mm for private
//     stairs. The options accept rise 0-0.22 m (0: the level case, for checks) and going 0.22-0.35 m.
//
// Quality: score_motion (motion_quality.hpp) measures foot skating, hover and penetration against the ground
// the motion's own footholds show (support_ground.hpp), as for any generated climb; the staircase's height_at
// is the ground that inference should find (tests/test_support_ground.cpp compares the two).
#pragma once
#include <Eigen/Core>
#include <vector>

#include "motion/foot_contacts.hpp"
#include "motion/joint_sequence.hpp"

namespace t2imu {

struct StairOptions {
    double rise_m = 0.17;             // riser height, [0, 0.22]
    double going_m = 0.28;            // tread depth along the walk, [0.22, 0.35]
    bool ascend = true;               // false: descend (the flight goes down along the walk)
    double trunk_lean_rad = 0.12;     // extra forward trunk lean about the pelvis, [0, 0.35]
    double cadence_factor = 0.72;     // pace relative to the source walk, [0.5, 1]
    double swing_clearance_m = 0.04;  // toe and ankle above the surface under them at mid-swing, [0.01, 0.10]
};

// Defaults by direction (see above): the caller samples around them.
StairOptions default_stair_options(bool ascend);
// Throws Error naming the field when an option is outside its range.
void validate(const StairOptions& o);

// A straight flight along `direction` (horizontal unit vector): tread k (k = 0 .. steps) covers the distances
// along it from start_m + k * going_m to start_m + (k + 1) * going_m from `origin`; tread 0 is the floor
// before the flight (it extends backward without end) and tread `steps` the landing after it (extends forward).
// Tread k stands k * rise_m above the floor when ascending, (steps - k) * rise_m when descending. The floor of
// the lowest tread is y = 0. Treads extend sideways without end.
struct Staircase {
    Eigen::Vector3d origin = Eigen::Vector3d::Zero();      // y ignored
    Eigen::Vector3d direction = Eigen::Vector3d::UnitZ();  // horizontal unit vector, the walking direction
    double start_m = 0, rise_m = 0, going_m = 0.28;
    int steps = 0;
    bool ascend = true;

    int tread_at(const Eigen::Vector3d& p) const;  // the tread under horizontal point p (y ignored)
    double tread_height(int tread) const;          // m
    double height_at(const Eigen::Vector3d& p) const { return tread_height(tread_at(p)); }
    double along(const Eigen::Vector3d& p) const;  // distance of p from origin along direction (m)
};

struct StairFoothold {
    Foot foot;
    int first_frame, last_frame;  // the stance phase in the derived motion, inclusive
    int tread;
};

struct StairMotion {
    JointSequence motion;
    Staircase stairs;
    std::vector<StairFoothold> footholds;  // in time order
};

// Refuses (Error) a motion that is not 22 joints, that travels less than 1.5 m, faces more than 60 deg away
// from the way it travels (a side step, walking backward), has fewer than four stance phases, or whose
// footholds do not advance along the walk in time order (a turn).
StairMotion derive_stairs(const JointSequence& walk, const StairOptions& o);
JointSequence walk_to_stairs(const JointSequence& walk, const StairOptions& o);

}  // namespace t2imu
