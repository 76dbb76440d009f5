// Captions written from what a motion measurably does (motion_attributes.hpp): how fast ("walks slowly", "jogs",
// "sprints"), which way it turns and by how much, whether it steps backward or sideways, how many stairs it
// climbs and in which order ("goes up the stairs and then back down"), how often it jumps, on which side it lies,
// whether it sits down and stands up again. The shared motion capture's own captions rarely say any of this
// (docs/attributes.md), so a text encoder trained on them cannot tell "walks slowly" from "hurries".
//
// Each caption is drawn from varied phrasings, mentioning a random subset of the attributes that are clear in
// the measurements, so an encoder sees each attribute word in many sentences. The activity comes from the
// clip's tags (clips.csv, "walking;standing"); a tag the measurements contradict (a "walking" chunk that does not
// travel) gets no measured caption. Speed classes and their sources: docs/attributes.md.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "motion/motion_attributes.hpp"

namespace t2imu {

enum class WalkingPace { slow, normal, brisk };
enum class RunningPace { jog, run, sprint };

constexpr double kSlowWalk = 1.0;     // m/s: below, a slow walk
constexpr double kBriskWalk = 1.5;    // m/s: above, a brisk walk
constexpr double kJogLimit = 2.7;     // m/s: below, a jog
constexpr double kSprintSpeed = 5.0;  // m/s: above, a sprint
// Running's pace words go to its tails only, so "slowly" and "fast" name speeds apart (a 2.6 m/s jog and a
// 2.8 m/s run are one pace): "slowly" below an easy jog's 2.2 m/s, "fast" above a fast run's 3.3 m/s
// (docs/attributes.md).
constexpr double kEasyJog = 2.2;  // m/s
constexpr double kFastRun = 3.3;  // m/s

WalkingPace walking_pace(double ground_speed_m_s);
RunningPace running_pace(double ground_speed_m_s);
const char* walking_pace_name(WalkingPace p);  // "slow", "normal", "brisk"
const char* running_pace_name(RunningPace p);  // "jog", "run", "sprint"

// The activity the captions describe, from a clip's tags (';'-separated): the first of lying, sitting, stairs,
// jumping, running, walking, standing that the tags name; "" for none (dancing, other: no measured captions).
std::string caption_activity(const std::string& activity_tags);

// Up to `count` distinct captions of a motion with these attributes and tags, drawn with `seed`; none when the
// activity is not one measured captions describe or the measurements contradict it.
std::vector<std::string> measured_captions(const MotionAttributes& a, const std::string& activity_tags, int count,
                                           uint64_t seed);

// The words of measured captions that name an attribute, by attribute ("pace_slow": slowly, slow, leisurely,
// ...; "turn_left": left; ...): what the caption anchor and the coverage report look for in a prompt.
struct AttributeWords {
    std::string attribute;
    std::vector<std::string> words;  // lower case, whole words
};
const std::vector<AttributeWords>& attribute_words();

// The attributes a text asks for: every attribute one of whose words it contains (case-insensitive whole words).
std::vector<std::string> attributes_asked(const std::string& text);

// How many of `asked` (attributes_asked of a prompt) are among `named` (attributes_asked of a caption): what the
// caption anchor and retrieval rank by before meaning, since in GloVe "slowly" and "quickly", "left" and "right"
// are neighbours and a caption's other words outweigh them.
size_t attributes_shared(const std::vector<std::string>& asked, const std::vector<std::string>& named);

}  // namespace t2imu
