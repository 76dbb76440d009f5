// Per-recording signal statistics that show at a glance whether synthetic IMU data moves like real data:
// how strongly (the spread of the acceleration magnitude) and at what rhythm (its dominant frequency, the step
// or stride rate of gait).
#pragma once
#include <string>
#include <vector>

#include "imu/imu_dataset.hpp"

namespace t2imu {

struct SignalStats {
    double acc_sd_m_s2 = 0;  // standard deviation over samples of |acc| (m/s^2; population sd, divides by n)
    double dominant_hz = 0;  // frequency of the largest periodogram bin of |acc| - mean(|acc|), DC excluded (Hz)
};

// Of a loaded recording (at least 2 samples) at its rate_hz (analysis/signal_statistics.hpp's standard_deviation
// and dominant_frequency_hz of |acc|, DC excluded).
SignalStats signal_stats(const ImuRecording& recording);

// The statistics of the recordings at one position, per canonical activity (motion/activity_names.hpp).
struct ActivityStats {
    std::string activity;
    std::vector<SignalStats> synthetic, real;  // real: empty without real data
};

// Statistics of the recordings (loaded) at `position`, per canonical activity of `synthetic`, alphabetical;
// real recordings of activities the synthetic data lacks are left out.
std::vector<ActivityStats> stats_by_activity(const std::vector<ImuRecording>& synthetic,
                                             const std::vector<ImuRecording>& real, const std::string& position);

// The median of one field over `stats` (the mean of the middle two for an even count; NaN when empty).
double median_of(const std::vector<SignalStats>& stats, double SignalStats::*field);

// The position to compare at: of the positions in `synthetic` (that `real` also has, unless it has none in
// common or is empty), the one with the most synthetic recordings; ties go to the alphabetically first.
// "" when `synthetic` is empty.
std::string comparison_position(const std::vector<ImuRecording>& synthetic, const std::vector<ImuRecording>& real);

}  // namespace t2imu
