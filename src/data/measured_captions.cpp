#include "data/measured_captions.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <random>
#include <set>
#include <sstream>

namespace t2imu {

WalkingPace walking_pace(double v) {
    return v < kSlowWalk ? WalkingPace::slow : v > kBriskWalk ? WalkingPace::brisk : WalkingPace::normal;
}
RunningPace running_pace(double v) {
    return v < kJogLimit ? RunningPace::jog : v > kSprintSpeed ? RunningPace::sprint : RunningPace::run;
}
const char* walking_pace_name(WalkingPace p) {
    return p == WalkingPace::slow ? "slow" : p == WalkingPace::brisk ? "brisk" : "normal";
}
const char* running_pace_name(RunningPace p) {
    return p == RunningPace::jog ? "jog" : p == RunningPace::sprint ? "sprint" : "run";
}

std::string caption_activity(const std::string& tags) {
    std::set<std::string> named;
    std::stringstream in(tags);
    for (std::string t; std::getline(in, t, ';');) named.insert(t);
    for (const char* a : {"lying", "sitting", "stairs", "jumping", "running", "walking", "standing"})
        if (named.count(a)) return a;
    return "";
}

namespace {

constexpr double kWalkingLeast = 0.4;  // m/s: a "walking" chunk slower than this does not walk
constexpr double kRunningLeast = 1.2;  // m/s: nor a "running" one slower than this run
constexpr double kTurnLeast = 45;      // deg of net heading change that is a turn
constexpr double kTurnAround = 135;    // deg: turning around
constexpr double kCircle = 300;        // deg of travel direction change: a circle
constexpr double kCurve = 60;          // deg: a curve

class Phrasing {
public:
    explicit Phrasing(uint64_t seed) : rng_(seed) {}
    const std::string& pick(const std::vector<std::string>& options) {
        return options[std::uniform_int_distribution<size_t>(0, options.size() - 1)(rng_)];
    }
    bool chance(double p) { return std::uniform_real_distribution<double>(0, 1)(rng_) < p; }

private:
    std::mt19937_64 rng_;
};

std::string side(double degrees) { return degrees > 0 ? "left" : "right"; }

// How the motion turns, as a clause ("" when it goes straight or the chance passes it by).
std::string turn_clause(const MotionAttributes& a, Phrasing& p) {
    const double h = a.heading_change_deg, path = a.path_turn_deg;
    if (std::abs(path) >= kCircle && a.distance_m > 2)
        return p.pick({"in a circle to the " + side(path), "around in a circle to the " + side(path),
                       "in a " + side(path) + " circle"});
    if (std::abs(h) >= kTurnAround)
        return p.pick(
            {"and turns around", "then turns around", "and turns back", "and then turns around to the " + side(h)});
    if (std::abs(h) >= kTurnLeast) {
        const std::string s = side(h);
        if (std::abs(path) >= kCurve && a.distance_m > 1)
            return p.pick({"in a curve to the " + s, "curving to the " + s, "and turns " + s});
        return p.pick({"and turns " + s, "then turns to the " + s, "and turns to the " + s, "turning " + s});
    }
    if (a.distance_m > 2 && std::abs(path) < 20)
        return a.travel == TravelDirection::forward ? p.pick({"in a straight line", "straight ahead", "forward"})
                                                    : "in a straight line";
    return "";
}

std::string direction_words(const MotionAttributes& a, Phrasing& p) {
    switch (a.travel) {
        case TravelDirection::backward: return p.pick({"backwards", "backward"});
        case TravelDirection::left: return p.pick({"sideways to the left", "to the left side"});
        case TravelDirection::right: return p.pick({"sideways to the right", "to the right side"});
        default: return "";
    }
}

std::string walking_verb(const MotionAttributes& a, Phrasing& p) {
    switch (walking_pace(a.ground_speed_m_s)) {
        case WalkingPace::slow:
            return p.pick(
                {"walks slowly", "walks at a slow pace", "slowly walks", "strolls slowly", "walks very slowly"});
        case WalkingPace::brisk:
            return p.pick({"walks quickly", "walks briskly", "walks fast", "walks at a brisk pace", "hurries"});
        default:
            return p.pick({"walks", "walks at a normal pace", "walks at a steady pace", "walks at a moderate speed"});
    }
}

std::string running_verb(const MotionAttributes& a, Phrasing& p) {
    switch (running_pace(a.ground_speed_m_s)) {
        case RunningPace::jog:
            if (a.ground_speed_m_s < kEasyJog)
                return p.pick({"jogs slowly", "runs slowly", "jogs at an easy pace", "jogs at a slow pace"});
            return p.pick({"jogs", "jogs at a steady pace"});
        case RunningPace::sprint: return p.pick({"sprints", "runs very fast", "sprints quickly"});
        default:
            if (a.ground_speed_m_s > kFastRun) return p.pick({"runs fast", "runs quickly", "runs at a fast pace"});
            return p.pick({"runs", "runs at a steady pace"});
    }
}

std::string stride_words(const MotionAttributes& a, bool running, Phrasing& p) {
    if (a.stride_length_m <= 0) return "";
    const double long_stride = running ? 2.6 : 1.6, short_stride = running ? 1.6 : 1.0;  // m, two steps
    if (a.stride_length_m > long_stride) return p.pick({"with long strides", "taking long steps"});
    if (a.stride_length_m < short_stride) return p.pick({"with short steps", "taking small steps"});
    return "";
}

std::string manner_words(const MotionAttributes& a, Phrasing& p) {
    if (a.trunk_lean_deg > 15) return p.pick({"leaning forward", "bent forward"});
    if (a.trunk_lean_deg < -8) return p.pick({"leaning back", "leaning backwards"});
    return "";
}

// Joins the non-empty parts with spaces.
std::string sentence(std::initializer_list<std::string> parts) {
    std::string s;
    for (const std::string& x : parts)
        if (!x.empty()) s += (s.empty() ? "" : " ") + x;
    return s;
}

bool has(const std::vector<Transition>& t, Transition x) { return std::find(t.begin(), t.end(), x) != t.end(); }
bool before(const std::vector<Transition>& t, Transition x, Transition y) {
    const auto i = std::find(t.begin(), t.end(), x);
    return i != t.end() && std::find(i, t.end(), y) != t.end();
}

std::string gait_caption(const MotionAttributes& a, bool running, Phrasing& p) {
    const std::string verb = running ? running_verb(a, p) : walking_verb(a, p);
    const std::string direction = direction_words(a, p);
    const std::string turn = p.chance(0.8) ? turn_clause(a, p) : "";
    const std::string extra = p.chance(0.4) ? stride_words(a, running, p) : p.chance(0.3) ? manner_words(a, p) : "";
    return sentence({verb, direction, turn, extra});
}

std::string stairs_caption(const MotionAttributes& a, Phrasing& p) {
    const std::vector<Transition>& t = a.transitions;
    if (before(t, Transition::climb_up, Transition::climb_down))
        return p.pick({"goes up the stairs and then back down", "walks up a flight of stairs and then walks back down",
                       "climbs up the stairs, turns and comes back down"});
    if (before(t, Transition::climb_down, Transition::climb_up))
        return p.pick({"goes down the stairs and then back up", "walks down the stairs and then climbs back up"});
    const bool up = a.steps_up >= a.steps_down;
    const int steps = up ? a.steps_up : a.steps_down;
    std::string pace;
    if (a.cadence_steps_min > 0 && a.cadence_steps_min < 75) pace = p.pick({"slowly", "carefully"});
    if (a.cadence_steps_min > 115) pace = p.pick({"quickly", "fast"});
    std::string verb =
        up ? p.pick({"walks up the stairs", "climbs up a flight of stairs", "goes upstairs", "ascends the stairs"})
           : p.pick(
                 {"walks down the stairs", "goes down a flight of stairs", "goes downstairs", "descends the stairs"});
    if (steps >= 2 && p.chance(0.4))
        verb = (up ? p.pick({"climbs up ", "steps up "}) : p.pick({"walks down ", "steps down "})) +
               std::to_string(steps) + " steps";
    return sentence({verb, pace});
}

std::string jumping_caption(const MotionAttributes& a, Phrasing& p) {
    std::string count;
    if (a.jumps == 1)
        count = p.pick({"once", "one time"});
    else if (a.jumps > 1)
        count = p.pick({std::to_string(a.jumps) + " times", "several times", "repeatedly"});
    std::string where = a.distance_m < 0.5                     ? p.pick({"in place", "on the spot"})
                        : a.travel == TravelDirection::forward ? "forward"
                                                               : "";
    std::string height = a.jump_height_m > 0.35 ? p.pick({"high", "up high"}) : "";
    return sentence({"jumps", p.chance(0.6) ? height : "", p.chance(0.7) ? where : "", p.chance(0.8) ? count : ""});
}

std::string lying_side_words(LyingSide s, Phrasing& p) {
    switch (s) {
        case LyingSide::back: return p.pick({"on the back", "on their back", "face up"});
        case LyingSide::front: return p.pick({"on the stomach", "face down", "on their front"});
        case LyingSide::left: return p.pick({"on the left side", "on their left side"});
        case LyingSide::right: return p.pick({"on the right side", "on their right side"});
        default: return "";
    }
}

std::string lying_caption(const MotionAttributes& a, Phrasing& p) {
    const std::string where = lying_side_words(a.lying_side, p);
    const std::vector<Transition>& t = a.transitions;
    if (before(t, Transition::lie_down, Transition::get_up))
        return sentence({p.pick({"lies down", "lies down on the floor"}), where,
                         p.pick({"and then gets up", "and gets back up", "then stands up again"})});
    if (has(t, Transition::lie_down))
        return sentence({p.pick({"lies down", "lies down on the floor", "gets down and lies"}), where});
    if (has(t, Transition::get_up))
        return sentence(
            {p.pick({"gets up from lying", "gets up from the floor"}), where.empty() ? "" : "after lying " + where});
    return sentence({p.pick({"lies", "is lying", "lies still"}), where});
}

std::string sitting_caption(const MotionAttributes& a, Phrasing& p) {
    const std::vector<Transition>& t = a.transitions;
    const std::string stay = a.seated_s >= 2 ? p.pick({"for a while", "for a few seconds"}) : "";
    if (before(t, Transition::sit_down, Transition::stand_up))
        return sentence({p.pick({"sits down", "sits down on a chair"}), stay,
                         p.pick({"and then stands up again", "and stands back up", "then gets up"})});
    if (has(t, Transition::sit_down))
        return sentence({p.pick({"sits down", "sits down on a chair", "takes a seat"}), stay});
    if (has(t, Transition::stand_up))
        return p.pick({"stands up from a chair", "gets up from sitting", "rises from a seat"});
    return sentence({p.pick({"sits", "is sitting", "sits still"}), stay});
}

std::string standing_caption(const MotionAttributes& a, Phrasing& p) {
    if (std::abs(a.heading_change_deg) >= kTurnAround)
        return p.pick({"stands and turns around", "turns around on the spot"});
    if (std::abs(a.heading_change_deg) >= kTurnLeast)
        return p.pick({"stands and turns " + side(a.heading_change_deg),
                       "turns to the " + side(a.heading_change_deg) + " while standing"});
    return p.pick({"stands still", "stands in place", "stands without moving much"});
}

// One caption's predicate, or "" when the measurements contradict the activity.
std::string predicate(const MotionAttributes& a, const std::string& activity, Phrasing& p) {
    if (activity == "walking")
        return a.ground_speed_m_s < kWalkingLeast || a.jumps > 0 ? "" : gait_caption(a, false, p);
    if (activity == "running") return a.ground_speed_m_s < kRunningLeast ? "" : gait_caption(a, true, p);
    if (activity == "stairs") return a.steps_up + a.steps_down < 2 ? "" : stairs_caption(a, p);
    if (activity == "jumping") return a.jumps == 0 ? "" : jumping_caption(a, p);
    if (activity == "lying") return a.lying_s < kMinPostureSeconds ? "" : lying_caption(a, p);
    if (activity == "sitting") return a.seated_s < kMinPostureSeconds ? "" : sitting_caption(a, p);
    if (activity == "standing") return a.ground_speed_m_s > kWalkingLeast ? "" : standing_caption(a, p);
    return "";
}

std::vector<std::string> words_of(const std::string& text) {
    std::vector<std::string> out;
    std::string w;
    for (char c : text + " ") {
        if (std::isalpha(static_cast<unsigned char>(c)))
            w += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        else if (!w.empty())
            out.push_back(w), w.clear();
    }
    return out;
}

}  // namespace

std::vector<std::string> measured_captions(const MotionAttributes& a, const std::string& tags, int count,
                                           uint64_t seed) {
    const std::string activity = caption_activity(tags);
    Phrasing p(seed);
    std::vector<std::string> out;
    for (int tries = 0; static_cast<int>(out.size()) < count && tries < 8 * count; ++tries) {
        const std::string body = predicate(a, activity, p);
        if (body.empty()) break;
        const std::string caption = p.pick({"a person", "someone", "the person", "a person"}) + " " + body + ".";
        if (std::find(out.begin(), out.end(), caption) == out.end()) out.push_back(caption);
    }
    return out;
}

const std::vector<AttributeWords>& attribute_words() {
    static const std::vector<AttributeWords> table = {
        {"pace_slow", {"slowly", "slow", "leisurely", "strolls", "stroll", "carefully", "easy"}},
        {"pace_fast", {"quickly", "fast", "briskly", "brisk", "hurries", "hurry", "rushes", "sprints", "sprint"}},
        {"jog", {"jogs", "jog", "jogging"}},
        {"turn_left", {"left"}},
        {"turn_right", {"right"}},
        {"turn_around", {"around", "back"}},
        {"circle", {"circle", "circles"}},
        {"curve", {"curve", "curving"}},
        {"backward", {"backwards", "backward"}},
        {"sideways", {"sideways", "sidesteps"}},
        {"stride_long", {"long"}},
        {"stride_short", {"short", "small"}},
        {"lean", {"leaning", "bent"}},
        {"lying_side", {"side"}},
        {"lying_front", {"stomach", "front"}},  // not "face": face up and face down share it
        {"sequence", {"then", "again"}},
        {"count", {"once", "twice", "times", "several", "repeatedly"}},
        {"jump_high", {"high"}},
    };
    return table;
}

std::vector<std::string> attributes_asked(const std::string& text) {
    const std::vector<std::string> words = words_of(text);
    std::vector<std::string> out;
    for (const AttributeWords& a : attribute_words())
        for (const std::string& w : a.words)
            if (std::find(words.begin(), words.end(), w) != words.end()) {
                out.push_back(a.attribute);
                break;
            }
    return out;
}

size_t attributes_shared(const std::vector<std::string>& asked, const std::vector<std::string>& named) {
    size_t n = 0;
    for (const std::string& a : asked) n += std::find(named.begin(), named.end(), a) != named.end();
    return n;
}

}  // namespace t2imu
