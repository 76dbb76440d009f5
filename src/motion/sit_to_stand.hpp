// Sitting down on a chair, sitting, and standing up again, derived from a captured idle standing clip (SMPL-22
// joints, metres, Y up, floor at y = 0): the feet stay planted where the person stands, the pelvis travels
// back and down onto a seat behind them and later forward and up, the trunk bends forward about the pelvis
// and straightens, and both knees are re-solved by two-bone IK; the source's upper-body idle motion (head,
// arms, breathing, sway of the trunk relative to the pelvis) plays on throughout.
//
// Timeline: stand_before_s standing, sit_down_s, seated_s, stand_up_s, stand_after_s standing. The source
// is consumed in order, one source frame per output frame, so it must be at least as long as the sum.
//
// Biomechanics behind the phases (healthy adults, chair without armrests, self-paced):
//   - Rising has four phases (Schenkman et al. 1990, Phys Ther 70:638): flexion momentum (the trunk bends
//     forward while the pelvis stays on the seat), momentum transfer (seat-off, at about a third of the
//     movement, near the trunk's peak flexion), extension (hips and knees straighten, the pelvis rises and
//     comes forward over the feet) and stabilisation. Here (fractions of stand_up_s): the trunk flexes to its
//     peak at 0.35 and is upright again at 0.8; the pelvis goes forward from 0.25 to 0.75 and up from seat-off
//     (0.35) to 0.9.
//   - Peak trunk flexion is about 30-50 deg and rising takes about 1.5-2.5 s; sitting down takes somewhat longer
//     than rising and moves the pelvis back and down in one sweep, with the trunk's peak flexion late, as the
//     seat is reached (Kralj, Jaeger & Munih 1990, J Biomech 23:1123; Roebroeck et al. 1994, Clin Biomech
//     9:235). Here (fractions of sit_down_s): sitting down moves the pelvis back over 0-0.75 and down over
//     0.1-0.95, the trunk flexes from 0.05 to its peak at 0.55 and is upright when seated. Defaults: 2.2 s down, 1.8 s
//     up, 40 deg.
//   - Seated, the pelvis joint (between the hip joint centres) sits about 10 cm above the seat, on the ischial
//     tuberosities: pelvis_above_seat_m. The chair stands where the thighs reach it with the shanks vertical
//     (knees at about 90 deg), which fixes how far behind the ankles the seated pelvis is.
//   - Ordinary dining and office chairs have seats 0.40-0.50 m high, about half an adult's hip-joint height
//     (0.85-0.95 m); the options allow 0.25-0.60 m so that a caller can scale the seat to a small capture rig.
// Every move is a minimum-jerk blend (motion_edit.hpp), and where the legs would be stretched past the
// source's own reach the body comes down sooner (lower_to_reach), which is how the pelvis path bends.
#pragma once
#include "motion/joint_sequence.hpp"

namespace t2imu {

struct ChairOptions {
    double seat_height_m = 0.45;           // seat surface above the floor, [0.25, 0.60] (scaled to the rig's size)
    double pelvis_above_seat_m = 0.10;     // seated pelvis joint above the seat surface, [0.05, 0.15]
    double stand_before_s = 1.0;           // [0, 10]
    double sit_down_s = 2.2;               // [1, 4]
    double seated_s = 3.0;                 // [0.5, 60]
    double stand_up_s = 1.8;               // [1, 4]
    double stand_after_s = 1.0;            // [0, 10]
    double trunk_flexion_peak_rad = 0.70;  // forward trunk bend at its peak, beyond the standing posture, [0.2, 1.0]
};

// Throws Error naming the field when an option is outside its range.
void validate(const ChairOptions& o);

// Frames the derived clip has (and the source must have at least): the timeline's duration at the source's
// fps, plus one.
int stand_sit_stand_frames(const ChairOptions& o, double fps);

// How far (m, horizontally) the source's pelvis may wander from where it stands at frame 0: the feet stay planted
// there and the seat is placed from them, so a source that steps away stretches one leg and sinks the seated
// pelvis below the seat. Measured on windows of a captured idle stand (ReActIdle 000_genuine, 6-9 s): pelvis
// drifts of 0.12-0.18 m (weight shifts) sink it by less than 1 cm, steps of 0.31 and 0.41 m by 6 and 4 cm.
constexpr double kMaxStandingDriftM = 0.25;

// Refuses (Error) a source that is not 22 joints, is shorter than stand_sit_stand_frames, or whose pelvis wanders
// further than kMaxStandingDriftM over those frames.
JointSequence stand_sit_stand(const JointSequence& standing, const ChairOptions& o);

}  // namespace t2imu
