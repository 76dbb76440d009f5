// catch22 for every window and channel of an IMU dataset: the table the t-SNE plots and the two-sample test
// read. Windows come from har/windowing.hpp (the HAR evaluation's rate, length and overlap).
#pragma once
#include <string>
#include <vector>

#include "core/csv.hpp"
#include "har/windowing.hpp"

namespace t2imu {

// The label columns a window table starts with; every other column is a feature.
inline const std::vector<std::string> kWindowLabelColumns = {"subject", "trial", "activity", "window"};

// Columns: subject, trial, activity, window (index within the trial), then <channel>_<short name> for every
// channel and feature. A channel that is constant within a window (catch22 cannot z-score it) gets "nan".
// channel_names: one per window channel, e.g. acc_x, acc_y, acc_z. Windows are computed on `threads` workers
// (core/parallel.hpp); the table is the same for any count.
CsvTable catch22_window_table(const WindowSet& windows, const std::vector<std::string>& channel_names, bool catch24,
                              int threads = 1);

// The channel names make_windows produces for these options: <position>_acc_x ... (<position>_gyr_z).
std::vector<std::string> window_channel_names(const WindowOptions& options);

}  // namespace t2imu
