// Two walking motions joined into one at a stance of the same foot (SMPL-22 joints, metres, Y up), so that a
// clip can hold two activities one after the other: a flight of stairs up and the next one down (the round trip
// that SisFall's D05/D06 and most people's "up the stairs and back down" are), which neither derived flight holds.
//
// Where: the last planted phase of `first` (foot_contacts.hpp, planted at any height, so a foot on a tread or a
// landing counts) and the first planted phase of `second` of the same foot, each at its middle frame: mid-stance,
// when that foot carries the body and the other one swings past it in both clips. Phases cut by a clip's first or
// last frame are passed over (their middle is unknown).
// How: `second` is turned about the vertical so that the body faces at its splice frame the way `first` faces at
// its own, then moved (horizontally and vertically) so that the planted foot's ankle lies where it lies in
// `first`; over `blend_s` seconds centred on the splice the two cross-fade linearly. The planted foot stands at one
// place in both, so it stays planted through the blend; every bone is then set back to `first`'s lengths (a blend
// of two poses shortens bones a little).
#pragma once
#include "motion/joint_sequence.hpp"

namespace t2imu {

struct GaitSpliceOptions {
    double blend_s = 0.2;  // cross-fade centred on the splice, [0.05, 0.4] s
    // The planted phases are found on the joints smoothed by a Gaussian of this sd, [0, 0.1] s (0: as they are): a
    // model's joints flicker from frame to frame while a foot stands, which the plant test's speed limits read as a
    // moving foot; the motions themselves are joined unsmoothed.
    double contact_smoothing_s = 0;
};

// Throws Error naming the field when an option is outside its range.
void validate(const GaitSpliceOptions& o);

struct GaitSplice {
    JointSequence motion;
    int splice_frame = 0;  // the frame of `motion` at the middle of the blend
};

// `first` then `second` (header comment). Refuses (Error) motions that are not SMPL-22 joints at one frame rate,
// and a pair with no planted phase of one foot, long enough to hold half the blend on each side of its middle,
// at the end of `first` and the start of `second`.
GaitSplice splice_at_stance(const JointSequence& first, const JointSequence& second, const GaitSpliceOptions& o);

// splice_at_stance cut to `frames` frames: the window centred on the splice, moved inward where one side is
// shorter than half of it (splice_frame counts in the window). Refuses (Error) what splice_at_stance refuses and a
// join shorter than `frames`.
GaitSplice splice_to_length(const JointSequence& first, const JointSequence& second, int frames,
                            const GaitSpliceOptions& o);

}  // namespace t2imu
