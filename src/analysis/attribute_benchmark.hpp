// The attribute benchmark: do the words of a prompt that say *how* (slowly, fast, left, right, around, backward,
// "A then B") reach the motion drawn for it? Each draw is measured (motion/motion_attributes.hpp) and checked
// by what its prompt's words ask (data/measured_captions.hpp's attributes_asked), so any prompt set can be
// checked, prompts/attributes.tsv being ours (docs/attributes.md):
//   speed ratio      per activity, median ground speed of the draws of prompts asking a fast pace over that of
//                    prompts asking a slow one (a jog counts as slow); prompts asking both are left out
//   turn_left/right  the heading turns that way by at least kTurnShown (sign and size of heading_change_deg)
//   turn_around      |heading change| of at least kAroundShown
//   backward         the draw travels backward
//   stairs_up_down   a stairs prompt with a sequence word: the pelvis rises and then falls by kStairsTripRise
//   sit_then_stand   a sitting prompt with a sequence word: sit_down and then stand_up among its transitions
#pragma once
#include <map>
#include <string>
#include <vector>

#include "motion/joint_sequence.hpp"
#include "motion/motion_attributes.hpp"

namespace t2imu {

constexpr double kTurnShown = 30;         // deg of net heading change in the asked direction
constexpr double kAroundShown = 135;      // deg
constexpr double kStairsTripRise = 0.25;  // m the smoothed pelvis rises above both its start and its end

struct AttributeDraw {
    std::string activity, prompt;
    MotionAttributes attributes;
    double pelvis_peak_above_ends_m = 0;  // the smoothed pelvis's highest point above the higher of its ends
};

// Measures one drawn motion for the benchmark.
AttributeDraw measure_draw(const std::string& activity, const std::string& prompt, const JointSequence& motion);

struct AttributeCheck {
    int passed = 0, checked = 0;
    double share() const { return checked > 0 ? static_cast<double>(passed) / checked : 0.0; }
};

struct SpeedRatio {
    double slow_median_m_s = 0, fast_median_m_s = 0;
    int slow_draws = 0, fast_draws = 0;
    double ratio() const { return slow_median_m_s > 0 ? fast_median_m_s / slow_median_m_s : 0.0; }
};

struct AttributeBenchmark {
    std::map<std::string, SpeedRatio> speed;       // by activity, where both paces were asked
    std::map<std::string, AttributeCheck> checks;  // by check name (above), where one was asked
};

AttributeBenchmark attribute_benchmark(const std::vector<AttributeDraw>& draws);

// Every kept motion of a `t2imu synth` folder, measured as a draw of its job's prompt. Error naming the folder
// when it holds no kept motion.
std::vector<AttributeDraw> synth_folder_draws(const std::string& dir);

// The benchmark as JSON ({"speed": {activity: {...}}, "checks": {name: {...}}}) and as a text table.
std::string attribute_benchmark_json(const AttributeBenchmark& b);
std::string attribute_benchmark_table(const AttributeBenchmark& b);

}  // namespace t2imu
