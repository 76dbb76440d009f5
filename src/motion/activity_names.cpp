#include "motion/activity_names.hpp"

#include <array>
#include <cctype>
#include <map>
#include <set>
#include <vector>

namespace t2imu {

namespace {

using Words = std::set<std::string>;

std::vector<std::string> lower_words(const std::string& s) {
    std::vector<std::string> out(1);
    for (char ch : s) {
        const unsigned char c = static_cast<unsigned char>(ch);
        if (std::isalpha(c))
            out.back() += static_cast<char>(std::tolower(c));
        else if (!out.back().empty())
            out.emplace_back();
    }
    if (out.back().empty()) out.pop_back();
    return out;
}

bool any_of(const std::vector<std::string>& words, const Words& set) {
    for (const std::string& w : words)
        if (set.count(w)) return true;
    return false;
}

// Stairs need a stair word, or "steps" with a direction: "walks down a hallway" and "takes a few steps" are not
// stairs, "walks up several steps" is. Climbing without "down" goes up.
std::string stairs_named_in(const std::vector<std::string>& w) {
    static const Words stair = {"stair",     "stairs",   "staircase",  "stairway",
                                "stairwell", "upstairs", "downstairs", "stairstep"};
    static const Words steps = {"step", "steps"};
    static const Words up = {"up", "upstairs", "ascend", "ascends", "ascending", "ascended"};
    static const Words down = {"down", "downstairs", "descend", "descends", "descending", "descended"};
    static const Words climb = {"climb", "climbs", "climbing", "climbed"};
    const bool has_up = any_of(w, up), has_down = any_of(w, down);
    if (!any_of(w, stair) && !(any_of(w, steps) && (has_up || has_down))) return "";
    const bool goes_up = has_up || (any_of(w, climb) && !has_down);
    if (goes_up && has_down) return "stairs";
    if (goes_up) return "stairs_up";
    return has_down ? "stairs_down" : "stairs";
}

}  // namespace

std::string canonical_activity(const std::string& label) {
    static const std::map<std::string, std::string> aliases = {{"jogging", "running"},
                                                               {"run", "running"},
                                                               {"walk", "walking"},
                                                               {"sit", "sitting"},
                                                               {"stand", "standing"},
                                                               {"lie", "lying"},
                                                               {"jump", "jumping"},
                                                               {"sit_down_stand_up", "sitting"},
                                                               {"lie_down_get_up_bed", "lying"},
                                                               {"stairs_up_down", "stairs"},
                                                               {"climbingup", "stairs_up"},
                                                               {"climbingdown", "stairs_down"}};
    const auto a = aliases.find(label);
    return a == aliases.end() ? label : a->second;
}

std::string activity_named_in(const std::string& sentence) {
    const std::vector<std::string> w = lower_words(sentence);
    if (std::string stairs = stairs_named_in(w); !stairs.empty()) return stairs;
    // From the most specific activity to the least: a sentence about sitting down often says "stands up", one
    // about running "strides", one about lying "gets up".
    static const std::array<std::pair<const char*, Words>, 7> kinds = {{
        {"lying",
         {"lie", "lies", "lying", "lay", "lays", "laying", "recline", "reclines", "reclining", "supine", "prone"}},
        {"sitting", {"sit", "sits", "sitting", "sat", "seated", "seat", "chair", "stool", "bench", "sofa", "couch"}},
        {"running", {"run",     "runs",   "running", "ran",    "runner",  "jog",       "jogs",
                     "jogging", "jogged", "jogger",  "sprint", "sprints", "sprinting", "sprinted",
                     "dash",    "dashes", "dashing", "trot",   "trots",   "trotting"}},
        {"jumping",
         {"jump", "jumps", "jumping", "jumped", "hop", "hops", "hopping", "hopped", "leap", "leaps", "leaping",
          "bounce", "bounces", "bouncing"}},
        {"dancing", {"dance", "dances", "dancing", "danced", "dancer", "salsa", "waltz", "ballet", "tango"}},
        {"walking", {"walk",      "walks",   "walking",   "walked",   "walker",  "stroll",  "strolls",
                     "strolling", "march",   "marches",   "marching", "pace",    "paces",   "pacing",
                     "wander",    "wanders", "wandering", "stride",   "strides", "striding"}},
        {"standing", {"stand", "stands", "standing", "stood", "idle", "idly"}},
    }};
    for (const auto& [activity, words] : kinds)
        if (any_of(w, words)) return activity;
    return "";
}

std::string activity_asked(const std::string& label, const std::string& prompt) {
    return label.empty() ? activity_named_in(prompt) : canonical_activity(label);
}

bool shows_activity(const std::string& shown, const std::string& asked) {
    if (shown == asked) return true;
    return asked == "stairs" && (shown == "stairs_up" || shown == "stairs_down");
}

}  // namespace t2imu
