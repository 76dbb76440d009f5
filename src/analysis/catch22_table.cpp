#include "analysis/catch22_table.hpp"

#include <cmath>
#include <cstdio>

#include "analysis/catch22.hpp"
#include "core/error.hpp"
#include "core/number_text.hpp"
#include "core/parallel.hpp"
#include "core/progress.hpp"
#include "imu/imu_dataset.hpp"

namespace t2imu {

std::vector<std::string> window_channel_names(const WindowOptions& o) {
    std::vector<std::string> names;
    const std::vector<std::string> positions = o.positions.empty() ? std::vector<std::string>{"sensor"} : o.positions;
    for (const std::string& p : positions)
        for (size_t c = 1; c < imu_sample_columns().size(); ++c) {  // the six signals after t
            if (!o.gyro && imu_sample_columns()[c].rfind("gyr", 0) == 0) continue;
            names.push_back(p + "_" + imu_sample_columns()[c]);
        }
    return names;
}

CsvTable catch22_window_table(const WindowSet& w, const std::vector<std::string>& channel_names, bool catch24,
                              int threads) {
    if (static_cast<int>(channel_names.size()) != w.channels)
        throw Error("catch22 table", "channels", std::to_string(w.channels) + " names",
                    std::to_string(channel_names.size()));
    CsvTable t;
    t.header = kWindowLabelColumns;
    const size_t features = catch24 ? 24 : 22;
    for (const std::string& c : channel_names)
        for (size_t f = 0; f < features; ++f) t.header.push_back(c + "_" + catch24_short_names()[f]);
    t.rows.resize(w.size());
    Progress progress("catch22", w.size(), "windows");
    parallel_for(w.size(), threads, [&](size_t i) {
        std::vector<std::string> row = {w.subjects[i], w.groups[i], w.labels[i], ""};
        std::vector<double> series(static_cast<size_t>(w.length));
        for (int c = 0; c < w.channels; ++c) {
            for (int k = 0; k < w.length; ++k)
                series[static_cast<size_t>(k)] = w.data[(i * static_cast<size_t>(w.length) + static_cast<size_t>(k)) *
                                                            static_cast<size_t>(w.channels) +
                                                        static_cast<size_t>(c)];
            std::vector<double> values;
            try {
                values = catch22(series, catch24);
            } catch (const Error&) {
                values.assign(features, std::nan(""));  // a constant channel: nothing to z-score
            }
            for (double v : values) {
                row.push_back(general_text(v, 9));
            }
        }
        t.rows[i] = std::move(row);
        progress.advance();
    });
    // The window's index within its trial: consecutive windows of one group count up from 0.
    for (size_t i = 0, index = 0; i < w.size(); ++i) {
        index = i > 0 && w.groups[i] == w.groups[i - 1] ? index + 1 : 0;
        t.rows[i][3] = std::to_string(index);
    }
    return t;
}

}  // namespace t2imu
