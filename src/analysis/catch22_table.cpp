#include "analysis/catch22_table.hpp"

#include <cmath>
#include <cstdio>

#include "analysis/catch22.hpp"
#include "core/error.hpp"

namespace t2imu {

std::vector<std::string> window_channel_names(const WindowOptions& o) {
    std::vector<std::string> names;
    const std::vector<std::string> positions = o.positions.empty() ? std::vector<std::string>{"sensor"} : o.positions;
    for (const std::string& p : positions)
        for (const char* c : {"acc_x", "acc_y", "acc_z", "gyr_x", "gyr_y", "gyr_z"}) {
            if (!o.gyro && c[0] == 'g') continue;
            names.push_back(p + "_" + c);
        }
    return names;
}

CsvTable catch22_window_table(const WindowSet& w, const std::vector<std::string>& channel_names, bool catch24) {
    if (static_cast<int>(channel_names.size()) != w.channels)
        throw Error("catch22 table", "channels", std::to_string(w.channels) + " names", std::to_string(channel_names.size()));
    CsvTable t;
    t.header = kWindowLabelColumns;
    const size_t features = catch24 ? 24 : 22;
    for (const std::string& c : channel_names)
        for (size_t f = 0; f < features; ++f) t.header.push_back(c + "_" + catch24_short_names()[f]);
    std::string previous_group;
    int index = 0;
    char buf[32];
    std::vector<double> series(static_cast<size_t>(w.length));
    for (size_t i = 0; i < w.size(); ++i) {
        index = w.groups[i] == previous_group ? index + 1 : 0;
        previous_group = w.groups[i];
        std::vector<std::string> row = {w.subjects[i], w.groups[i], w.labels[i], std::to_string(index)};
        for (int c = 0; c < w.channels; ++c) {
            for (int k = 0; k < w.length; ++k) series[static_cast<size_t>(k)] = w.data[(i * static_cast<size_t>(w.length) + static_cast<size_t>(k)) * static_cast<size_t>(w.channels) + static_cast<size_t>(c)];
            std::vector<double> values;
            try {
                values = catch22(series, catch24);
            } catch (const Error&) {
                values.assign(features, std::nan(""));  // a constant channel: nothing to z-score
            }
            for (double v : values) {
                std::snprintf(buf, sizeof buf, "%.9g", v);
                row.push_back(buf);
            }
        }
        t.rows.push_back(std::move(row));
    }
    return t;
}

}  // namespace t2imu
