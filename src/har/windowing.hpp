// IMU recordings -> fixed-length, labelled windows for a classifier (the paper: 20 Hz, 2 s, each window overlapping the
// next by half).
//
// Positions: recordings of one trial at several positions are grouped by their path with the trailing
// `_<position>.csv` or `/<position>.csv` removed; a window holds the chosen positions' channels side by side
// (acc x,y,z [, gyr x,y,z] per position, in the order asked), cut to the shortest of the group. A position
// without a side ("shin") selects either side ("left_shin" or "right_shin", the first one present).
// Rate: integer rates are converted with the polyphase FIR of resample_poly.hpp (scipy's resample_poly);
// others (HuGaDB's 58.82 Hz) are low-passed by a Gaussian with its -3 dB point at 0.8 x the new Nyquist
// frequency and linearly interpolated. Each window's label is its recording's (labels are per recording in
// this layout, so the majority label is that one).
#pragma once
#include <map>
#include <string>
#include <vector>

#include "imu/imu_dataset.hpp"

namespace t2imu {

struct WindowOptions {
    double rate_hz = 20, window_s = 2, overlap = 0.5;
    bool gyro = false;                             // acc only, or acc and gyr
    std::vector<std::string> positions;            // empty: the data set must hold a single position
    std::string positions_option = "--positions";  // the option errors about `positions` name
    std::string window_option = "--window";        // likewise for window_s
    long min_window_samples = 1;                   // what the windows feed needs (catch22: 10)

    // Throws Error naming the option (--rate, --window, --overlap) for a value out of range or not finite.
    void validate() const;
};

struct WindowSet {
    int length = 0, channels = 0;       // samples per window, channels per sample
    std::vector<float> data;            // [windows, length, channels]
    std::vector<std::string> labels;    // evaluation class per window
    std::vector<std::string> subjects;  // per window
    std::vector<std::string> groups;    // per window: the trial it came from (for splits without leakage)
    size_t size() const { return labels.size(); }
};

// Windows of every trial that has all requested positions; labels through map_activity ("" = dropped). Refuses a
// requested position no recording has, and a window longer than every trial that has the positions.
WindowSet make_windows(const std::vector<ImuRecording>& recordings, const WindowOptions& options);

// One channel resampled from rate_in to rate_out (see above).
std::vector<double> resample_channel(const std::vector<double>& x, double rate_in, double rate_out);

// Keeps the windows whose label `rename` maps to a non-empty class, under that class's name.
WindowSet relabel(const WindowSet& w, const std::map<std::string, std::string>& rename);

}  // namespace t2imu
