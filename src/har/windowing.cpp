#include "har/windowing.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <set>

#include "core/error.hpp"
#include "core/parse.hpp"
#include "core/signal/gaussian_filter.hpp"
#include "core/signal/resample_poly.hpp"
#include "har/class_map.hpp"

namespace t2imu {

namespace {

bool is_integer(double v) { return std::fabs(v - std::round(v)) < 1e-9 && v >= 1; }

std::string trial_key(const ImuRecording& r) {
    for (const std::string& sep : {std::string("_"), std::string("/")}) {
        const std::string suffix = sep + r.position + ".csv";
        if (r.path.size() > suffix.size() && ends_with(r.path, suffix))
            return r.path.substr(0, r.path.size() - suffix.size());
    }
    return r.path;
}

bool position_matches(const std::string& wanted, const std::string& position) {
    return position == wanted || position == "left_" + wanted || position == "right_" + wanted;
}

}  // namespace

std::vector<double> resample_channel(const std::vector<double>& x, double rate_in, double rate_out) {
    if (std::fabs(rate_in - rate_out) < 1e-9 || x.empty()) return x;
    if (is_integer(rate_in) && is_integer(rate_out)) {
        const long a = std::lround(rate_in), b = std::lround(rate_out), g = std::gcd(a, b);
        return resample_poly(x, static_cast<int>(b / g), static_cast<int>(a / g));
    }
    std::vector<double> y = x;
    if (rate_out < rate_in) {
        // A Gaussian of sigma s seconds is 3 dB down at 0.1325 / s Hz; put that at 0.8 x the new Nyquist.
        const double sigma_samples = 0.1325 / (0.8 * rate_out / 2) * rate_in;
        TimeSeries s = Eigen::Map<const TimeSeries>(x.data(), static_cast<Eigen::Index>(x.size()), 1);
        s = gaussian_filter1d_nearest(s, sigma_samples);
        y.assign(s.data(), s.data() + s.size());
    }
    const double duration = static_cast<double>(x.size() - 1) / rate_in;
    const size_t n = static_cast<size_t>(std::floor(duration * rate_out + 1e-9)) + 1;
    std::vector<double> out(n);
    for (size_t k = 0; k < n; ++k) {
        const double pos = static_cast<double>(k) * rate_in / rate_out;
        const size_t i = std::min(static_cast<size_t>(pos), y.size() - 1);
        const double f = pos - static_cast<double>(i);
        out[k] = i + 1 < y.size() ? y[i] * (1 - f) + y[i + 1] * f : y[i];
    }
    return out;
}

void WindowOptions::validate() const {
    if (!(rate_hz > 0 && rate_hz <= 10000))
        throw Error("windows", "--rate", "0 < HZ <= 10000", std::to_string(rate_hz));
    if (!(window_s > 0 && window_s <= 3600))
        throw Error("windows", window_option, "0 < SECONDS <= 3600", std::to_string(window_s));
    if (!(overlap >= 0 && overlap < 1))
        throw Error("windows", "--overlap", "0 <= OVERLAP < 1", std::to_string(overlap));
    if (std::lround(window_s * rate_hz) < min_window_samples)
        throw Error(
            window_option, std::to_string(window_s) + " s",
            "at least " + std::to_string(min_window_samples) + " samples at --rate " + std::to_string(rate_hz) + " Hz");
}

WindowSet make_windows(const std::vector<ImuRecording>& recordings, const WindowOptions& o) {
    o.validate();
    std::vector<std::string> positions = o.positions;
    if (positions.empty()) {
        std::set<std::string> all;
        for (const ImuRecording& r : recordings) all.insert(r.position);
        if (all.size() != 1)
            throw Error(o.positions_option, "positions",
                        "a choice: the data set holds " + std::to_string(all.size()) + " positions");
        positions = {*all.begin()};
    }
    for (const std::string& p : positions) check_position_held(recordings, p, o.positions_option, /*sided=*/true);
    std::map<std::string, std::vector<const ImuRecording*>> trials;
    for (const ImuRecording& r : recordings) trials[r.dataset + "|" + trial_key(r)].push_back(&r);
    WindowSet w;
    w.length = static_cast<int>(std::lround(o.window_s * o.rate_hz));
    const int per_position = o.gyro ? 6 : 3;
    w.channels = per_position * static_cast<int>(positions.size());
    const int step = std::max(1, static_cast<int>(std::lround(w.length * (1 - o.overlap))));
    size_t longest = 0;  // samples of the longest trial with every position, to name a window that fits none
    for (const auto& [key, recs] : trials) {
        std::vector<const ImuRecording*> chosen;
        for (const std::string& p : positions) {
            const ImuRecording* match = nullptr;
            for (const ImuRecording* r : recs)
                if (position_matches(p, r->position) && (!match || r->position < match->position)) match = r;
            if (!match) break;
            chosen.push_back(match);
        }
        if (chosen.size() != positions.size()) continue;
        const std::string label = map_activity(chosen[0]->dataset, chosen[0]->activity);
        if (label.empty()) continue;
        std::vector<std::vector<double>> channels;
        size_t n = SIZE_MAX;
        for (const ImuRecording* r : chosen)
            for (int c = 0; c < per_position; ++c) {
                std::vector<double> x(r->samples.size());
                for (size_t k = 0; k < x.size(); ++k) x[k] = r->samples[k][static_cast<size_t>(c)];
                channels.push_back(resample_channel(x, r->rate_hz, o.rate_hz));
                n = std::min(n, channels.back().size());
            }
        longest = std::max(longest, n);
        for (size_t start = 0; start + static_cast<size_t>(w.length) <= n; start += static_cast<size_t>(step)) {
            for (int k = 0; k < w.length; ++k)
                for (const std::vector<double>& ch : channels)
                    w.data.push_back(static_cast<float>(ch[start + static_cast<size_t>(k)]));
            w.labels.push_back(label);
            w.subjects.push_back(chosen[0]->dataset + ":" + chosen[0]->subject);
            w.groups.push_back(key);
        }
    }
    if (w.size() == 0 && longest > 0 && longest < static_cast<size_t>(w.length)) {
        char expected[64], got[32];
        std::snprintf(expected, sizeof expected, "at most the longest trial, %.3g s",
                      static_cast<double>(longest) / o.rate_hz);
        std::snprintf(got, sizeof got, "%g s", o.window_s);
        throw Error("windows", o.window_option, expected, got);
    }
    return w;
}

WindowSet relabel(const WindowSet& w, const std::map<std::string, std::string>& rename) {
    WindowSet out;
    out.length = w.length;
    out.channels = w.channels;
    const size_t per = static_cast<size_t>(w.length * w.channels);
    for (size_t i = 0; i < w.size(); ++i) {
        const auto it = rename.find(w.labels[i]);
        if (it == rename.end() || it->second.empty()) continue;
        out.data.insert(out.data.end(), w.data.begin() + static_cast<std::ptrdiff_t>(i * per),
                        w.data.begin() + static_cast<std::ptrdiff_t>((i + 1) * per));
        out.labels.push_back(it->second);
        out.subjects.push_back(w.subjects[i]);
        out.groups.push_back(w.groups[i]);
    }
    return out;
}

}  // namespace t2imu
