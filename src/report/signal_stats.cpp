#include "report/signal_stats.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "analysis/signal_statistics.hpp"
#include "core/error.hpp"
#include "motion/activity_names.hpp"

namespace t2imu {

SignalStats signal_stats(const ImuRecording& r) {
    const size_t n = r.samples.size();
    if (n < 2 || !(r.rate_hz > 0)) throw Error(r.path, "samples", "at least 2 samples at a positive rate");
    std::vector<double> magnitude(n);
    for (size_t i = 0; i < n; ++i) magnitude[i] = std::hypot(r.samples[i][0], r.samples[i][1], r.samples[i][2]);
    return {standard_deviation(magnitude), dominant_frequency_hz(magnitude, r.rate_hz, 0)};
}

std::string comparison_position(const std::vector<ImuRecording>& synthetic, const std::vector<ImuRecording>& real) {
    std::set<std::string> real_positions;
    for (const ImuRecording& r : real) real_positions.insert(r.position);
    std::map<std::string, int> all, shared;
    for (const ImuRecording& r : synthetic) {
        ++all[r.position];
        if (real_positions.count(r.position)) ++shared[r.position];
    }
    const std::map<std::string, int>& counts = shared.empty() ? all : shared;
    std::string best;
    for (const auto& [position, n] : counts)  // alphabetical: a strictly larger count wins
        if (best.empty() || n > counts.at(best)) best = position;
    return best;
}

std::vector<ActivityStats> stats_by_activity(const std::vector<ImuRecording>& synthetic,
                                             const std::vector<ImuRecording>& real, const std::string& position) {
    std::map<std::string, ActivityStats> groups;
    for (const ImuRecording& r : synthetic)
        if (r.position == position) groups[canonical_activity(r.activity)].synthetic.push_back(signal_stats(r));
    for (const ImuRecording& r : real) {
        const auto g = groups.find(canonical_activity(r.activity));
        if (r.position == position && g != groups.end()) g->second.real.push_back(signal_stats(r));
    }
    std::vector<ActivityStats> out;
    for (auto& [activity, g] : groups) {
        g.activity = activity;
        out.push_back(std::move(g));
    }
    return out;
}

double median_of(const std::vector<SignalStats>& stats, double SignalStats::*field) {
    if (stats.empty()) return std::nan("");
    std::vector<double> v;
    for (const SignalStats& s : stats) v.push_back(s.*field);
    std::sort(v.begin(), v.end());
    const size_t m = v.size() / 2;
    return v.size() % 2 ? v[m] : (v[m - 1] + v[m]) / 2;
}

}  // namespace t2imu
