// The activities of human activity recognition in one vocabulary, and the words people use for them: what
// links a prompt ("A man jogs around the track"), a prompt set's class label (SisFall's "jogging"), a motion
// clip's activity tags (the shared mocap manifest's "running") and the motion activity classifier's classes.
//
// Canonical names: walking, running, standing, sitting, stairs_up, stairs_down, lying, jumping, dancing, and
// "stairs" for a class that pools both directions (SisFall's stairs_up_down). Other names (UMAFall's
// applauding, bending, hands_up) pass through unchanged.
#pragma once
#include <string>

namespace t2imu {

// A data set's class label -> the canonical name: jogging -> running, sit_down_stand_up -> sitting,
// lie_down_get_up_bed -> lying, stairs_up_down -> stairs, climbingup/climbingdown (RealWorld) -> stairs_up/down.
std::string canonical_activity(const std::string& label);

// The canonical activity a sentence names by its words, "" when it names none: synonyms (jog, sprint, dash ->
// running; ascend, climb, go up the stairs -> stairs_up; be seated, take a seat -> sitting; lie, recline ->
// lying), checked from the most specific activity to the least, so that "walks up the stairs" is stairs_up and
// "stands up from the chair" is sitting.
std::string activity_named_in(const std::string& sentence);

// The activity a prompt asks for: its prompt set's label (canonical_activity) when it has one, else the one its
// words name (activity_named_in), else "".
std::string activity_asked(const std::string& label, const std::string& prompt);

// Whether a motion of canonical activity `shown` shows the activity `asked` (canonical): the same name, or
// either stair direction for "stairs".
bool shows_activity(const std::string& shown, const std::string& asked);

}  // namespace t2imu
