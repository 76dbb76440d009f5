// catch22_table: the channel names make_windows produces, and the window table: label columns, one column per
// channel and feature, the window index within each trial, values equal to catch22 of that window's channel,
// "nan" for a constant channel, and a refused channel count.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

#include "analysis/catch22.hpp"
#include "analysis/catch22_table.hpp"
#include "core/error.hpp"

using namespace t2imu;

TEST(Catch22Table, ChannelNames) {
    WindowOptions o;
    EXPECT_EQ(window_channel_names(o), (std::vector<std::string>{"sensor_acc_x", "sensor_acc_y", "sensor_acc_z"}));
    o.gyro = true;
    o.positions = {"waist", "left_wrist"};
    const std::vector<std::string> names = window_channel_names(o);
    ASSERT_EQ(names.size(), 12u);
    EXPECT_EQ(names[0], "waist_acc_x");
    EXPECT_EQ(names[5], "waist_gyr_z");
    EXPECT_EQ(names[6], "left_wrist_acc_x");
    EXPECT_EQ(names[11], "left_wrist_gyr_z");
}

namespace {
// Three windows of 30 samples and 2 channels: trial A twice, then trial B. Channel 0 varies; channel 1 is
// constant in the second window.
WindowSet three_windows() {
    WindowSet w;
    w.length = 30;
    w.channels = 2;
    for (int i = 0; i < 3; ++i) {
        for (int k = 0; k < w.length; ++k) {
            w.data.push_back(static_cast<float>(std::sin(0.4 * k + i) + 0.05 * k));
            w.data.push_back(i == 1 ? 9.81f : static_cast<float>(std::cos(0.9 * k * (i + 1))));
        }
        w.labels.push_back(i < 2 ? "walking" : "running");
        w.subjects.push_back("s1");
        w.groups.push_back(i < 2 ? "A" : "B");
    }
    return w;
}
}  // namespace

TEST(Catch22Table, OneRowPerWindowWithCatch22OfEachChannel) {
    const WindowSet w = three_windows();
    const CsvTable t = catch22_window_table(w, {"waist_acc_x", "waist_acc_y"}, true);
    ASSERT_EQ(t.header.size(), 4u + 2 * 24);
    EXPECT_EQ(std::vector<std::string>(t.header.begin(), t.header.begin() + 4), kWindowLabelColumns);
    EXPECT_EQ(t.header[4], "waist_acc_x_mode_5");
    EXPECT_EQ(t.header[4 + 23], "waist_acc_x_std");
    EXPECT_EQ(t.header[4 + 24], "waist_acc_y_mode_5");
    ASSERT_EQ(t.rows.size(), 3u);
    // subject, trial, activity, window index within the trial (0, 1, then 0 again for trial B).
    EXPECT_EQ(t.rows[0][0], "s1");
    EXPECT_EQ(t.rows[1][1], "A");
    EXPECT_EQ(t.rows[2][2], "running");
    EXPECT_EQ(t.rows[0][3], "0");
    EXPECT_EQ(t.rows[1][3], "1");
    EXPECT_EQ(t.rows[2][3], "0");
    // Each value is catch24 of that window's channel, printed to 9 significant digits.
    for (size_t i = 0; i < 3; ++i) {
        std::vector<double> series;
        for (int k = 0; k < w.length; ++k) series.push_back(w.data[(i * 30 + k) * 2]);
        const std::vector<double> expected = catch22(series, true);
        for (size_t f = 0; f < 24; ++f) {
            const double got = std::strtod(t.rows[i][4 + f].c_str(), nullptr);
            EXPECT_NEAR(got, expected[f], 1e-8 * std::max(1.0, std::fabs(expected[f])))
                << "window " << i << " " << t.header[4 + f];
        }
    }
    // The constant channel of window 1 cannot be z-scored: every feature "nan"; window 0's channel 1 has values.
    for (size_t f = 0; f < 24; ++f) EXPECT_EQ(t.rows[1][4 + 24 + f], "nan");
    EXPECT_NE(t.rows[0][4 + 24], "nan");
}

TEST(Catch22Table, Catch22WithoutTheExtrasAndRefusedChannelCount) {
    const WindowSet w = three_windows();
    const CsvTable t = catch22_window_table(w, {"x", "y"}, false);
    EXPECT_EQ(t.header.size(), 4u + 2 * 22);
    EXPECT_EQ(t.header.back(), "y_dfa");
    try {
        catch22_window_table(w, {"only_one"}, false);
        ADD_FAILURE() << "1 name for 2 channels accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("channels"), std::string::npos) << e.what();
    }
}
