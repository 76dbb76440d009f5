#include "analysis/attribute_benchmark.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "core/npy.hpp"
#include "data/measured_captions.hpp"
#include "imu/synth_folder.hpp"
#include "motion/skeleton.hpp"

namespace t2imu {

namespace {

double median(std::vector<double> v) {
    if (v.empty()) return 0;
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

bool asks(const std::vector<std::string>& asked, const char* attribute) {
    return std::find(asked.begin(), asked.end(), attribute) != asked.end();
}

bool in_order(const std::vector<Transition>& t, Transition first, Transition then) {
    const auto i = std::find(t.begin(), t.end(), first);
    return i != t.end() && std::find(i, t.end(), then) != t.end();
}

void count(AttributeBenchmark& b, const char* check, bool passed) {
    AttributeCheck& c = b.checks[check];
    ++c.checked;
    c.passed += passed;
}

}  // namespace

AttributeDraw measure_draw(const std::string& activity, const std::string& prompt, const JointSequence& motion) {
    AttributeDraw d{activity, prompt, measure_attributes(motion, prompt), 0};
    const int n = motion.num_frames, half = std::max(1, static_cast<int>(std::lround(motion.fps / 2)));
    std::vector<double> smooth(static_cast<size_t>(n));
    for (int f = 0; f < n; ++f) {  // pelvis height over a 1 s window that shrinks at the ends
        const int h = std::min({half, f, n - 1 - f});
        double s = 0;
        for (int g = f - h; g <= f + h; ++g) s += motion.at(g, smpl22::pelvis).y();
        smooth[static_cast<size_t>(f)] = s / (2 * h + 1);
    }
    d.pelvis_peak_above_ends_m =
        *std::max_element(smooth.begin(), smooth.end()) - std::max(smooth.front(), smooth.back());
    return d;
}

AttributeBenchmark attribute_benchmark(const std::vector<AttributeDraw>& draws) {
    AttributeBenchmark b;
    std::map<std::string, std::pair<std::vector<double>, std::vector<double>>> speeds;  // activity -> slow, fast
    for (const AttributeDraw& d : draws) {
        const std::vector<std::string> asked = attributes_asked(d.prompt);
        const MotionAttributes& a = d.attributes;
        const bool slow = asks(asked, "pace_slow") || asks(asked, "jog"), fast = asks(asked, "pace_fast");
        if (slow != fast) (slow ? speeds[d.activity].first : speeds[d.activity].second).push_back(a.ground_speed_m_s);
        if (asks(asked, "turn_around"))
            count(b, "turn_around", std::abs(a.heading_change_deg) >= kAroundShown);
        else if (asks(asked, "turn_left") != asks(asked, "turn_right"))
            count(b, asks(asked, "turn_left") ? "turn_left" : "turn_right",
                  (asks(asked, "turn_left") ? a.heading_change_deg : -a.heading_change_deg) >= kTurnShown);
        if (asks(asked, "backward")) count(b, "backward", a.travel == TravelDirection::backward);
        if (asks(asked, "sequence") && d.activity.rfind("stairs", 0) == 0)
            count(b, "stairs_up_down", d.pelvis_peak_above_ends_m >= kStairsTripRise);
        if (asks(asked, "sequence") && d.activity == "sitting")
            count(b, "sit_then_stand", in_order(a.transitions, Transition::sit_down, Transition::stand_up));
    }
    for (const auto& [activity, s] : speeds) {
        if (s.first.empty() || s.second.empty()) continue;
        b.speed[activity] = {median(s.first), median(s.second), static_cast<int>(s.first.size()),
                             static_cast<int>(s.second.size())};
    }
    return b;
}

std::vector<AttributeDraw> synth_folder_draws(const std::string& dir) {
    std::vector<AttributeDraw> draws;
    for (const JobMarker& m : read_job_markers(dir)) {
        if (!m.kept) continue;
        const std::string path = dir + "/" + job_joints_file(m.job);
        draws.push_back(measure_draw(m.activity, m.prompt, joint_sequence_from_array(read_npy(path), path, 22, 3)));
    }
    if (draws.empty()) throw Error(dir, "jobs", "at least one kept motion (a t2imu synth folder)");
    return draws;
}

std::string attribute_benchmark_json(const AttributeBenchmark& b) {
    nlohmann::json j;
    j["speed"] = nlohmann::json::object();
    for (const auto& [activity, s] : b.speed)
        j["speed"][activity] = {{"slow_median_m_s", s.slow_median_m_s},
                                {"fast_median_m_s", s.fast_median_m_s},
                                {"slow_draws", s.slow_draws},
                                {"fast_draws", s.fast_draws},
                                {"ratio", s.ratio()}};
    j["checks"] = nlohmann::json::object();
    for (const auto& [name, c] : b.checks)
        j["checks"][name] = {{"passed", c.passed}, {"checked", c.checked}, {"share", c.share()}};
    return j.dump(1) + "\n";
}

std::string attribute_benchmark_table(const AttributeBenchmark& b) {
    std::string out;
    char line[160];
    for (const auto& [activity, s] : b.speed) {
        std::snprintf(line, sizeof line, "speed %-10.10s fast / slow %.2f (median %.2f / %.2f m/s, %d / %d draws)\n",
                      activity.c_str(), s.ratio(), s.fast_median_m_s, s.slow_median_m_s, s.fast_draws, s.slow_draws);
        out += line;
    }
    for (const auto& [name, c] : b.checks) {
        std::snprintf(line, sizeof line, "%-16.16s %d of %d draws (%.0f %%)\n", name.c_str(), c.passed, c.checked,
                      100 * c.share());
        out += line;
    }
    return out;
}

}  // namespace t2imu
